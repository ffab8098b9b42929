// Saving a scene after edits: the text it was loaded from, with each object's `position` and
// `rotate_y` set to where the object stands now. The caller writes it (atomically).
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// `text` must be the walkrad-scene/1 text `scene` was parsed from. Everything but the poses is
// kept as it was, in order (formatting is the writer's: two-space indents); a pose is written only
// where it differs from the file's (or the spec's default where the file gives none).
std::string sceneTextWithPoses(std::string_view text, const Scene& scene);

}  // namespace engine

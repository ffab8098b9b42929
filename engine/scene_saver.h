// Saving a scene after edits: the text it was loaded from, with each object's `position` and
// `rotate_y` set to where the object stands now. The caller writes it (atomically).
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// `text` must be the walkrad-scene/1 text `scene` was parsed from. Everything but the poses is
// kept as it was, in order (formatting is the writer's: two-space indents). A pose equal to the
// spec's default is written only where the file already gave one.
std::string sceneTextWithPoses(std::string_view text, const Scene& scene);

}  // namespace engine

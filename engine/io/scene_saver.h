// Saving a scene after edits: the text it was loaded from, with each object's `position` and
// `rotate_y` set to where the object stands now. The caller writes it (atomically).
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// `text` must be the walkrad-scene/1 text `scene` was parsed from. Everything but the poses is
// kept byte for byte, its layout the author's (a scene under version control shows a move as the
// lines it changed); a pose is written only where it differs from the file's (or the spec's
// default where the file gives none): its value replaced in place, or added as the object's last
// member, laid out as the members before it.
std::string sceneTextWithPoses(std::string_view text, const Scene& scene);

}  // namespace engine

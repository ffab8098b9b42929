// Reading walkrad-scene/1 files (spec/scene-format.md) into a fully validated Scene.
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// Reads, validates and builds the surfaces of a scene file. Throws SceneError (file, JSON path,
// problem) for anything that breaks the spec; nothing is returned half-loaded.
Scene loadScene(const std::string& path);

// The same for scene text already in memory; `file` names it in messages.
Scene parseScene(std::string_view text, const std::string& file);

// The whole text of a file; throws SceneError (FileUnreadable) naming it when it cannot be read.
std::string readInputFile(const std::string& path);

// Metres per unit for a `units` value, or 0 when unknown.
double metersPerUnit(std::string_view units);

}  // namespace engine

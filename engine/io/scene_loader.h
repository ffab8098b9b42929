// Reading walkrad-scene/1 text (spec/scene-format.md) into a fully validated Scene. Files of any
// kind, scene files and glTF models, are loaded by load_scene.h.
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// Reads, validates and builds the surfaces of scene text; `file` names it in messages. Throws
// SceneError (file, JSON path, problem) for anything that breaks the spec; nothing is returned
// half-loaded.
Scene parseScene(std::string_view text, const std::string& file);

// The two halves of parseScene, for tools that look at a model as it was described (walkrad
// check). parseSceneFaces reads and validates like parseScene but leaves Scene::surfaces as the
// faces themselves, one surface per face and per filled hole, in file order. preprocessSurfaces
// then makes them the surfaces that are meshed: coplanar merging (thesis 3.2) and contact
// cut-outs. parseScene is the one followed by the other.
Scene parseSceneFaces(std::string_view text, const std::string& file);
void preprocessSurfaces(Scene& scene);

}  // namespace engine

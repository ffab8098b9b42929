#include "app/window/scene_edits.h"

#include "app/image/atomic_file.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/scene_loader.h"
#include "engine/io/scene_saver.h"

#include <exception>

namespace app {

namespace {

engine::SceneEditor meshedEditor(engine::Scene scene) {
  engine::MeshedScene meshed = engine::meshScene(scene);
  return engine::SceneEditor(std::move(scene), std::move(meshed));
}

}  // namespace

SceneEdits::SceneEdits(std::string path, std::string text, engine::Scene scene)
    : path_(std::move(path)), text_(std::move(text)), editor_(meshedEditor(std::move(scene))) {}

// Undo and redo put an object back at a pose the scene stood in, every other object where it
// stood then: the editor places surfaces from their loaded pose, so the polygons to mesh are bit
// for bit those it meshed then (SceneEditor tests), and the mesher cannot refuse them.
std::optional<uint32_t> SceneEdits::undo() {
  if (const auto dragged = drag_.release()) history_.record(*dragged);  // a drag in progress first
  const auto edit = history_.undo();
  if (!edit) return std::nullopt;
  editor_.setPose(edit->object, edit->before);
  return edit->object;
}

std::optional<uint32_t> SceneEdits::redo() {
  if (const auto dragged = drag_.release()) history_.record(*dragged);
  const auto edit = history_.redo();
  if (!edit) return std::nullopt;
  editor_.setPose(edit->object, edit->after);
  return edit->object;
}

std::string SceneEdits::save() {
  // Rewriting a modeller's file would lose what walkrad does not read (textures, normals,
  // animation), so poses are written only into scene files.
  if (engine::isGltfPath(path_)) return "not saved: " + path_ + " is a glTF model; walkrad saves poses only into scene files (.json)";
  try {
    const std::string text = engine::sceneTextWithPoses(text_, editor_.scene());
    // A file that would not load again is not written; the loader's error says why (an object
    // moved so far off that the scene's patch size is too small for its extent).
    engine::parseScene(text, path_);
    writeFileAtomically(path_, text);
    text_ = text;
    history_.markSaved();
    return "saved " + path_;
  } catch (const std::exception& e) {
    return std::string("not saved: ") + e.what();
  }
}

}  // namespace app

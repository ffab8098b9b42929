// Selecting and dragging objects with rays, as the window's mouse does.
#include "engine/document/lighting.h"
#include "engine/io/input_file.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"
#include "engine/session/object_drag.h"
#include "engine/session/scene_edits.h"
#include "engine/session/view_camera.h"
#include "tests/engine/file_size_limit.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

namespace engine {
namespace {

// A room (fixed) with a 1 m box (movable) standing on its floor at x, z in 1..2.
constexpr const char* kScene = R"({
  "format": "walkrad-scene/1", "settings": { "patch_size": 0.5 },
  "materials": { "white": { "reflectance": [0.5, 0.5, 0.5] }, "lamp": { "reflectance": [0.5, 0.5, 0.5], "emission": [4, 4, 4] } },
  "objects": [
    { "name": "room", "movable": false,
      "solids": [ { "profile": [[0, 0], [4, 0], [4, 3], [0, 3]], "from": 0, "to": 2.5, "inward": true, "material": "white",
                    "faces": { "top": { "holes": [ { "polygon": [[1, 1], [2, 1], [2, 2], [1, 2]], "fill": "lamp" } ] } } } ] },
    { "name": "box", "solids": [ { "profile": [[1, 1], [2, 1], [2, 2], [1, 2]], "from": 0, "to": 1, "material": "white" } ] }
  ] })";

engine::SceneView viewOf(const engine::Scene& scene) { return engine::SceneView(scene, engine::meshScene(scene)); }

SceneEdits editsOf(const std::string& path = "unused.json") {
  return SceneEdits(path, kScene, viewOf(engine::parseScene(kScene, path)));
}

// A ray from above the room's floor, looking down at (x, z).
Ray down(double x, double z) { return {{x, 2, z}, {0, -1, 0}}; }

TEST(ObjectDrag, ADragSlidesTheBoxOnTheFloorAndRecordsOneEdit) {
  SceneEdits edits = editsOf();
  ObjectDrag& drag = edits.drag();
  ASSERT_TRUE(drag.press(down(1.5, 1.5)));  // the box's top
  EXPECT_EQ(edits.view().scene().objects[*drag.selected()].name, "box");
  // Grabbed on its top (y = 1), the box follows the ray's crossing with the plane y = 1.
  EXPECT_TRUE(drag.follow({{2.5, 2, 1.5}, glm::normalize(glm::dvec3{0.5, -1, 0.25})}));
  const engine::Object& box = edits.view().scene().objects[*drag.selected()];
  EXPECT_NEAR(box.position.x, 1.5, 1e-12);
  EXPECT_NEAR(box.position.z, 0.25, 1e-12);
  EXPECT_EQ(box.position.y, 0);  // still on the floor
  EXPECT_TRUE(drag.lift(0.5));
  EXPECT_EQ(box.position.y, 0.5);
  // A ray above the horizon leaves the box where it was.
  EXPECT_FALSE(drag.follow({{2, 2, 2}, {0, 1, 0}}));
  const auto edit = drag.release();
  ASSERT_TRUE(edit);
  EXPECT_EQ(edit->before.position, glm::dvec3{0});
  EXPECT_EQ(edit->after.position, box.position);
  EXPECT_FALSE(drag.dragging());
}

// Dragged toward the horizon or lifted by a wild wheel, the box stops at the scene limits (a
// scene file holds no position beyond 1e6) and comes back with the first step the other way.
TEST(ObjectDrag, ADragStopsAtTheSceneLimits) {
  SceneEdits edits = editsOf();
  ObjectDrag& drag = edits.drag();
  ASSERT_TRUE(drag.press(down(1.5, 1.5)));
  const engine::Object& box = edits.view().scene().objects[*drag.selected()];
  EXPECT_TRUE(drag.follow({{2.5, 2, 1.5}, glm::normalize(glm::dvec3{1, -1e-9, 0})}));  // crosses y = 1 at x = 1e9
  EXPECT_EQ(box.position.x, engine::kMaxLength);
  EXPECT_FALSE(drag.follow({{2.5, 2, 1.5}, {1, -1e-320, 0}}));  // crosses at infinity: stays
  EXPECT_EQ(box.position.x, engine::kMaxLength);
  EXPECT_TRUE(drag.lift(1e300));
  EXPECT_EQ(box.position.y, engine::kMaxLength);
  EXPECT_TRUE(drag.lift(-0.5));
  EXPECT_EQ(box.position.y, engine::kMaxLength - 0.5);
  const auto edit = drag.release();
  ASSERT_TRUE(edit);
  EXPECT_TRUE(engine::inSceneLimits(edit->after));
}

// Dragged so that its footprint would leave a strip of floor 3 um wide 900 km from the origin
// (finer than the mesher resolves there: engine's SceneEditor test), the box is shown there at
// once, but the document on the lighting thread refuses the pose: the box goes back to its last
// good pose and the drag says why until a later pose is taken; the drag is one edit.
TEST(ObjectDrag, ADragThatWouldLeaveASliverTooFineGoesBackToTheLastGoodPose) {
  const std::string path = std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json";
  const engine::Scene loaded = engine::loadScene(path);
  const engine::MeshedScene meshed = engine::meshScene(loaded);
  SceneEdits edits(path, "", engine::SceneView(loaded, meshed));
  engine::LightingSettings settings;
  settings.converge = 1;  // nothing to shoot: only the edits
  engine::LightingThread lighting(loaded, meshed, settings);
  uint64_t sent = 0;
  // As the window's frame does: the poses to the document, then what it sends back, once it has
  // taken them.
  const auto exchange = [&] {
    for (const auto& [object, pose] : edits.takePosesToSend()) {
      lighting.requestPose(object, pose);
      ++sent;
    }
    while (lighting.latest()->edits < sent) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    edits.take(lighting.take());
  };
  ObjectDrag& drag = edits.drag();
  const auto below = [](double x, double z) { return Ray{{x, 0.9, z}, {0, -1, 0}}; };  // under the ceiling
  ASSERT_TRUE(drag.press(below(900000.5, 900000.5)));  // the box's top, its origin 0.1 away
  const engine::Object& box = edits.view().scene().objects[*drag.selected()];
  ASSERT_TRUE(drag.follow(below(900000.6, 900000.5)));
  exchange();
  const engine::ObjectPose good = engine::poseOf(box);
  EXPECT_EQ(drag.refusal(), "");
  EXPECT_TRUE(drag.follow(below(900000.100003, 900000.5)));  // its side 3 um from the wall x = 900000
  EXPECT_NE(engine::poseOf(box), good);  // shown there until the document says no
  exchange();
  EXPECT_EQ(engine::poseOf(box), good);
  EXPECT_NE(drag.refusal().find("detail finer than the coordinates resolve"), std::string::npos) << drag.refusal();
  EXPECT_TRUE(drag.follow(below(900000.3, 900000.5)));
  EXPECT_NE(drag.refusal(), "");  // until the document has taken the new pose
  exchange();
  EXPECT_EQ(drag.refusal(), "");
  const auto edit = drag.release();
  ASSERT_TRUE(edit);
  EXPECT_EQ(edit->after, engine::poseOf(box));
}

// A turn recorded before the document refuses it is amended to the pose the object stayed at;
// a refused turn that leaves the object where it was is no edit at all.
TEST(SceneEdits, ARefusedTurnLeavesNoEdit) {
  SceneEdits edits = editsOf();
  ObjectDrag& drag = edits.drag();
  drag.press(down(1.5, 1.5));
  drag.release();
  const auto turned = drag.turn(15);
  ASSERT_TRUE(turned);
  edits.record(*turned);
  ASSERT_TRUE(edits.history().canUndo());
  const uint32_t box = *drag.selected();
  EXPECT_EQ(edits.takePosesToSend().size(), 1u);
  engine::LightingUpdate update;
  update.refusals.push_back({box, turned->after, turned->before, "refused"});
  edits.take(update);
  EXPECT_EQ(edits.view().scene().objects[box].rotateYDeg, 0);
  EXPECT_EQ(drag.refusal(), "refused");
  EXPECT_FALSE(edits.history().canUndo());
  EXPECT_FALSE(edits.history().unsaved());
}

TEST(ObjectDrag, FixedObjectsAreSelectedButNotDragged) {
  SceneEdits edits = editsOf();
  ObjectDrag& drag = edits.drag();
  EXPECT_FALSE(drag.press(down(3, 2.5)));  // the floor
  ASSERT_TRUE(drag.selected());
  EXPECT_EQ(edits.view().scene().objects[*drag.selected()].name, "room");
  EXPECT_FALSE(drag.follow(down(3.5, 2.5)));
  EXPECT_FALSE(drag.turn(15));
  EXPECT_FALSE(drag.release());
  EXPECT_FALSE(drag.press({{2, 1, 1.5}, {0, 0, 1}}) && drag.selected());  // misses everything: no selection
}

TEST(ObjectDrag, TurnsUndoAndRedo) {
  SceneEdits edits = editsOf();
  ObjectDrag& drag = edits.drag();
  drag.press(down(1.5, 1.5));
  EXPECT_FALSE(drag.release());  // a click without a move is no edit
  const auto turned = drag.turn(15);
  ASSERT_TRUE(turned);
  edits.record(*turned);
  const uint32_t box = *drag.selected();
  EXPECT_EQ(edits.view().scene().objects[box].rotateYDeg, 15);
  EXPECT_EQ(edits.undo(), box);
  EXPECT_EQ(edits.view().scene().objects[box].rotateYDeg, 0);
  EXPECT_EQ(edits.redo(), box);
  EXPECT_EQ(edits.view().scene().objects[box].rotateYDeg, 15);
  EXPECT_FALSE(edits.redo());
  // The document is asked for each pose in turn.
  const auto sent = edits.takePosesToSend();
  ASSERT_EQ(sent.size(), 3u);
  EXPECT_EQ(sent[0].second.rotateYDeg, 15);
  EXPECT_EQ(sent[1].second.rotateYDeg, 0);
  EXPECT_EQ(sent[2].second.rotateYDeg, 15);
  EXPECT_TRUE(edits.takePosesToSend().empty());
}

// kScene written as scene.json in a fresh folder `name` of the test output; its path.
std::string sceneFileIn(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(WALKRAD_TEST_OUTPUT) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "scene.json").string();
  std::ofstream(path) << kScene;
  return path;
}

TEST(SceneEdits, SavingWritesThePosesAndAFailedSaveLosesNothing) {
  const std::string path = sceneFileIn("scene_edits_save");
  SceneEdits edits = editsOf(path);
  ObjectDrag& drag = edits.drag();
  drag.press(down(1.5, 1.5));
  drag.lift(0.25);
  edits.record(*drag.release());
  EXPECT_TRUE(edits.history().unsaved());
  EXPECT_EQ(edits.save(), "saved " + path);
  EXPECT_FALSE(edits.history().unsaved());
  EXPECT_EQ(engine::loadScene(path).objects[1].position.y, 0.25);

  // The file cannot be written in full (as on a full disk): the save fails with a report and the
  // scene's file stays as it was.
  edits.undo();
  std::string report;
  {
    const test::FileSizeLimit full(100);
    report = edits.save();
  }
  EXPECT_EQ(report.rfind("not saved: " + path + ": cannot write: File too large", 0), 0u) << report;
  EXPECT_TRUE(edits.history().unsaved());
  EXPECT_EQ(engine::loadScene(path).objects[1].position.y, 0.25);
}

// The box 1e6 m off a 4 m room whose patch size is 0.5 m makes a scene the loader refuses (over
// 100,000 patches along its extent): that is not saved, and the file stays as it was.
TEST(SceneEdits, ASceneThatWouldNotLoadAgainIsNotSaved) {
  const std::string path = sceneFileIn("scene_edits_unloadable");
  SceneEdits edits = editsOf(path);
  ObjectDrag& drag = edits.drag();
  drag.press(down(1.5, 1.5));
  drag.follow({{2.5, 2, 1.5}, glm::normalize(glm::dvec3{1, -1e-9, 0})});
  edits.record(*drag.release());
  const std::string report = edits.save();
  EXPECT_EQ(report.rfind("not saved: " + path + ": settings.patch_size: patch size too small", 0), 0u) << report;
  EXPECT_EQ(engine::readInputFile(path), kScene);
}

// A glTF model's objects move, but the model is not rewritten: the save says so and the file
// stays byte for byte.
TEST(ObjectDrag, SavingAGltfModelIsRefusedWithAReason) {
  const std::string path = std::string(WALKRAD_SOURCE) + "/tests/cli/no_light.gltf";
  const std::string before = engine::readInputFile(path);
  SceneEdits edits(path, "", viewOf(engine::loadScene(path)));
  ASSERT_TRUE(edits.view().setPose(0, {engine::Vec3(0.5, 0, 0), 0}));
  edits.record({0, {engine::Vec3(0), 0}, {engine::Vec3(0.5, 0, 0), 0}});
  const std::string report = edits.save();
  EXPECT_EQ(report, "not saved: " + path + " is a glTF model; walkrad saves poses only into scene files (.json)");
  EXPECT_TRUE(edits.history().unsaved());
  EXPECT_EQ(engine::readInputFile(path), before);
}

}  // namespace
}  // namespace engine

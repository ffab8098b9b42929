// Moving objects: the surfaces and meshes go with them, rigidly, and come back exactly.
#include "engine/document/edit_history.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace engine {
namespace {

SceneEditor editorOf(const Json& json) {
  Scene scene = test::parse(json);
  MeshedScene meshed = meshScene(scene);
  return SceneEditor(std::move(scene), std::move(meshed));
}

// The box moves with its meshes; the floor it stands on is meshed again around its new
// footprint; nothing else changes.
TEST(SceneEditor, TranslationMovesTheObjectAndItsFootprint) {
  SceneEditor editor = editorOf(test::baseScene());
  const Scene before = editor.scene();
  const MeshedScene meshedBefore = editor.meshed();
  const uint32_t box = *editor.findObject("box");
  const Vec3 offset{0.5, 0, 0.75};
  EXPECT_TRUE(editor.setPose(box, {offset, 0}));
  EXPECT_EQ(editor.scene().objects[box].position, offset);
  const Surface& floor = test::surfaceOf(editor.scene(), "room", "bottom");
  const auto floorIndex = static_cast<uint32_t>(&floor - editor.scene().surfaces.data());
  EXPECT_EQ(editor.remeshed(), std::vector<uint32_t>{floorIndex});
  ASSERT_EQ(floor.holes.size(), 1u);
  EXPECT_EQ(floor.holes[0], test::surfaceOf(editor.scene(), "box", "bottom").outer);
  EXPECT_NE(editor.meshed().surfaces[floorIndex].mesh.elements, meshedBefore.surfaces[floorIndex].mesh.elements);
  for (uint32_t s = 0; s < before.surfaces.size(); ++s) {
    if (s == floorIndex) continue;
    const bool moved = before.surfaces[s].object == box;
    for (size_t i = 0; i < before.surfaces[s].outer.size(); ++i)
      EXPECT_EQ(editor.scene().surfaces[s].outer[i], before.surfaces[s].outer[i] + (moved ? offset : Vec3{0}));
    EXPECT_EQ(editor.scene().surfaces[s].normal, before.surfaces[s].normal);
    const auto& positions = editor.meshed().surfaces[s].positions;
    for (size_t i = 0; i < positions.size(); ++i)
      EXPECT_NEAR(glm::length(positions[i] - meshedBefore.surfaces[s].positions[i] - (moved ? offset : Vec3{0})), 0, 1e-12);
    EXPECT_EQ(editor.meshed().surfaces[s].mesh.elements, meshedBefore.surfaces[s].mesh.elements);
  }
}

// Lifted off the floor, or pushed against the wall, the box leaves no footprint; set down again
// in the open, it does.
TEST(SceneEditor, FootprintsComeAndGoWithContact) {
  SceneEditor editor = editorOf(test::baseScene());
  const uint32_t box = *editor.findObject("box");
  auto floorHoles = [&] { return test::surfaceOf(editor.scene(), "room", "bottom").holes.size(); };
  ASSERT_EQ(floorHoles(), 1u);
  editor.setPose(box, {Vec3{0, 0.25, 0}, 0});
  EXPECT_EQ(floorHoles(), 0u);
  editor.setPose(box, {Vec3{-1, 0, 0}, 0});  // its side on the wall x = 0
  EXPECT_EQ(floorHoles(), 0u);
  editor.setPose(box, {Vec3{1, 0, 0.5}, 0});
  EXPECT_EQ(floorHoles(), 1u);
}

// A quarter turn about +y takes +x to -z (the spec's rule) about the object's origin.
TEST(SceneEditor, RotationTurnsAboutTheVerticalThroughTheObjectsOrigin) {
  SceneEditor editor = editorOf(test::baseScene());
  const uint32_t box = *editor.findObject("box");
  const Surface east = test::surfaceOf(editor.scene(), "box", "side 1");  // the face at x = 2
  ASSERT_NEAR(east.normal.x, 1, 1e-12);
  editor.setPose(box, {Vec3{0}, 90});
  const Surface& turned = test::surfaceOf(editor.scene(), "box", "side 1");
  EXPECT_NEAR(glm::length(turned.normal - Vec3{0, 0, -1}), 0, 1e-12);
  for (size_t i = 0; i < east.outer.size(); ++i) {
    const Vec3 p = east.outer[i];
    EXPECT_NEAR(glm::length(turned.outer[i] - Vec3{p.z, p.y, -p.x}), 0, 1e-12);
  }
  EXPECT_NEAR(glm::length(turned.outer[0] - turned.outer[1]), glm::length(east.outer[0] - east.outer[1]), 1e-12);
}

TEST(SceneEditor, ManyMovesAndBackRestoreTheLoadedGeometryExactly) {
  SceneEditor editor = editorOf(test::baseScene());
  const Scene loaded = editor.scene();
  const MeshedScene meshedLoaded = editor.meshed();
  const uint32_t box = *editor.findObject("box");
  std::mt19937 random(3);
  std::uniform_real_distribution<double> offset(-1, 1), angle(-180, 180);
  for (int i = 0; i < 50; ++i) editor.setPose(box, {Vec3{offset(random), 0, offset(random)}, angle(random)});
  editor.setPose(box, {Vec3{0}, 0});
  for (size_t s = 0; s < loaded.surfaces.size(); ++s) {
    EXPECT_EQ(editor.scene().surfaces[s].outer, loaded.surfaces[s].outer);
    EXPECT_EQ(editor.scene().surfaces[s].holes, loaded.surfaces[s].holes);
    EXPECT_EQ(editor.scene().surfaces[s].normal, loaded.surfaces[s].normal);
    EXPECT_EQ(editor.meshed().surfaces[s].positions, meshedLoaded.surfaces[s].positions);
    EXPECT_EQ(editor.meshed().surfaces[s].mesh.elements, meshedLoaded.surfaces[s].mesh.elements);
  }
  EXPECT_EQ(editor.scene().boundsMin, loaded.boundsMin);
  EXPECT_EQ(editor.scene().boundsMax, loaded.boundsMax);
}

TEST(SceneEditor, FixedObjectsAndUnknownOnesRefuseToMove) {
  SceneEditor editor = editorOf(test::baseScene());
  const uint32_t room = *editor.findObject("room");
  EXPECT_THROW(editor.setPose(room, {Vec3{1, 0, 0}, 0}), std::invalid_argument);
  EXPECT_THROW(editor.setPose(7, {Vec3{1, 0, 0}, 0}), std::invalid_argument);
  EXPECT_FALSE(editor.findObject("nothing"));
  EXPECT_FALSE(editor.setPose(*editor.findObject("box"), {Vec3{0}, 0}));  // where it stands
}

// A scene file holds positions and turns within 1e6 (the loader refuses others), so no edit goes
// beyond: a scene saved after moves loads again.
TEST(SceneEditor, PosesBeyondTheSceneLimitsAreRefused) {
  SceneEditor editor = editorOf(test::baseScene());
  const uint32_t box = *editor.findObject("box");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const ObjectPose& pose : {ObjectPose{Vec3{1e7, 0, 0}, 0}, ObjectPose{Vec3{0, -1e308, 0}, 0},
                                 ObjectPose{Vec3{0, 0, nan}, 0}, ObjectPose{Vec3{0}, 2e6}, ObjectPose{Vec3{0}, nan}}) {
    EXPECT_FALSE(inSceneLimits(pose));
    EXPECT_THROW(editor.setPose(box, pose), std::invalid_argument);
    EXPECT_EQ(editor.scene().objects[box].position, Vec3{0});
  }
  EXPECT_TRUE(editor.setPose(box, {Vec3{kMaxLength, -kMaxLength, 0}, -kMaxLength}));
  EXPECT_EQ(clampToSceneLimits(Vec3{2e6, -1e308, 5}), (Vec3{kMaxLength, -kMaxLength, 5}));
}

TEST(SceneEditor, BoundsFollowAnObjectLeavingTheRoom) {
  SceneEditor editor = editorOf(test::baseScene());
  editor.setPose(*editor.findObject("box"), {Vec3{10, 0, 0}, 0});
  EXPECT_EQ(editor.scene().boundsMax.x, 12);
}

// The meshes of two editors' scenes are alike, element for element and point for point.
void expectSameMeshes(const MeshedScene& a, const MeshedScene& b) {
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (size_t s = 0; s < a.surfaces.size(); ++s) {
    EXPECT_EQ(a.surfaces[s].mesh.elements, b.surfaces[s].mesh.elements) << "surface " << s;
    EXPECT_EQ(a.surfaces[s].positions, b.surfaces[s].positions) << "surface " << s;
  }
}

// A room 1 m wide 900 km from the origin: a box slid to 3 um from its wall leaves a strip of
// floor wider than the contact tolerance (1e-6 of the scene's extent), so it is cut out, but
// narrower than the mesher resolves at coordinates of 9e5 (about 4096 roundings, 7.6 um). The
// move is refused at the floor, and nothing of it is applied; the box moves on from where it was.
TEST(SceneEditor, AMoveWhoseFootprintLeavesASliverTooFineIsRefusedWhole) {
  Scene loaded = loadScene(std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json");
  MeshedScene meshed = meshScene(loaded);
  SceneEditor editor(std::move(loaded), std::move(meshed));
  const uint32_t box = *editor.findObject("box");
  ASSERT_TRUE(editor.setPose(box, {Vec3{900000.5, 0, 900000.4}, 0}));  // remeshes the floor
  const Scene before = editor.scene();
  const MeshedScene meshedBefore = editor.meshed();
  const std::vector<uint32_t> remeshedBefore = editor.remeshed();
  const Surface& floor = test::surfaceOf(before, "room", "bottom");
  try {
    editor.setPose(box, {Vec3{900000 + 3e-6, 0, 900000.4}, 0});
    FAIL() << "the move was not refused";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::MeshTooFine);
    EXPECT_EQ(e.place(), floor.jsonPath);
  }
  EXPECT_EQ(poseOf(editor.scene().objects[box]), poseOf(before.objects[box]));
  EXPECT_EQ(editor.scene().boundsMin, before.boundsMin);
  EXPECT_EQ(editor.scene().boundsMax, before.boundsMax);
  EXPECT_EQ(editor.remeshed(), remeshedBefore);
  for (size_t s = 0; s < before.surfaces.size(); ++s) {
    EXPECT_EQ(editor.scene().surfaces[s].outer, before.surfaces[s].outer) << "surface " << s;
    EXPECT_EQ(editor.scene().surfaces[s].holes, before.surfaces[s].holes) << "surface " << s;
  }
  expectSameMeshes(editor.meshed(), meshedBefore);

  // Moving on from the last good pose works as from any other, and coming home restores the
  // loaded meshes.
  EXPECT_TRUE(editor.setPose(box, {Vec3{900000.3, 0, 900000.6}, 0}));
  EXPECT_EQ(test::surfaceOf(editor.scene(), "room", "bottom").holes.size(), 1u);
  Scene home = loadScene(std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json");
  const MeshedScene homeMeshed = meshScene(home);
  EXPECT_TRUE(editor.setPose(box, poseOf(home.objects[box])));
  expectSameMeshes(editor.meshed(), homeMeshed);
}

TEST(EditHistory, UndoRedoAndTheSavedState) {
  EditHistory history;
  EXPECT_FALSE(history.undo());
  EXPECT_FALSE(history.unsaved());
  const PoseEdit a{1, {Vec3{0}, 0}, {Vec3{1, 0, 0}, 0}}, b{1, a.after, {Vec3{2, 0, 0}, 30}};
  history.record(a);
  history.record(b);
  history.record({1, b.after, b.after});  // no change: not recorded
  EXPECT_TRUE(history.unsaved());
  EXPECT_EQ(history.undo()->after, b.after);
  history.markSaved();
  EXPECT_FALSE(history.unsaved());
  EXPECT_EQ(history.redo()->after, b.after);
  EXPECT_TRUE(history.unsaved());
  EXPECT_FALSE(history.redo());
  EXPECT_EQ(history.undo()->before, a.after);
  EXPECT_FALSE(history.unsaved());  // back where it was saved
  EXPECT_EQ(history.undo()->before, a.before);
  EXPECT_FALSE(history.undo());
  // A new edit after undoing drops the redo list and, with it, the saved state.
  history.record({2, {Vec3{0}, 0}, {Vec3{0, 1, 0}, 0}});
  EXPECT_FALSE(history.canRedo());
  EXPECT_TRUE(history.unsaved());
  history.undo();
  EXPECT_TRUE(history.unsaved());
}

}  // namespace
}  // namespace engine

// Moving objects: the surfaces and meshes go with them, rigidly, and come back exactly.
#include "engine/document/edit_history.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "mesher/mesh_check.h"
#include "tests/engine/test_scenes.h"
#include "tests/mesher/mesh_expectations.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
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
  ASSERT_TRUE(editor.setPose(box, {Vec3{900000.5, 0, 900000.4}, 0}));  // moves the floor's footprint
  const Scene before = editor.scene();
  const MeshedScene meshedBefore = editor.meshed();
  const std::vector<uint32_t> remeshedBefore = editor.remeshed();
  const Surface& floor = test::surfaceOf(before, "room", "bottom");
  const auto floorIndex = static_cast<uint32_t>(&floor - before.surfaces.data());
  ASSERT_EQ(editor.holeEdits().size(), 1u);
  const mesher::AdaptiveMesh* adaptive = editor.adaptiveMeshes().find(floorIndex);
  ASSERT_TRUE(adaptive);
  const std::vector<mesher::ElementId> adaptiveBefore = adaptive->elements();
  const std::vector<int> footprintsBefore = editor.adaptiveMeshes().footprints(floorIndex);
  const size_t adaptiveMeshesBefore = editor.adaptiveMeshes().size();
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
  // The floor's adaptive mesh, its footprint's hole id, and the adaptive meshes made: as they were.
  EXPECT_EQ(editor.adaptiveMeshes().find(floorIndex), adaptive);
  EXPECT_EQ(adaptive->elements(), adaptiveBefore);
  EXPECT_EQ(editor.adaptiveMeshes().footprints(floorIndex), footprintsBefore);
  EXPECT_EQ(editor.adaptiveMeshes().size(), adaptiveMeshesBefore);

  // Moving on from the last good pose works as from any other, and coming home restores the
  // loaded meshes.
  EXPECT_TRUE(editor.setPose(box, {Vec3{900000.3, 0, 900000.6}, 0}));
  EXPECT_EQ(test::surfaceOf(editor.scene(), "room", "bottom").holes.size(), 1u);
  Scene home = loadScene(std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json");
  const MeshedScene homeMeshed = meshScene(home);
  EXPECT_TRUE(editor.setPose(box, poseOf(home.objects[box])));
  expectSameMeshes(editor.meshed(), homeMeshed);
}

// A surface's elements by key, each as its corners' world positions.
std::map<uint64_t, std::vector<Vec3>> elementsByKey(const SurfaceMesh& mesh) {
  std::map<uint64_t, std::vector<Vec3>> out;
  for (size_t e = 0; e < mesh.keys.size(); ++e) {
    std::vector<Vec3>& corners = out[mesh.keys[e]];
    for (uint32_t v : mesh.mesh.elements[e])
      if (v != mesher::Mesh::kNone) corners.push_back(mesh.positions[v]);
  }
  return out;
}

// Distance along the floor (x, z) from p to the nearest of the rings' bounding boxes.
double distanceToFootprints(const Vec3& p, const std::vector<Ring3>& rings) {
  double nearest = 1e300;
  for (const Ring3& ring : rings) {
    Vec3 lo = ring.front(), hi = lo;
    for (const Vec3& q : ring) lo = glm::min(lo, q), hi = glm::max(hi, q);
    nearest = std::min(nearest, std::hypot(std::max({lo.x - p.x, 0.0, p.x - hi.x}), std::max({lo.z - p.z, 0.0, p.z - hi.z})));
  }
  return nearest;
}

Vec3 mean(const std::vector<Vec3>& points) {
  Vec3 sum{0};
  for (const Vec3& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

uint32_t floorIndex(const Scene& scene) {
  const Surface& floor = test::surfaceOf(scene, "room", "bottom");
  return static_cast<uint32_t>(&floor - scene.surfaces.data());
}

// Moves `name` of `asset` by `step`: the floor's footprints move by hole removal and insertion
// in its adaptive mesh. Every element of the floor within `near` of neither the old nor the new
// footprints goes on under its key, corners unmoved; the elements removed and added lie within
// it; the mesh stays conforming with exact boundaries. (The floor was meshed anew: every key
// new.) Returns the share of the floor's elements that went on.
double expectFootprintsMovedLocally(const std::string& asset, const std::string& name, const Vec3& step, double near) {
  Scene loaded = loadScene(std::string(WALKRAD_ASSETS) + "/" + asset);
  MeshedScene meshed = meshScene(loaded);
  SceneEditor editor(std::move(loaded), std::move(meshed));
  const uint32_t floor = floorIndex(editor.scene());
  const uint32_t object = *editor.findObject(name);
  const Surface before = editor.scene().surfaces[floor];
  const auto elementsBefore = elementsByKey(editor.meshed().surfaces[floor]);
  ObjectPose pose = poseOf(editor.scene().objects[object]);
  pose.position += step;
  EXPECT_TRUE(editor.setPose(object, pose));
  const Surface& after = editor.scene().surfaces[floor];
  EXPECT_NE(after.holes, before.holes);
  const std::vector<EditedSurface> edited = editor.takeEdited();
  const auto floorEdit = std::find_if(edited.begin(), edited.end(), [&](const EditedSurface& e) { return e.surface == floor; });
  EXPECT_NE(floorEdit, edited.end());
  if (floorEdit == edited.end()) return 0;
  EXPECT_FALSE(floorEdit->meshedAnew);
  EXPECT_TRUE(floorEdit->holesChanged);

  std::vector<Ring3> footprints(before.holes.end() - static_cast<ptrdiff_t>(before.contactHoles), before.holes.end());
  footprints.insert(footprints.end(), after.holes.end() - static_cast<ptrdiff_t>(after.contactHoles), after.holes.end());
  const SurfaceMesh& mesh = editor.meshed().surfaces[floor];
  const auto elementsAfter = elementsByKey(mesh);
  size_t kept = 0, removed = 0, added = 0;
  for (const auto& [key, corners] : elementsBefore) {
    const auto found = elementsAfter.find(key);
    if (found != elementsAfter.end()) {
      ++kept;
      EXPECT_EQ(found->second, corners);
    } else {
      ++removed;
      EXPECT_LT(distanceToFootprints(mean(corners), footprints), near);
    }
  }
  for (const auto& [key, corners] : elementsAfter)
    if (!elementsBefore.count(key)) {
      ++added;
      EXPECT_LT(distanceToFootprints(mean(corners), footprints), near);
    }
  const auto holeEdit = std::find_if(editor.holeEdits().begin(), editor.holeEdits().end(),
                                     [&](const SceneEditor::HoleEdit& h) { return h.surface == floor; });
  EXPECT_NE(holeEdit, editor.holeEdits().end());
  if (holeEdit != editor.holeEdits().end()) {
    EXPECT_EQ(holeEdit->removed, removed);
    EXPECT_EQ(holeEdit->added, added);
  }
  std::printf("%s, %s moved: of the floor's %zu elements %zu went on, %zu removed, %zu added\n", asset.c_str(),
              name.c_str(), elementsBefore.size(), kept, removed, added);
  mesher::test::expectValidMesh(mesher::checkMesh(mesh.polygon, mesh.mesh), false);
  for (const Vec3& p : mesh.positions) EXPECT_EQ(p.y, before.outer.front().y);
  return static_cast<double>(kept) / static_cast<double>(elementsBefore.size());
}

TEST(SceneEditor, AMovedBoxKeepsTheFloorsElementsAwayFromItsFootprint) {
  // Patches of 0.5 m: the grading around a footprint reaches about two patch sizes, which on this
  // 4 x 3 m floor under a 0.9 m box is a third of it.
  EXPECT_GT(expectFootprintsMovedLocally("box-on-floor.json", "box", Vec3{0.3, 0, 0}, 1.0), 0.7);
}

TEST(SceneEditor, AMovedKitchenChairKeepsTheFloorsElementsAwayFromItsLegs) {
  // Patches of 12 inches; four legs' footprints go and come.
  EXPECT_GT(expectFootprintsMovedLocally("kitchen.json", "chair 1", Vec3{6, 0, -4}, 24), 0.8);
}

// Moving the box back where it was loaded meshes the floor as it was loaded, element for element
// and point for point (hole insertion leaves a mesh a little different from the mesher's around
// a footprint), and the elements it kept all the while go on under their loaded keys.
TEST(SceneEditor, MovingThereAndBackRestoresTheFloorsLoadedMesh) {
  Scene loaded = loadScene(std::string(WALKRAD_ASSETS) + "/box-on-floor.json");
  const MeshedScene meshedLoaded = meshScene(loaded);
  SceneEditor editor(loaded, meshedLoaded);
  const uint32_t floor = floorIndex(loaded), box = *editor.findObject("box");
  const ObjectPose home = poseOf(loaded.objects[box]);
  for (const Vec3 step : {Vec3{0.3, 0, 0}, Vec3{0.3, 0, 0.2}, Vec3{-0.2, 0, 0.4}}) {
    editor.setPose(box, {home.position + step, home.rotateYDeg});
    ASSERT_EQ(editor.holeEdits().size(), 1u);
  }
  editor.takeEdited();
  editor.setPose(box, home);
  const SurfaceMesh& mesh = editor.meshed().surfaces[floor];
  EXPECT_EQ(mesh.mesh.elements, meshedLoaded.surfaces[floor].mesh.elements);
  EXPECT_EQ(mesh.positions, meshedLoaded.surfaces[floor].positions);
  EXPECT_EQ(mesh.keys, meshedLoaded.surfaces[floor].keys);
  for (const EditedSurface& e : editor.takeEdited())
    EXPECT_EQ(e, (EditedSurface{e.surface, false, e.surface == floor})) << editor.scene().surfaces[e.surface].face;
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

// The scene as the thread that draws holds it (SceneView) against the document (LitScene): a
// move shows at once and costs only the moved object; the document's updates make the view's
// display the document's, and its refusals put objects back.
#include "engine/document/lit_scene.h"
#include "engine/document/scene_view.h"
#include "engine/geometry/meshed_scene.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>

namespace engine {
namespace {

LitSceneSettings coarse() {
  LitSceneSettings settings;
  settings.solver.resolution = 64;
  return settings;
}

// The base scene (a room with a box on its floor) as the view and the document start from it.
struct Pair {
  Scene scene = test::parse(test::baseScene());
  MeshedScene meshed = meshScene(scene);
  SceneView view{scene, meshed};
  LitScene document{scene, meshed, coarse()};
};

// The view's display is the document's, vertex for vertex (positions to float rounding) and
// element for element.
void expectSameDisplay(const DisplayMesh& view, const MeshedScene& document) {
  const DisplayMesh fresh = displayMesh(document, view.origin);
  ASSERT_EQ(view.positions.size(), fresh.positions.size());
  EXPECT_EQ(view.triangles, fresh.triangles);
  EXPECT_EQ(view.surfaceVertexStart, fresh.surfaceVertexStart);
  for (size_t v = 0; v < fresh.positions.size(); ++v)
    EXPECT_LT(glm::length(view.positions[v] - fresh.positions[v]), 1e-5f) << "vertex " << v;
}

TEST(SceneView, AMoveShowsAtOnceAndMovesOnlyTheObject) {
  Pair pair;
  SceneView& view = pair.view;
  const uint32_t box = *view.poses().findObject("box");
  const DisplayMesh before = view.display();
  const ObjectPose pose{Vec3{0.5, 0, 0.75}, 30};
  ASSERT_TRUE(view.setPose(box, pose));
  EXPECT_EQ(view.poses().pose(box), pose);
  const RigidMotion motion = view.poses().motionTo(box, pose);
  const DisplayMesh& after = view.display();
  ASSERT_EQ(after.positions.size(), before.positions.size());
  for (uint32_t s = 0; s < view.scene().surfaces.size(); ++s)
    for (uint32_t v = before.surfaceVertexStart[s]; v < before.surfaceVertexStart[s + 1]; ++v) {
      const bool ofBox = view.scene().surfaces[s].object == box;
      const glm::dvec3 loaded = glm::dvec3(before.positions[v]) + before.origin;
      const glm::vec3 expected = ofBox ? glm::vec3(motion.place(loaded) - after.origin) : before.positions[v];
      if (ofBox) EXPECT_LT(glm::length(after.positions[v] - expected), 1e-5f);
      else EXPECT_EQ(after.positions[v], expected);
    }
  // Picking sees the box where it is shown: its surfaces moved, without cut-outs.
  for (uint32_t s : view.poses().surfacesOf(box))
    EXPECT_EQ(view.scene().surfaces[s].outer[0], motion.place(pair.scene.surfaces[s].outer[0]));
}

TEST(SceneView, TheDocumentsUpdatesMakeTheViewItsDisplay) {
  Pair pair;
  const uint32_t box = *pair.view.poses().findObject("box");
  for (const ObjectPose& pose : {ObjectPose{Vec3{0.5, 0, 0.75}, 0}, ObjectPose{Vec3{-0.5, 0, 0.25}, 45}, ObjectPose{}}) {
    pair.view.setPose(box, pose);
    ASSERT_TRUE(pair.document.setPose(box, pose));
    const std::vector<SurfaceUpdate> updates = pair.document.takeUpdates();
    // The box's surfaces and the floor it stands on, each once.
    std::vector<uint32_t> surfaces;
    for (const SurfaceUpdate& u : updates) surfaces.push_back(u.surface);
    std::vector<uint32_t> expected = pair.view.poses().surfacesOf(box);
    expected.push_back(static_cast<uint32_t>(&test::surfaceOf(pair.document.scene(), "room", "bottom") - pair.document.scene().surfaces.data()));
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(surfaces, expected);
    EXPECT_TRUE(pair.view.take({nullptr, updates, {}}).geometry);
    expectSameDisplay(pair.view.display(), pair.document.meshed());
  }
  EXPECT_TRUE(pair.document.takeUpdates().empty());
}

// An update made at one pose is shown where the object stands in the view now: the view has
// moved on while the document worked.
TEST(SceneView, AnUpdateForAnOlderPoseIsShownAtTheNewest) {
  Pair pair;
  const uint32_t box = *pair.view.poses().findObject("box");
  const ObjectPose first{Vec3{0.5, 0, 0.75}, 0}, newest{Vec3{0.5, 0, -0.25}, 90};
  pair.view.setPose(box, first);
  pair.document.setPose(box, first);
  pair.view.setPose(box, newest);
  pair.view.take({nullptr, pair.document.takeUpdates(), {}});
  pair.document.setPose(box, newest);
  // The box is shown where the document now has it (its floor comes with the newest pose's update).
  const DisplayMesh& shown = pair.view.display();
  const DisplayMesh fresh = displayMesh(pair.document.meshed(), shown.origin);
  for (uint32_t s : pair.view.poses().surfacesOf(box)) {
    ASSERT_EQ(shown.surfaceVertexStart[s + 1] - shown.surfaceVertexStart[s], fresh.surfaceVertexStart[s + 1] - fresh.surfaceVertexStart[s]);
    for (uint32_t k = 0; k < shown.surfaceVertexStart[s + 1] - shown.surfaceVertexStart[s]; ++k)
      EXPECT_LT(glm::length(shown.positions[shown.surfaceVertexStart[s] + k] - fresh.positions[fresh.surfaceVertexStart[s] + k]), 1e-5f);
  }
}

TEST(SceneView, ARefusalPutsTheObjectBackUnlessItMovedAgain) {
  Pair pair;
  SceneView& view = pair.view;
  const uint32_t box = *view.poses().findObject("box");
  const DisplayMesh loaded = view.display();
  const ObjectPose refused{Vec3{0.5, 0, 0.75}, 0}, later{Vec3{0.25, 0, 0}, 0};
  view.setPose(box, refused);
  view.setPose(box, later);
  // A refusal of a pose the view has moved on from: the later pose waits for its own verdict.
  SceneView::Taken taken = view.take({nullptr, {}, {PoseRefusal{box, refused, ObjectPose{}, "no"}}});
  EXPECT_TRUE(taken.movedBack.empty());
  EXPECT_EQ(view.poses().pose(box), later);
  taken = view.take({nullptr, {}, {PoseRefusal{box, later, ObjectPose{}, "no"}}});
  EXPECT_EQ(taken.movedBack, std::vector<uint32_t>{box});
  EXPECT_TRUE(taken.geometry);
  EXPECT_EQ(view.poses().pose(box), ObjectPose{});
  for (size_t v = 0; v < loaded.positions.size(); ++v)
    EXPECT_LT(glm::length(view.display().positions[v] - loaded.positions[v]), 1e-5f) << "vertex " << v;
}

// A pose the document refuses changes nothing of it: scene, meshes, light, and no update.
TEST(LitScene, ARefusedPoseChangesNothing) {
  Pair pair;
  const uint32_t box = *pair.document.editor().findObject("box");
  pair.document.solve(0.05, 100);
  const std::vector<glm::dvec3> before(pair.document.solver().elementRadiance(0).begin(),
                                       pair.document.solver().elementRadiance(0).end());
  const uint64_t shots = pair.document.solver().stats().shots;
  pair.document.takeUpdates();
  EXPECT_THROW(pair.document.setPose(box, {Vec3{2e6, 0, 0}, 0}), std::invalid_argument);
  EXPECT_TRUE(pair.document.takeUpdates().empty());
  EXPECT_EQ(pair.document.solver().stats().shots, shots);
  EXPECT_EQ(pair.document.solver().pendingCorrections(), 0u);
  const std::span<const glm::dvec3> after = pair.document.solver().elementRadiance(0);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), after.begin(), after.end()));
}

}  // namespace
}  // namespace engine

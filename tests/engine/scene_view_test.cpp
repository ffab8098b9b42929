// The scene as the thread that draws holds it (SceneView) against the document (LitScene): a
// move shows at once and costs only the moved object; the document's updates make the view's
// display the document's, and its refusals put objects back.
#include "engine/document/lit_scene.h"
#include "engine/document/scene_view.h"
#include "engine/geometry/meshed_scene.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <malloc.h>

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

// Surface s's display vertices where the view shows them: through its object's transform.
std::vector<glm::vec3> shown(const SceneView& view, uint32_t s) {
  const SurfaceDisplay& display = view.display().surfaces[s];
  const glm::dmat4 transform = view.objectTransform(display.object);
  std::vector<glm::vec3> positions;
  for (const glm::vec3& p : display.positions) positions.emplace_back(transform * glm::dvec4(p, 1));
  return positions;
}

// The view shows surface s as the document has it, vertex for vertex (to float rounding) and
// element for element.
void expectShownAsTheDocumentHasIt(const SceneView& view, const LitScene& document, uint32_t s) {
  const DisplayMesh fresh = displayMesh(document.scene(), document.meshed(), view.display().origin);
  EXPECT_EQ(view.display().surfaces[s].triangles, fresh.surfaces[s].triangles) << "surface " << s;
  const std::vector<glm::vec3> positions = shown(view, s);
  ASSERT_EQ(positions.size(), fresh.surfaces[s].positions.size()) << "surface " << s;
  for (size_t v = 0; v < positions.size(); ++v)
    EXPECT_LT(glm::length(positions[v] - fresh.surfaces[s].positions[v]), 1e-5f) << "surface " << s << ", vertex " << v;
}

// A move changes the object's transform and its surfaces for picking, and no display vertex.
TEST(SceneView, AMoveShowsAtOnceThroughTheObjectsTransform) {
  Pair pair;
  SceneView& view = pair.view;
  const uint32_t box = *view.poses().findObject("box");
  const DisplayMesh before = view.display();
  const ObjectPose pose{Vec3{0.5, 0, 0.75}, 30};
  ASSERT_TRUE(view.setPose(box, pose));
  EXPECT_EQ(view.poses().pose(box), pose);
  const RigidMotion motion = view.poses().motionTo(box, pose);
  for (uint32_t s = 0; s < view.scene().surfaces.size(); ++s) {
    EXPECT_EQ(view.display().surfaces[s].positions, before.surfaces[s].positions);
    const bool ofBox = view.scene().surfaces[s].object == box;
    const std::vector<glm::vec3> positions = shown(view, s);
    for (size_t v = 0; v < positions.size(); ++v) {
      const glm::dvec3 loaded = glm::dvec3(before.surfaces[s].positions[v]) + before.origin;
      const glm::vec3 expected(ofBox ? motion.place(loaded) - before.origin : loaded - before.origin);
      EXPECT_LT(glm::length(positions[v] - expected), 1e-5f) << "surface " << s << ", vertex " << v;
    }
  }
  EXPECT_EQ(view.objectTransform(*view.poses().findObject("room")), glm::dmat4{1.0});
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
    // The box's surfaces moved along (the view has their meshes where it was loaded); the floor's
    // was meshed anew.
    for (const SurfaceUpdate& u : updates) EXPECT_EQ(u.meshChanged, pair.scene.surfaces[u.surface].object != box) << u.surface;
    const auto floor = static_cast<uint32_t>(&test::surfaceOf(pair.document.scene(), "room", "bottom") - pair.document.scene().surfaces.data());
    EXPECT_EQ(pair.view.take({nullptr, updates, {}}).surfaces, std::vector<uint32_t>{floor});
    for (uint32_t s = 0; s < pair.scene.surfaces.size(); ++s) expectShownAsTheDocumentHasIt(pair.view, pair.document, s);
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
  for (uint32_t s : pair.view.poses().surfacesOf(box)) expectShownAsTheDocumentHasIt(pair.view, pair.document, s);
}

TEST(SceneView, ARefusalPutsTheObjectBackUnlessItMovedAgain) {
  Pair pair;
  SceneView& view = pair.view;
  const uint32_t box = *view.poses().findObject("box");
  const ObjectPose refused{Vec3{0.5, 0, 0.75}, 0}, later{Vec3{0.25, 0, 0}, 0};
  view.setPose(box, refused);
  view.setPose(box, later);
  // A refusal of a pose the view has moved on from: the later pose waits for its own verdict.
  SceneView::Taken taken = view.take({nullptr, {}, {PoseRefusal{box, refused, ObjectPose{}, "no"}}});
  EXPECT_TRUE(taken.movedBack.empty());
  EXPECT_EQ(view.poses().pose(box), later);
  taken = view.take({nullptr, {}, {PoseRefusal{box, later, ObjectPose{}, "no"}}});
  EXPECT_EQ(taken.movedBack, std::vector<uint32_t>{box});
  EXPECT_EQ(view.poses().pose(box), ObjectPose{});
  EXPECT_EQ(view.objectTransform(box), glm::dmat4{1.0});
}

// The poses keep the surfaces as loaded for movable objects only, the ones they place: a
// building's fixed walls are most of its surfaces (the White Room's 266,000), and a Surface kept
// for each took 45 MB of every ScenePoses (the view's and the document's).
TEST(ScenePoses, KeepsTheLoadedSurfacesOfMovableObjectsOnly) {
  const auto heldPerSurface = [](bool movable) {
    Scene scene;
    scene.objects.push_back({});
    scene.objects[0].movable = movable;
    constexpr size_t kSurfaces = 20000;
    for (size_t i = 0; i < kSurfaces; ++i) {
      Surface& s = scene.surfaces.emplace_back();
      const double x = static_cast<double>(i);
      s.outer = {{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 0, 1}, {x, 0, 1}};
    }
    scene.computeBounds();
    const auto heap = [] {
      const struct mallinfo2 m = mallinfo2();
      return static_cast<double>(m.uordblks + m.hblkhd);
    };
    const double before = heap();
    const ScenePoses poses(std::move(scene));
    return (heap() - before) / kSurfaces;
  };
  const double fixed = heldPerSurface(false), movable = heldPerSurface(true);
  if (movable <= 0) GTEST_SKIP() << "mallinfo2 counts no heap under this allocator";
  EXPECT_GT(movable, static_cast<double>(sizeof(Surface)));
  EXPECT_LT(fixed, 16);
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

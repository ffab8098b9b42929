// Adaptive refinement during solving (thesis 5.5) on a shadow: the mesh follows the shadow's
// edge, stays conforming and exact, the light's ledgers stay exact, and the adapted solution is
// what a fresh solve on the adapted mesh gives (new elements gather, they are not interpolated).
#include "engine/document/lighting.h"
#include "engine/document/mesh_adaptation.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "mesher/mesh_check.h"
#include "tests/engine/test_scenes.h"
#include "tests/mesher/mesh_expectations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace engine {
namespace {

constexpr double kConverge = 1e-2;
// Hemispheres of 128 pixels across: a quarter of the default's work, the same conclusions.
const radiosity::SolverSettings kSettings{.resolution = 128};

// A 4 x 3 m room lit by a 1 m lamp in its ceiling, a box hovering 0.6-0.9 m above the floor
// under it ("box", 0.8 x 0.6 m): its shadow on the floor has a sharp edge near the box and
// penumbrae around.
Scene shadowScene() {
  Json scene = test::baseScene();
  scene["objects"][0]["solids"][0]["faces"]["top"]["holes"][0]["polygon"] = Json::parse("[[1.5, 1], [2.5, 1], [2.5, 2], [1.5, 2]]");
  scene["objects"][1]["solids"][0] = Json::parse(R"({ "profile": [[1.6, 1.2], [2.4, 1.2], [2.4, 1.8], [1.6, 1.8]],
                                                     "from": 0.6, "to": 0.9, "material": "white" })");
  return test::parse(scene);
}

uint32_t floorOf(const Scene& scene) {
  for (uint32_t s = 0; s < scene.surfaces.size(); ++s)
    if (scene.objects[scene.surfaces[s].object].name == "room" && scene.surfaces[s].face == "bottom") return s;
  ADD_FAILURE() << "no floor";
  return 0;
}

// Distance in the floor's plane from p to the rectangle [x0, x1] x [z0, z1] (0 inside).
double distanceToRectangle(const Vec3& p, double x0, double x1, double z0, double z1) {
  const double dx = std::max({x0 - p.x, 0.0, p.x - x1}), dz = std::max({z0 - p.z, 0.0, p.z - z1});
  return std::hypot(dx, dz);
}

struct ElementSizes {
  double meanNear = 0, meanFar = 0, smallestNear = 1e300;
  size_t near = 0, far = 0;
};

// Floor elements by the distance of their centroid from the box's outline seen from above:
// near (within 0.5 m, where its shadow's edges fall) and far (beyond 1.2 m); their sizes are
// their longest edges.
ElementSizes floorSizes(const Scene& scene, const MeshedScene& meshed, double x0, double x1) {
  const SurfaceMesh& floor = meshed.surfaces[floorOf(scene)];
  ElementSizes out;
  for (const auto& corners : floor.mesh.elements) {
    const int n = corners[3] == mesher::Mesh::kNone ? 3 : 4;
    Vec3 centroid{0};
    double size = 0;
    for (int k = 0; k < n; ++k) {
      centroid += floor.positions[corners[k]] / double(n);
      size = std::max(size, glm::length(floor.positions[corners[(k + 1) % n]] - floor.positions[corners[k]]));
    }
    const double d = distanceToRectangle(centroid, x0, x1, 1.2, 1.8);
    if (d < 0.5) out.meanNear += size, ++out.near, out.smallestNear = std::min(out.smallestNear, size);
    else if (d > 1.2) out.meanFar += size, ++out.far;
  }
  out.meanNear /= double(out.near);
  out.meanFar /= double(out.far);
  return out;
}

// Mean absolute difference of element radiance over the mean, all surfaces (same meshes).
double relativeDifference(const radiosity::Solver& a, const radiosity::Solver& b) {
  double difference = 0, level = 0;
  for (uint32_t s = 0; s < a.surfaceCount(); ++s) {
    const auto ra = a.elementRadiance(s), rb = b.elementRadiance(s);
    EXPECT_EQ(ra.size(), rb.size());
    for (size_t e = 0; e < std::min(ra.size(), rb.size()); ++e)
      for (int c = 0; c < 3; ++c) difference += std::abs(ra[e][c] - rb[e][c]), level += std::abs(rb[e][c]);
  }
  return difference / level;
}

TEST(MeshAdaptation, RefinesAlongTheShadowAndGathersWhatAFreshSolveGives) {
  const Scene scene = shadowScene();
  const MeshedScene meshed = meshScene(scene);
  AdaptiveMeshes adaptive(scene.surfaces.size());
  MeshAdaptation adaptation(scene, meshed, {}, adaptive);
  radiosity::Solver solver(adaptation.input(), kSettings);
  solveTo(solver, kConverge, UINT64_MAX, {}, &adaptation);
  ASSERT_TRUE(solver.converged(kConverge));
  EXPECT_GT(adaptation.passes(), 0u);
  EXPECT_GT(solver.elementCount(), radiosity::Solver(radiosityInput(scene, meshed), kSettings).elementCount());

  // Smaller elements around the shadow than far from it, down to the minimum size (a quarter of
  // the 0.5 m patch size) and no further.
  const ElementSizes sizes = floorSizes(scene, adaptation.meshed(), 1.6, 2.4);
  std::printf("floor elements near the shadow: %zu, mean size %.3f m (smallest %.3f); far: %zu, mean %.3f m; "
              "%zu elements in all (%llu passes)\n",
              sizes.near, sizes.meanNear, sizes.smallestNear, sizes.far, sizes.meanFar, solver.elementCount(),
              static_cast<unsigned long long>(adaptation.passes()));
  EXPECT_LT(sizes.meanNear, 0.75 * sizes.meanFar);
  EXPECT_LT(sizes.smallestNear, 0.15);
  EXPECT_GE(sizes.smallestNear, 0.125 - 1e-9);

  // Every adapted mesh conforming, exact at its boundary, its own points first and unmoved.
  for (size_t s = 0; s < scene.surfaces.size(); ++s)
    mesher::test::expectValidMesh(mesher::checkMesh(adaptation.meshed().surfaces[s].polygon, adaptation.meshed().surfaces[s].mesh));

  // The power ledgers are exact through the passes.
  EXPECT_LT(solver.ledgerResidual(), 1e-9);

  // Gathering, not interpolating: a fresh solve on the final mesh gives the same light.
  radiosity::Solver fresh(adaptation.input(), kSettings);
  fresh.solve(kConverge);
  const double difference = relativeDifference(solver, fresh);
  std::printf("adapted against a fresh solve on the adapted mesh: %.3f%%\n", 100 * difference);
  EXPECT_LT(difference, 0.01);
}

// Where a gradient disappears the mesh coarsens: the box moves 1.5 m aside and its old shadow's
// refinement goes again.
TEST(MeshAdaptation, CoarsensWhereTheShadowWent) {
  SceneEditor editor(shadowScene(), meshScene(shadowScene()));
  MeshAdaptation adaptation(editor.scene(), editor.meshed(), {}, editor.adaptiveMeshes());
  std::unique_ptr<radiosity::Solver> solver = std::make_unique<radiosity::Solver>(adaptation.input(), kSettings);
  solveTo(*solver, kConverge, UINT64_MAX, {}, &adaptation);
  const ElementSizes before = floorSizes(editor.scene(), adaptation.meshed(), 1.6, 2.4);

  const uint32_t box = *editor.findObject("box");
  ObjectPose pose = poseOf(editor.scene().objects[box]);
  pose.position.x -= 1.5;
  editor.setPose(box, pose);
  applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited(), &adaptation);
  solveTo(*solver, kConverge, UINT64_MAX, {}, &adaptation);
  const ElementSizes after = floorSizes(editor.scene(), adaptation.meshed(), 1.6, 2.4);
  const ElementSizes moved = floorSizes(editor.scene(), adaptation.meshed(), 0.1, 0.9);
  std::printf("around the old shadow: %zu elements before the move, %zu after; around the new: %zu\n", before.near,
              after.near, moved.near);
  EXPECT_LT(after.near, before.near);
  EXPECT_GT(after.meanNear, before.meanNear);
  EXPECT_LT(moved.meanNear, moved.meanFar);
  EXPECT_LT(solver->ledgerResidual(), 1e-9);
  // Every mesh where its surface is now: the box's, refined again after the move, too.
  for (size_t s = 0; s < editor.scene().surfaces.size(); ++s) {
    const Surface& surface = editor.scene().surfaces[s];
    const SurfaceMesh& mesh = adaptation.meshed().surfaces[s];
    mesher::test::expectValidMesh(mesher::checkMesh(mesh.polygon, mesh.mesh));
    Vec3 low = surface.outer.front(), high = low;
    for (const Vec3& p : surface.outer) low = glm::min(low, p), high = glm::max(high, p);
    for (const Vec3& p : mesh.positions) {
      EXPECT_NEAR(glm::dot(p, surface.normal), surface.planeOffset(), 1e-9);
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, low - 1e-9)) && glm::all(glm::lessThanEqual(p, high + 1e-9)))
          << surface.face << " of " << editor.scene().objects[surface.object].name;
    }
  }
}

// The hovering box turned and moved: its surfaces keep the plane coordinates they were meshed in
// (only their frame moves), so their adaptive meshes are their meshes again, refining goes on in
// them, and the vertices they had stay where the move put them. A pass hands the solver only the
// surfaces it changed.
TEST(MeshAdaptation, AMovedSurfaceIsRefinedInThePlaneCoordinatesItWasMeshedIn) {
  SceneEditor editor(shadowScene(), meshScene(shadowScene()));
  const MeshedScene loaded = editor.meshed();
  MeshAdaptation adaptation(editor.scene(), editor.meshed(), {}, editor.adaptiveMeshes());
  auto solver = std::make_unique<radiosity::Solver>(adaptation.input(), kSettings);
  solveTo(*solver, kConverge, UINT64_MAX, {}, &adaptation);

  const uint32_t box = *editor.findObject("box");
  ObjectPose pose = poseOf(editor.scene().objects[box]);
  pose.position += Vec3{-0.7, 0.2, 0.3};
  pose.rotateYDeg += 30;
  ASSERT_TRUE(editor.setPose(box, pose));
  ASSERT_TRUE(editor.remeshed().empty());  // it touches nothing
  const std::vector<radiosity::SurfaceChange> changes =
      applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited(), &adaptation);
  ASSERT_EQ(changes.size(), editor.surfacesOf(box).size());
  for (uint32_t s : editor.surfacesOf(box)) {
    const SurfaceMesh& mesh = adaptation.meshed().surfaces[s];
    EXPECT_EQ(mesh.polygon.outer, loaded.surfaces[s].polygon.outer);
    EXPECT_EQ(mesh.mesh.vertices, loaded.surfaces[s].mesh.vertices);
    EXPECT_EQ(mesh.positions, editor.meshed().surfaces[s].positions);
  }

  // Passes until one refines a surface of the box, each handing the solver what it changed.
  size_t refined = 0;
  for (int tries = 0; tries < 50 && refined == 0; ++tries) {
    solver->solve(0, 10);
    const MeshedScene before = adaptation.meshed();
    const uint64_t edited = solver->stats().editedSurfaces;
    if (adaptation.pass(*solver) == 0) continue;
    size_t changed = 0;
    for (size_t s = 0; s < before.surfaces.size(); ++s) {
      const SurfaceMesh &was = before.surfaces[s], &is = adaptation.meshed().surfaces[s];
      if (is.keys == was.keys) continue;
      ++changed;
      if (editor.scene().surfaces[s].object != box) continue;
      ++refined;
      EXPECT_EQ(std::vector<Vec3>(is.positions.begin(), is.positions.begin() + was.positions.size()), was.positions);
      for (const Vec3& p : is.positions) EXPECT_NEAR(glm::dot(p, editor.scene().surfaces[s].normal), editor.scene().surfaces[s].planeOffset(), 1e-9);
    }
    EXPECT_EQ(solver->stats().editedSurfaces - edited, changed);
    EXPECT_LT(changed, before.surfaces.size());
  }
  EXPECT_GT(refined, 0u);
}

// The floor of box-on-floor refined around the box's shadow, then the box moved 0.3 m: the
// footprint moves in the floor's adaptive mesh, the one that was refined, so the refinement away
// from the footprints stays, under the same keys (the floor was meshed anew and lost it all).
TEST(MeshAdaptation, AMoveKeepsTheRefinementAwayFromTheFootprints) {
  const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/box-on-floor.json");
  SceneEditor editor(scene, meshScene(scene));
  MeshAdaptation adaptation(editor.scene(), editor.meshed(), {}, editor.adaptiveMeshes());
  auto solver = std::make_unique<radiosity::Solver>(adaptation.input(), kSettings);
  solveTo(*solver, kConverge, UINT64_MAX, {}, &adaptation);
  const uint32_t floor = floorOf(scene);
  const std::set<uint64_t> loadedKeys(editor.meshed().surfaces[floor].keys.begin(), editor.meshed().surfaces[floor].keys.end());
  const SurfaceMesh before = adaptation.meshed().surfaces[floor];
  std::set<uint64_t> refined;
  for (uint64_t key : before.keys)
    if (!loadedKeys.count(key)) refined.insert(key);
  ASSERT_GT(refined.size(), 20u);

  const uint32_t box = *editor.findObject("box");
  ObjectPose pose = poseOf(editor.scene().objects[box]);
  pose.position.x += 0.3;
  ASSERT_TRUE(editor.setPose(box, pose));
  const std::vector<radiosity::SurfaceChange> changes =
      applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited(), &adaptation);
  for (const radiosity::SurfaceChange& c : changes) EXPECT_FALSE(c.meshedAnew && c.surface == floor);
  const SurfaceMesh& after = adaptation.meshed().surfaces[floor];
  const std::set<uint64_t> keysAfter(after.keys.begin(), after.keys.end());
  size_t keptRefined = 0;
  for (size_t e = 0; e < before.keys.size(); ++e) {
    if (!refined.count(before.keys[e])) continue;
    if (keysAfter.count(before.keys[e])) {
      ++keptRefined;
      continue;
    }
    // A refined element that went lay near where the box stood (x 1.2 to 2.1, z 1.3 to 2.2) or
    // stands (x 0.3 further).
    Vec3 centroid{0};
    int n = 0;
    for (uint32_t v : before.mesh.elements[e])
      if (v != mesher::Mesh::kNone) centroid += before.positions[v], ++n;
    EXPECT_LT(distanceToRectangle(centroid / double(n), 1.2, 2.4, 1.3, 2.2), 1.0);
  }
  std::printf("refined floor elements: %zu before the move, %zu of them kept\n", refined.size(), keptRefined);
  EXPECT_GT(keptRefined, refined.size() / 2);
  mesher::test::expectValidMesh(mesher::checkMesh(after.polygon, after.mesh), false);
  solveTo(*solver, kConverge, UINT64_MAX, {}, &adaptation);
  EXPECT_LT(solver->ledgerResidual(), 1e-9);
}

}  // namespace
}  // namespace engine

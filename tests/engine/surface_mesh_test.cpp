// Meshing one surface: a triangle that is already a good element stays one; a repeat of a
// surface met before gets the mesh meshing it gives; every mesh is an adaptive mesh's, under its
// handles.
#include "engine/geometry/surface_mesh.h"

#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "mesher/adaptive_mesh.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

Surface triangle(Vec3 a, Vec3 b, Vec3 c, double patchSize) {
  Surface s;
  s.outer = {a, b, c};
  s.normal = {0, 1, 0};
  s.patchSize = patchSize;
  return s;
}

TEST(SurfaceMesh, AWellShapedTriangleWithinThePatchSizeIsOneElement) {
  // Counter-clockwise seen from +y: (0,0,0), (0,0,1), (1,0,0); angles 45, 45, 90 degrees.
  const auto meshed = [](const Surface& s) {
    mesher::Mesher mesher;
    return meshSurface(s, mesher);
  };
  const SurfaceMesh small = meshed(triangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 2));
  ASSERT_EQ(small.mesh.elements.size(), 1u);
  EXPECT_EQ(small.mesh.elements[0][3], mesher::Mesh::kNone);
  EXPECT_EQ(small.positions, (std::vector<Vec3>{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}));
  // Longer than the patch size, or with an angle under the bound (10 degrees): the quadtree's.
  EXPECT_GT(meshed(triangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 0.5)).mesh.elements.size(), 1u);
  EXPECT_GT(meshed(triangle({0, 0, 0}, {0, 0, 0.176}, {1, 0, 0}, 2)).mesh.elements.size(), 1u);
}

// A scene's surfaces meshed by one Mesher, as a scene is loaded: the kitchen's boxes have
// opposite faces alike, and its cabinets, doors and chairs repeat, so most surfaces are repeats
// of one met before. Each gets the mesh, and the 3-D points, that meshing it alone gives.
TEST(SurfaceMesh, RepeatsInTheKitchenGetTheMeshesMeshingGives) {
  const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/kitchen.json");
  mesher::Mesher shared;
  for (const Surface& s : scene.surfaces) {
    const SurfaceMesh once = meshSurface(s, shared);
    mesher::Mesher alone(0);
    const SurfaceMesh fresh = meshSurface(s, alone);
    ASSERT_EQ(once.mesh.elements, fresh.mesh.elements);
    ASSERT_EQ(once.mesh.vertices, fresh.mesh.vertices);
    ASSERT_EQ(once.positions, fresh.positions);
  }
  EXPECT_GT(shared.repeats(), scene.surfaces.size() / 2);
}

// A mesh holds what it uses, not the mesher's buffers sized for its tree: a scene's meshes are
// held while it is lit.
TEST(SurfaceMesh, AMeshHoldsNoMoreThanItUses) {
  const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/kitchen.json");
  mesher::Mesher mesher;
  for (const Surface& s : scene.surfaces) {
    const SurfaceMesh meshed = meshSurface(s, mesher);
    ASSERT_EQ(meshed.mesh.vertices.capacity(), meshed.mesh.vertices.size());
    ASSERT_EQ(meshed.mesh.elements.capacity(), meshed.mesh.elements.size());
  }
}

// A surface's mesh is the mesh an adaptive mesh of its polygon makes, element for element, and
// its keys are that mesh's handles for them (element i: slot i, generation 0), so that adaptive
// refinement and the solver know its elements by key (mesh_adaptation.h). Every surface of the
// shipped scenes, meshed as a scene is (through one Mesher, repeats and all).
TEST(SurfaceMesh, AnAdaptiveMeshOfEachShippedSurfaceIsItsMeshUnderItsKeys) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "box-on-floor.json", "furnace.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const MeshedScene meshed = meshScene(scene);
    for (size_t s = 0; s < scene.surfaces.size(); ++s) {
      const SurfaceMesh& m = meshed.surfaces[s];
      const mesher::AdaptiveMesh adaptive(m.polygon, {scene.surfaces[s].patchSize});
      const mesher::Mesh snapshot = adaptive.snapshot();
      ASSERT_EQ(snapshot.elements, m.mesh.elements) << scene.surfaces[s].jsonPath;
      ASSERT_EQ(snapshot.vertices, m.mesh.vertices) << scene.surfaces[s].jsonPath;
      const std::vector<mesher::ElementId> ids = adaptive.elements();
      ASSERT_EQ(elementKeys(ids), m.keys) << scene.surfaces[s].jsonPath;
      for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], (mesher::ElementId{i, 0}));
    }
  }
}

}  // namespace
}  // namespace engine

// Coplanar merging (thesis 3.2): touching faces of one material in one plane become one surface.
#include "engine/coplanar_merge.h"

#include "engine/scene_loader.h"
#include "engine/surface_mesh.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <map>

namespace engine {
namespace {

Json box(double x0, double z0, double x1, double z1, const char* material = "white") {
  return {{"profile", {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}}, {"from", 0}, {"to", 1}, {"material", material}};
}

Scene sceneOf(std::vector<Json> objects) {
  Json j = test::baseScene();
  j["objects"] = objects;
  return test::parse(j);
}

std::vector<const Surface*> facing(const Scene& scene, Vec3 normal) {
  std::vector<const Surface*> out;
  for (const Surface& s : scene.surfaces)
    if (glm::dot(s.normal, normal) > 0.999) out.push_back(&s);
  return out;
}

TEST(CoplanarMerge, BoxesSideBySideShareTheirOuterFaces) {
  const Scene scene = sceneOf({{{"name", "pair"}, {"solids", {box(0, 0, 1, 1), box(1, 0, 2, 1)}}}});
  // Tops, bottoms, fronts and backs merge; the two faces between the boxes face apart and stay.
  EXPECT_EQ(scene.surfaces.size(), 12u - 4);
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  EXPECT_NEAR(tops[0]->area, 2, 1e-12);
  EXPECT_NE(tops[0]->face.find(" + "), std::string::npos);
  EXPECT_TRUE(tops[0]->holes.empty());
}

TEST(CoplanarMerge, TJunctionsSplitTheLongerEdge) {
  const Scene scene = sceneOf({{{"name", "three"}, {"solids", {box(0, 0, 2, 1), box(2, 0, 3, 0.5), box(2, 0.5, 3, 1)}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  EXPECT_NEAR(tops[0]->area, 3, 1e-12);
  // The junction point (2, 1, 0.5) is on the merged boundary? No: it is inside now; the outer
  // ring runs round all three tops.
  double ringArea = 0;
  const Ring3& r = tops[0]->outer;
  for (size_t i = 0; i < r.size(); ++i) ringArea += 0.5 * glm::cross(r[i], r[(i + 1) % r.size()]).y;
  EXPECT_NEAR(std::abs(ringArea), 3, 1e-12);
}

TEST(CoplanarMerge, ARingOfBoxesLeavesAHole) {
  const Scene scene = sceneOf({{{"name", "ring"},
                                {"solids", {box(0, 0, 3, 1), box(0, 2, 3, 3), box(0, 1, 1, 2), box(2, 1, 3, 2)}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  ASSERT_EQ(tops[0]->holes.size(), 1u);
  EXPECT_NEAR(tops[0]->area, 8, 1e-12);
}

TEST(CoplanarMerge, OnlyOneMaterialAndOneMovableObjectMerge) {
  const Scene materials = sceneOf({{{"name", "two"}, {"solids", {box(0, 0, 1, 1), box(1, 0, 2, 1, "lamp")}}}});
  EXPECT_EQ(facing(materials, {0, 1, 0}).size(), 2u);
  const Scene movable = sceneOf({{{"name", "a"}, {"solids", {box(0, 0, 1, 1)}}}, {{"name", "b"}, {"solids", {box(1, 0, 2, 1)}}}});
  EXPECT_EQ(facing(movable, {0, 1, 0}).size(), 2u);
  const Scene fixed = sceneOf({{{"name", "a"}, {"movable", false}, {"solids", {box(0, 0, 1, 1)}}},
                               {{"name", "b"}, {"movable", false}, {"solids", {box(1, 0, 2, 1)}}}});
  EXPECT_EQ(facing(fixed, {0, 1, 0}).size(), 1u);
}

TEST(CoplanarMerge, FacesTouchingAtACornerOnlyStayApart) {
  const Scene scene = sceneOf({{{"name", "diagonal"}, {"solids", {box(0, 0, 1, 1), box(1, 1, 2, 2)}}}});
  EXPECT_EQ(facing(scene, {0, 1, 0}).size(), 2u);
}

// Across the shipped scenes, no mesh vertex of one surface lies inside a boundary edge of
// another coplanar surface of the same material: no T-vertex where surfaces that could merge
// meet. (Surfaces of different movable objects are meant to move apart and are not compared.)
TEST(CoplanarMerge, ShippedScenesHaveNoTVerticesBetweenMergeableSurfaces) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const Vec3 size = scene.boundsMax - scene.boundsMin;
    const double tolerance = 1e-9 * std::max({size.x, size.y, size.z});
    // Group by material, owner (fixed objects share one) and plane.
    std::map<std::tuple<uint32_t, int64_t, int64_t, int64_t, int64_t, int64_t>, std::vector<size_t>> groups;
    for (size_t i = 0; i < scene.surfaces.size(); ++i) {
      const Surface& s = scene.surfaces[i];
      const int64_t owner = scene.objects[s.object].movable ? s.object : -1;
      auto q = [&](double v, double unit) { return static_cast<int64_t>(std::llround(v / unit)); };
      groups[{s.material, owner, q(s.normal.x, 1e-6), q(s.normal.y, 1e-6), q(s.normal.z, 1e-6), q(s.planeOffset(), 1e-6 * std::max({size.x, size.y, size.z}))}].push_back(i);
    }
    size_t tVertices = 0, compared = 0;
    for (const auto& [key, members] : groups) {
      if (members.size() < 2) continue;
      std::vector<SurfaceMesh> meshes;
      for (size_t m : members) meshes.push_back(meshSurface(scene.surfaces[m]));
      for (size_t a = 0; a < meshes.size(); ++a)
        for (size_t b = 0; b < meshes.size(); ++b) {
          if (a == b) continue;
          ++compared;
          const auto& rb = scene.surfaces[members[b]];
          std::vector<Ring3> rings{rb.outer};
          rings.insert(rings.end(), rb.holes.begin(), rb.holes.end());
          for (const Vec3& p : meshes[a].positions)
            for (const Ring3& ring : rings)
              for (size_t i = 0; i < ring.size(); ++i) {
                const Vec3 u = ring[i], w = ring[(i + 1) % ring.size()];
                const double t = glm::dot(p - u, w - u) / glm::dot(w - u, w - u);
                if (t > 1e-9 && t < 1 - 1e-9 && glm::length(p - (u + t * (w - u))) <= tolerance) ++tVertices;
              }
        }
    }
    EXPECT_EQ(tVertices, 0u) << compared << " pairs compared";
  }
}

}  // namespace
}  // namespace engine

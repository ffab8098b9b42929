#include "engine/display_mesh.h"

#include "engine/scene_loader.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace engine {
namespace {

// Triangles of every surface of every shipped scene cover exactly the surface's area, face
// the surface's front, and use every boundary point.
TEST(DisplayMesh, TrianglesTileEverySurface) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "furnace.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const DisplayMesh mesh = buildPlaceholderDisplay(scene);
    size_t points = 0;
    double surfaceArea = 0;
    for (const Surface& s : scene.surfaces) {
      points += s.outer.size();
      for (const Ring3& h : s.holes) points += h.size();
      surfaceArea += s.area;
    }
    ASSERT_EQ(mesh.positions.size(), points);
    double triangleArea = 0;
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
      const glm::dvec3 a{mesh.positions[mesh.triangles[t]]}, b{mesh.positions[mesh.triangles[t + 1]]},
          c{mesh.positions[mesh.triangles[t + 2]]};
      triangleArea += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    EXPECT_NEAR(triangleArea, surfaceArea, 1e-5 * surfaceArea);  // float positions
    double vertexArea = 0;
    for (float a : mesh.area) vertexArea += a;
    EXPECT_NEAR(vertexArea, surfaceArea, 1e-5 * surfaceArea);
  }
}

TEST(DisplayMesh, TrianglesFaceTheSurfaceFront) {
  const Scene scene = test::parse(test::baseScene());
  const DisplayMesh mesh = buildPlaceholderDisplay(scene);
  // Vertices are laid out surface by surface; map each triangle back through its first index.
  std::vector<uint32_t> surfaceOfVertex;
  for (uint32_t i = 0; i < scene.surfaces.size(); ++i) {
    size_t n = scene.surfaces[i].outer.size();
    for (const Ring3& h : scene.surfaces[i].holes) n += h.size();
    surfaceOfVertex.insert(surfaceOfVertex.end(), n, i);
  }
  for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.triangles[t]], b = mesh.positions[mesh.triangles[t + 1]],
                    c = mesh.positions[mesh.triangles[t + 2]];
    const glm::dvec3 n = scene.surfaces[surfaceOfVertex[mesh.triangles[t]]].normal;
    EXPECT_GT(glm::dot(glm::dvec3(glm::cross(b - a, c - a)), n), 0);
  }
}

TEST(DisplayMesh, PlaceholderShadingIsEmissionPlusReflectedAmbient) {
  const Scene scene = test::parse(test::baseScene());
  glm::dvec3 ambient{0};
  const DisplayMesh mesh = buildPlaceholderDisplay(scene, &ambient);
  EXPECT_GT(ambient.x, 0);
  // Lamp: emission 4 + 0.5 ambient; walls: 0.5 ambient.
  float brightest = 0, darkest = 1e9f;
  for (const glm::vec3& r : mesh.radiance) brightest = std::max(brightest, r.x), darkest = std::min(darkest, r.x);
  EXPECT_NEAR(brightest, 4 + 0.5 * ambient.x, 1e-5);
  EXPECT_NEAR(darkest, 0.5 * ambient.x, 1e-5);
}

TEST(DisplayMesh, EachElementEdgeOnce) {
  const Scene scene = test::parse(test::sceneWithSolid(
      {{"profile", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {"from", 0}, {"to", 1}, {"material", "white"}}));
  const DisplayMesh mesh = buildPlaceholderDisplay(scene);
  // 6 quads, each split into 2 triangles: 4 sides + 1 diagonal per face.
  EXPECT_EQ(mesh.triangleCount(), 12u);
  EXPECT_EQ(mesh.edges.size(), 2u * 6 * 5);
}

TEST(DisplayMesh, AutoExposureMapsTheLogAverageToTheKey) {
  DisplayMesh mesh;
  mesh.positions.assign(2, glm::vec3{0});
  mesh.radiance = {glm::vec3{2}, glm::vec3{2}};
  mesh.area = {1, 1};
  EXPECT_NEAR(autoExposure(mesh, 0.25) * (2 + 1e-4), 0.25, 1e-9);
  EXPECT_EQ(autoExposure(DisplayMesh{}), 1);
}

}  // namespace
}  // namespace engine

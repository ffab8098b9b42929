#include "engine/document/display_mesh.h"

#include "engine/document/scene_editor.h"
#include "engine/io/load_scene.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace engine {
namespace {

// Triangles of every surface of every shipped scene cover exactly the surface's area, face the
// surface's front, lie in its plane, and keep the surface's own points exactly.
TEST(DisplayMesh, TrianglesTileEverySurface) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "furnace.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const DisplayMesh mesh = displayMesh(meshScene(scene));
    ASSERT_EQ(mesh.surfaceVertexStart.size(), scene.surfaces.size() + 1);
    std::vector<double> areaOf(scene.surfaces.size(), 0);
    std::vector<uint32_t> surfaceOf(mesh.positions.size());
    for (uint32_t i = 0; i < scene.surfaces.size(); ++i) {
      const Surface& s = scene.surfaces[i];
      uint32_t v = mesh.surfaceVertexStart[i];
      for (uint32_t k = v; k < mesh.surfaceVertexStart[i + 1]; ++k) {
        surfaceOf[k] = i;
        EXPECT_NEAR(glm::dot(mesh.origin + glm::dvec3(mesh.positions[k]), s.normal), s.planeOffset(), 1e-4 * (1 + std::abs(s.planeOffset())));
      }
      for (const Vec3& p : s.outer) EXPECT_EQ(mesh.positions[v++], glm::vec3(p - mesh.origin));
      for (const Ring3& h : s.holes)
        for (const Vec3& p : h) EXPECT_EQ(mesh.positions[v++], glm::vec3(p - mesh.origin));
    }
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
      const glm::dvec3 a{mesh.positions[mesh.triangles[t]]}, b{mesh.positions[mesh.triangles[t + 1]]},
          c{mesh.positions[mesh.triangles[t + 2]]};
      const uint32_t surface = surfaceOf[mesh.triangles[t]];
      EXPECT_EQ(surfaceOf[mesh.triangles[t + 1]], surface);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      // Never backward; a boundary sliver (an edge passing a grid corner closely: thesis figure
      // 5.9 a) may have no area left in float positions.
      EXPECT_GE(glm::dot(n, scene.surfaces[surface].normal), 0);
      areaOf[surface] += 0.5 * glm::length(n);
    }
    for (uint32_t i = 0; i < scene.surfaces.size(); ++i)
      EXPECT_NEAR(areaOf[i], scene.surfaces[i].area, 1e-4 * scene.surfaces[i].area) << scene.surfaces[i].face;  // float positions
    double vertexArea = 0, surfaceArea = 0;
    for (float a : mesh.area) vertexArea += a;
    for (const Surface& s : scene.surfaces) surfaceArea += s.area;
    EXPECT_NEAR(vertexArea, surfaceArea, 1e-5 * surfaceArea);
  }
}

// No element is larger than its surface's patch size along the mesh axes: on an axis-aligned
// box every element edge is at most the patch size along each world axis.
TEST(DisplayMesh, ElementsAreNoLargerThanThePatchSize) {
  Json j = test::sceneWithSolid({{"profile", {{0, 0}, {3, 0}, {3, 1.2}, {0, 1.2}}}, {"from", 0}, {"to", 2}, {"material", "white"}});
  j["settings"]["patch_size"] = 0.4;
  const Scene scene = test::parse(j);
  const DisplayMesh mesh = displayMesh(meshScene(scene));
  for (size_t e = 0; e < mesh.edges.size(); e += 2) {
    const glm::vec3 d = mesh.positions[mesh.edges[e + 1]] - mesh.positions[mesh.edges[e]];
    EXPECT_LE(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}), 0.4f + 1e-6f);
  }
}

TEST(DisplayMesh, PlaceholderShadingIsEmissionPlusReflectedAmbient) {
  const Scene scene = test::parse(test::baseScene());
  DisplayMesh mesh = displayMesh(meshScene(scene));
  const glm::dvec3 ambient = shadeWithAmbient(scene, mesh);
  EXPECT_GT(ambient.x, 0);
  // Lamp: emission 4 + 0.5 ambient; walls: 0.5 ambient.
  float brightest = 0, darkest = 1e9f;
  for (const glm::vec3& r : mesh.radiance) brightest = std::max(brightest, r.x), darkest = std::min(darkest, r.x);
  EXPECT_NEAR(brightest, 4 + 0.5 * ambient.x, 1e-5);
  EXPECT_NEAR(darkest, 0.5 * ambient.x, 1e-5);
}

TEST(DisplayMesh, QuadsAreTwoTrianglesAndEachEdgeIsDrawnOnce) {
  const Scene scene = test::parse(test::sceneWithSolid(
      {{"profile", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {"from", 0}, {"to", 1}, {"material", "white"}}));
  const DisplayMesh mesh = displayMesh(meshScene(scene));
  // Patch size 0.5: each face of the unit cube is 2 x 2 quads with 12 edges.
  EXPECT_EQ(mesh.elements, 6u * 4);
  EXPECT_EQ(mesh.quads, 6u * 4);
  EXPECT_EQ(mesh.triangleCount(), 6u * 8);
  EXPECT_EQ(mesh.edges.size(), 2u * 6 * 12);
}

// The display's float positions are about the meshes' middle, so a room 900 km out keeps its
// detail: every vertex within the room's size of the origin, and back in the world to 1e-6.
TEST(DisplayMesh, PositionsAreAboutTheMiddleOfTheMeshes) {
  const Scene scene = loadScene(std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json");
  const MeshedScene meshed = meshScene(scene);
  const DisplayMesh mesh = displayMesh(meshed);
  EXPECT_NEAR(mesh.origin.x, 900000.5, 1e-9);
  EXPECT_NEAR(mesh.origin.z, 900000.5, 1e-9);
  size_t v = 0;
  for (const SurfaceMesh& s : meshed.surfaces)
    for (const Vec3& p : s.positions) {
      EXPECT_LE(glm::length(glm::dvec3(mesh.positions[v])), 1.0);
      EXPECT_LT(glm::length(mesh.origin + glm::dvec3(mesh.positions[v++]) - p), 1e-6);
    }
  EXPECT_EQ(v, mesh.positions.size());
  // A rebuild may keep an origin given, for carryRadiance.
  EXPECT_EQ(displayMesh(meshed, glm::dvec3{1, 2, 3}).positions[0], glm::vec3(meshed.surfaces[0].positions[0] - glm::dvec3{1, 2, 3}));
}

// A moved object's display follows it: made anew with the light carried over when a surface was
// meshed again (the floor, as the chair leaves it), by positions only (the chair's, nothing
// else's) when none was (the chair lifted further).
TEST(DisplayMesh, FollowsAMoveAnewOrByPositions) {
  const Scene loaded = loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  SceneEditor editor(loaded, meshScene(loaded));
  DisplayMesh mesh = displayMesh(editor.meshed());
  for (size_t v = 0; v < mesh.radiance.size(); ++v) mesh.radiance[v] = glm::vec3(static_cast<float>(v % 7));
  const uint32_t chair = *editor.findObject("chair");
  std::vector<uint8_t> ofChair(editor.scene().surfaces.size(), 0);
  for (uint32_t s : editor.surfacesOf(chair)) ofChair[s] = 1;
  ObjectPose pose = poseOf(editor.scene().objects[chair]);

  pose.position.y += 0.5;  // off the floor, whose footprint goes
  ASSERT_TRUE(editor.setPose(chair, pose));
  ASSERT_FALSE(editor.remeshed().empty());
  DisplayMesh before = mesh;
  EXPECT_TRUE(followMove(editor.meshed(), editor.surfacesOf(chair), true, mesh));
  EXPECT_EQ(mesh.origin, before.origin);
  std::vector<uint8_t> remeshed(ofChair.size(), 0);
  for (uint32_t s : editor.remeshed()) remeshed[s] = 1;
  for (uint32_t s = 0; s < ofChair.size(); ++s)
    if (!remeshed[s] && !ofChair[s])  // the same vertices, each with its light
      for (uint32_t v = mesh.surfaceVertexStart[s]; v < mesh.surfaceVertexStart[s + 1]; ++v) {
        EXPECT_EQ(mesh.positions[v], before.positions[v - mesh.surfaceVertexStart[s] + before.surfaceVertexStart[s]]);
        EXPECT_EQ(mesh.radiance[v], before.radiance[v - mesh.surfaceVertexStart[s] + before.surfaceVertexStart[s]]);
      }

  pose.position.y += 0.3;  // higher still: no footprint changes
  ASSERT_TRUE(editor.setPose(chair, pose));
  ASSERT_TRUE(editor.remeshed().empty());
  before = mesh;
  EXPECT_FALSE(followMove(editor.meshed(), editor.surfacesOf(chair), false, mesh));
  for (uint32_t s = 0; s < ofChair.size(); ++s)
    for (uint32_t v = mesh.surfaceVertexStart[s]; v < mesh.surfaceVertexStart[s + 1]; ++v) {
      if (ofChair[s]) EXPECT_NEAR(mesh.positions[v].y, before.positions[v].y + 0.3f, 1e-5);
      else EXPECT_EQ(mesh.positions[v], before.positions[v]);
    }
  EXPECT_EQ(mesh.radiance, before.radiance);
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

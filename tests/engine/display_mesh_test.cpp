#include "engine/document/display_mesh.h"

#include "engine/document/scene_editor.h"
#include "engine/io/load_scene.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <random>

namespace engine {
namespace {

// Triangles of every surface of every shipped scene cover exactly the surface's area, face the
// surface's front, lie in its plane, and keep the surface's own points exactly; each surface's
// display names its object.
TEST(DisplayMesh, TrianglesTileEverySurface) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "furnace.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const DisplayMesh mesh = displayMesh(scene, meshScene(scene));
    ASSERT_EQ(mesh.surfaces.size(), scene.surfaces.size());
    double vertexArea = 0, surfaceArea = 0;
    for (uint32_t i = 0; i < scene.surfaces.size(); ++i) {
      const Surface& s = scene.surfaces[i];
      const SurfaceDisplay& display = mesh.surfaces[i];
      EXPECT_EQ(display.object, s.object);
      for (const glm::vec3& p : display.positions)
        EXPECT_NEAR(glm::dot(mesh.origin + glm::dvec3(p), s.normal), s.planeOffset(), 1e-4 * (1 + std::abs(s.planeOffset())));
      size_t v = 0;
      for (const Vec3& p : s.outer) EXPECT_EQ(display.positions[v++], glm::vec3(p - mesh.origin));
      for (const Ring3& h : s.holes)
        for (const Vec3& p : h) EXPECT_EQ(display.positions[v++], glm::vec3(p - mesh.origin));
      double area = 0;
      for (size_t t = 0; t < display.triangles.size(); t += 3) {
        const glm::dvec3 a{display.positions.at(display.triangles[t])}, b{display.positions.at(display.triangles[t + 1])},
            c{display.positions.at(display.triangles[t + 2])};
        const glm::dvec3 n = glm::cross(b - a, c - a);
        // Never backward; a boundary sliver (an edge passing a grid corner closely: thesis figure
        // 5.9 a) may have no area left in float positions.
        EXPECT_GE(glm::dot(n, s.normal), 0);
        area += 0.5 * glm::length(n);
      }
      EXPECT_NEAR(area, s.area, 1e-4 * s.area) << s.face;  // float positions
      for (float a : display.area) vertexArea += a;
      surfaceArea += s.area;
    }
    EXPECT_NEAR(vertexArea, surfaceArea, 1e-5 * surfaceArea);
  }
}

// Every surface's outline (the coarsest level of detail) tiles what its elements tile, faces the
// surface's front, uses only the surface's own points, and its border is the polygon's rings edge
// for edge, on which the elements' boundary points lie: drawing a surface as its outline leaves
// no gap its elements would not.
TEST(DisplayMesh, TheOutlineTilesTheSurfaceWithItsOwnPoints) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const DisplayMesh mesh = displayMesh(scene, meshScene(scene));
    for (uint32_t i = 0; i < scene.surfaces.size(); ++i) {
      const Surface& s = scene.surfaces[i];
      const SurfaceDisplay& display = mesh.surfaces[i];
      SCOPED_TRACE(s.face);
      ASSERT_FALSE(display.outline.empty());
      std::vector<std::pair<uint32_t, uint32_t>> ringEdges;
      uint32_t first = 0;
      for (size_t r = 0; r <= s.holes.size(); ++r) {
        const auto n = static_cast<uint32_t>(r == 0 ? s.outer.size() : s.holes[r - 1].size());
        for (uint32_t k = 0; k < n; ++k) ringEdges.push_back(std::minmax(first + k, first + (k + 1) % n));
        first += n;
      }
      double area = 0;
      std::map<std::pair<uint32_t, uint32_t>, int> edgeUses;
      for (size_t t = 0; t < display.outline.size(); t += 3) {
        for (size_t k = 0; k < 3; ++k) {
          EXPECT_LT(display.outline[t + k], first);  // the surface's own points only
          ++edgeUses[std::minmax(display.outline[t + k], display.outline[t + (k + 1) % 3])];
        }
        const glm::dvec3 a{display.positions[display.outline[t]]}, b{display.positions[display.outline[t + 1]]},
            c{display.positions[display.outline[t + 2]]};
        const glm::dvec3 n = glm::cross(b - a, c - a);
        EXPECT_GE(glm::dot(n, s.normal), 0);
        area += 0.5 * glm::length(n);
      }
      EXPECT_NEAR(area, s.area, 1e-4 * s.area);
      std::vector<std::pair<uint32_t, uint32_t>> border;
      for (const auto& [edge, uses] : edgeUses)
        if (uses == 1) border.push_back(edge);
      std::sort(ringEdges.begin(), ringEdges.end());
      EXPECT_EQ(border, ringEdges);
    }
  }
}

// After a move the floor's footprints are holes inserted into its adaptive mesh, whose points
// come after the vertices made before them: the outline still finds them and tiles the floor.
TEST(DisplayMesh, TheOutlineFollowsFootprintsMovedByHoleInsertion) {
  const Scene loaded = loadScene(std::string(WALKRAD_ASSETS) + "/box-on-floor.json");
  SceneEditor editor(loaded, meshScene(loaded));
  const uint32_t box = *editor.findObject("box");
  ObjectPose pose = poseOf(editor.scene().objects[box]);
  pose.position += Vec3{0.3, 0, 0.1};
  ASSERT_TRUE(editor.setPose(box, pose));
  const std::vector<uint32_t> remeshed = editor.remeshed();
  ASSERT_FALSE(remeshed.empty());
  for (uint32_t s : remeshed) {
    if (editor.scene().surfaces[s].object == box) continue;
    const SurfaceMesh& mesh = editor.meshed().surfaces[s];
    ASSERT_NE(mesh.mesh.vertices[mesh.polygon.outer.size()], mesh.polygon.holes.back().front());  // not in triangulate's order
    const SurfaceDisplay display = surfaceDisplay(mesh, 0, glm::dmat4{1}, surfaceOutline(mesh));
    ASSERT_FALSE(display.outline.empty());
    double area = 0;
    for (size_t t = 0; t < display.outline.size(); t += 3) {
      const glm::dvec3 a{display.positions[display.outline[t]]}, b{display.positions[display.outline[t + 1]]},
          c{display.positions[display.outline[t + 2]]};
      area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    EXPECT_NEAR(area, editor.scene().surfaces[s].area, 1e-5 * editor.scene().surfaces[s].area);
  }
}

// The extent is the diagonal of the surface's bounds: a 2 x 1 wall's is sqrt(5).
TEST(DisplayMesh, TheExtentIsTheDiagonalOfTheBounds) {
  const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  const DisplayMesh mesh = displayMesh(scene, meshScene(scene));
  for (uint32_t i = 0; i < scene.surfaces.size(); ++i) {
    glm::dvec3 low{INFINITY}, high{-INFINITY};
    for (const Vec3& p : scene.surfaces[i].outer) low = glm::min(low, p), high = glm::max(high, p);
    EXPECT_NEAR(mesh.surfaces[i].extent, glm::length(high - low), 1e-5 * glm::length(high - low));
  }
}

// No element is larger than its surface's patch size along the mesh axes: on an axis-aligned
// box every element edge is at most the patch size along each world axis.
TEST(DisplayMesh, ElementsAreNoLargerThanThePatchSize) {
  Json j = test::sceneWithSolid({{"profile", {{0, 0}, {3, 0}, {3, 1.2}, {0, 1.2}}}, {"from", 0}, {"to", 2}, {"material", "white"}});
  j["settings"]["patch_size"] = 0.4;
  const Scene scene = test::parse(j);
  const DisplayMesh mesh = displayMesh(scene, meshScene(scene));
  for (const SurfaceDisplay& s : mesh.surfaces)
    for (size_t e = 0; e < s.edges.size(); e += 2) {
      const glm::vec3 d = s.positions[s.edges[e + 1]] - s.positions[s.edges[e]];
      EXPECT_LE(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}), 0.4f + 1e-6f);
    }
}

TEST(DisplayMesh, PlaceholderShadingIsEmissionPlusReflectedAmbient) {
  const Scene scene = test::parse(test::baseScene());
  DisplayMesh mesh = displayMesh(scene, meshScene(scene));
  const glm::dvec3 ambient = shadeWithAmbient(scene, mesh);
  EXPECT_GT(ambient.x, 0);
  // Lamp: emission 4 + 0.5 ambient; walls: 0.5 ambient.
  float brightest = 0, darkest = 1e9f;
  for (const SurfaceDisplay& s : mesh.surfaces)
    for (const glm::vec3& r : s.radiance) brightest = std::max(brightest, r.x), darkest = std::min(darkest, r.x);
  EXPECT_NEAR(brightest, 4 + 0.5 * ambient.x, 1e-5);
  EXPECT_NEAR(darkest, 0.5 * ambient.x, 1e-5);
}

TEST(DisplayMesh, QuadsAreTwoTrianglesAndEachEdgeIsDrawnOnce) {
  const Scene scene = test::parse(test::sceneWithSolid(
      {{"profile", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {"from", 0}, {"to", 1}, {"material", "white"}}));
  const DisplayMesh mesh = displayMesh(scene, meshScene(scene));
  // Patch size 0.5: each face of the unit cube is 2 x 2 quads with 12 edges.
  EXPECT_EQ(mesh.elements, 6u * 4);
  EXPECT_EQ(mesh.quads, 6u * 4);
  EXPECT_EQ(mesh.triangleCount(), 6u * 8);
  EXPECT_EQ(mesh.vertices, 6u * 9);
  for (const SurfaceDisplay& s : mesh.surfaces) EXPECT_EQ(s.edges.size(), 2u * 12);
}

// The display's float positions are about the meshes' middle, so a room 900 km out keeps its
// detail: every vertex within the room's size of the origin, and back in the world to 1e-6.
TEST(DisplayMesh, PositionsAreAboutTheMiddleOfTheMeshes) {
  const Scene scene = loadScene(std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json");
  const MeshedScene meshed = meshScene(scene);
  const DisplayMesh mesh = displayMesh(scene, meshed);
  EXPECT_NEAR(mesh.origin.x, 900000.5, 1e-9);
  EXPECT_NEAR(mesh.origin.z, 900000.5, 1e-9);
  for (size_t s = 0; s < meshed.surfaces.size(); ++s) {
    ASSERT_EQ(mesh.surfaces[s].positions.size(), meshed.surfaces[s].positions.size());
    for (size_t v = 0; v < meshed.surfaces[s].positions.size(); ++v) {
      const glm::vec3& p = mesh.surfaces[s].positions[v];
      EXPECT_LE(glm::length(glm::dvec3(p)), 1.0);
      EXPECT_LT(glm::length(mesh.origin + glm::dvec3(p) - meshed.surfaces[s].positions[v]), 1e-6);
    }
  }
  // A display may be made about an origin given.
  EXPECT_EQ(displayMesh(scene, meshed, glm::dvec3{1, 2, 3}).surfaces[0].positions[0],
            glm::vec3(meshed.surfaces[0].positions[0] - glm::dvec3{1, 2, 3}));
}

// Two displays of one scene are the same, surface by surface, but for the radiance.
void expectSameGeometry(const DisplayMesh& a, const DisplayMesh& b) {
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.elements, b.elements);
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.vertices, b.vertices);
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (size_t s = 0; s < a.surfaces.size(); ++s) {
    SCOPED_TRACE(s);
    EXPECT_EQ(a.surfaces[s].object, b.surfaces[s].object);
    EXPECT_EQ(a.surfaces[s].positions, b.surfaces[s].positions);
    EXPECT_EQ(a.surfaces[s].area, b.surfaces[s].area);
    EXPECT_EQ(a.surfaces[s].triangles, b.surfaces[s].triangles);
    EXPECT_EQ(a.surfaces[s].edges, b.surfaces[s].edges);
    EXPECT_EQ(a.surfaces[s].elements, b.surfaces[s].elements);
    EXPECT_EQ(a.surfaces[s].quads, b.surfaces[s].quads);
    EXPECT_EQ(a.surfaces[s].radiance.size(), b.surfaces[s].positions.size());
  }
}

// Random moves of the office's movable objects, each followed surface by surface (the moved
// object's surfaces, and those meshed again around changed footprints): the display is then the
// one made anew from the edited meshes, and only the surfaces followed changed.
TEST(DisplayMesh, FollowingMovesSurfaceBySurfaceGivesTheDisplayMadeAnew) {
  const Scene loaded = loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  SceneEditor editor(loaded, meshScene(loaded));
  DisplayMesh mesh = displayMesh(editor.scene(), editor.meshed());
  std::vector<uint32_t> movable;
  for (uint32_t o = 0; o < editor.scene().objects.size(); ++o)
    if (editor.scene().objects[o].movable) movable.push_back(o);
  ASSERT_GE(movable.size(), 2u);

  std::mt19937 random(5);
  std::uniform_real_distribution<double> step(-0.4, 0.4), unit(0, 1);
  size_t remeshedMoves = 0;
  for (int move = 0; move < 12; ++move) {
    SCOPED_TRACE(move);
    const uint32_t object = movable[static_cast<size_t>(move) % movable.size()];
    // Along the floor, now and then lifted off it (and back: its footprint goes and comes).
    ObjectPose pose = poseOf(editor.scene().objects[object]);
    pose.position += Vec3{step(random), 0, step(random)};
    pose.position.y = loaded.objects[object].position.y + (unit(random) < 0.3 ? 0.2 * unit(random) : 0.0);
    pose.rotateYDeg += unit(random) < 0.5 ? 15 : 0;
    const DisplayMesh before = mesh;
    ASSERT_TRUE(editor.setPose(object, pose));
    remeshedMoves += !editor.remeshed().empty();
    std::vector<uint32_t> changed;
    for (const EditedSurface& e : editor.takeEdited()) {
      const uint32_t owner = editor.scene().surfaces[e.surface].object;
      replaceSurface(mesh, e.surface, surfaceDisplay(editor.meshed().surfaces[e.surface], owner, displayFromWorld(mesh), surfaceOutline(editor.meshed().surfaces[e.surface])));
      changed.push_back(e.surface);
    }
    expectSameGeometry(mesh, displayMesh(editor.scene(), editor.meshed(), mesh.origin));
    for (uint32_t s = 0; s < mesh.surfaces.size(); ++s)
      if (!std::binary_search(changed.begin(), changed.end(), s)) {
        EXPECT_EQ(mesh.surfaces[s].positions, before.surfaces[s].positions);
        EXPECT_EQ(mesh.surfaces[s].radiance, before.surfaces[s].radiance);
      }
  }
  EXPECT_GT(remeshedMoves, 3u);  // footprints changed on the floor often enough
}

// The lighting snapshots' radiance (one value per display vertex, surface after surface) goes
// onto the surfaces in order; a snapshot of other meshes (another vertex count) is refused.
TEST(DisplayMesh, FlatRadianceGoesOntoTheSurfacesInOrder) {
  const Scene scene = test::parse(test::baseScene());
  DisplayMesh mesh = displayMesh(scene, meshScene(scene));
  std::vector<glm::vec3> flat(mesh.vertices);
  for (size_t v = 0; v < flat.size(); ++v) flat[v] = glm::vec3(static_cast<float>(v));
  ASSERT_TRUE(setRadiance(mesh, flat));
  size_t v = 0;
  for (const SurfaceDisplay& s : mesh.surfaces)
    for (const glm::vec3& r : s.radiance) EXPECT_EQ(r, flat[v++]);
  flat.emplace_back(-1.0f);
  EXPECT_FALSE(setRadiance(mesh, flat));
  EXPECT_EQ(mesh.surfaces.back().radiance.back(), flat[flat.size() - 2]);
}

TEST(DisplayMesh, AutoExposureMapsTheLogAverageToTheKey) {
  DisplayMesh mesh;
  SurfaceDisplay& s = mesh.surfaces.emplace_back();
  s.positions.assign(2, glm::vec3{0});
  s.radiance = {glm::vec3{2}, glm::vec3{2}};
  s.area = {1, 1};
  EXPECT_NEAR(autoExposure(mesh, 0.25) * (2 + 1e-4), 0.25, 1e-9);
  EXPECT_EQ(autoExposure(DisplayMesh{}), 1);
}

}  // namespace
}  // namespace engine

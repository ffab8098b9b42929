// The renderer's chunks without GL: how a display mesh is cut, and which boxes are left out of a
// view.
#include "app/gl/display_chunks.h"

#include "engine/document/display_mesh.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace app {
namespace {

// Every surface in exactly one chunk, every chunk of one object, in object order, and each
// within `maxVertices` unless it is one surface.
void expectWellCut(const engine::DisplayMesh& mesh, const std::vector<ChunkPlan>& chunks, size_t maxVertices) {
  std::vector<int> seen(mesh.surfaces.size(), 0);
  for (size_t c = 0; c < chunks.size(); ++c) {
    SCOPED_TRACE(c);
    ASSERT_FALSE(chunks[c].surfaces.empty());
    if (c > 0) {
      EXPECT_GE(chunks[c].object, chunks[c - 1].object);
    }
    size_t vertices = 0;
    for (uint32_t s : chunks[c].surfaces) {
      ++seen.at(s);
      EXPECT_EQ(mesh.surfaces[s].object, chunks[c].object);
      vertices += mesh.surfaces[s].positions.size();
    }
    if (chunks[c].surfaces.size() > 1) {
      EXPECT_LE(vertices, maxVertices);
    }
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

// The kitchen cut finely (its larger objects into many chunks) and at the renderer's size (one
// chunk per object: none of its objects has 65,536 vertices).
TEST(DisplayChunks, NeverSplitASurfaceNorMixObjects) {
  const engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/kitchen.json");
  const engine::DisplayMesh mesh = engine::displayMesh(scene, engine::meshScene(scene));
  const std::vector<ChunkPlan> fine = planChunks(mesh, 300);
  expectWellCut(mesh, fine, 300);
  EXPECT_GT(fine.size(), 2 * scene.objects.size());

  const std::vector<ChunkPlan> whole = planChunks(mesh);
  expectWellCut(mesh, whole, kChunkVertices);
  size_t objectsWithSurfaces = 0;
  for (uint32_t o = 0; o < scene.objects.size(); ++o)
    objectsWithSurfaces += std::any_of(scene.surfaces.begin(), scene.surfaces.end(), [&](const engine::Surface& s) { return s.object == o; });
  EXPECT_EQ(whole.size(), objectsWithSurfaces);
}

// One object of 64 x 64 unit squares on a floor, listed in random order (a glTF model lists its
// triangles as the modeller made them): chunks of 16 squares follow the Morton curve, so they are
// compact, where cutting in list order would give chunks spread over the whole floor.
TEST(DisplayChunks, ALargeObjectIsCutIntoCompactRegions) {
  constexpr int kSide = 64;
  std::vector<int> order(kSide * kSide);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  engine::DisplayMesh mesh;
  for (int cell : order) {
    engine::SurfaceDisplay& s = mesh.surfaces.emplace_back();
    const auto x = static_cast<float>(cell % kSide), z = static_cast<float>(cell / kSide);
    s.positions = {{x, 0, z}, {x + 1, 0, z}, {x + 1, 0, z + 1}, {x, 0, z + 1}};
  }
  const std::vector<ChunkPlan> chunks = planChunks(mesh, 64);
  expectWellCut(mesh, chunks, 64);
  ASSERT_EQ(chunks.size(), size_t{kSide * kSide / 16});

  // A chunk of 16 squares covers 16 in its box at best (4 x 4), and these do; one straddling a
  // jump of the curve would cover more. In list order, a box is nearly the whole floor (4,096).
  double boxArea = 0;
  for (const ChunkPlan& chunk : chunks) {
    glm::vec3 low{INFINITY}, high{-INFINITY};
    for (uint32_t s : chunk.surfaces)
      for (const glm::vec3& p : mesh.surfaces[s].positions) low = glm::min(low, p), high = glm::max(high, p);
    boxArea += static_cast<double>((high.x - low.x) * (high.z - low.z)) / static_cast<double>(chunks.size());
  }
  EXPECT_LE(boxArea, 24);
}

// A camera at the origin looking down -z: a box ahead is in view, one behind it, beside it or
// beyond the far plane is not, and one the camera stands in is.
TEST(DisplayChunks, BoxesWhollyOutsideTheViewAreLeftOut) {
  const glm::mat4 clipFromDisplay =
      glm::perspective(glm::radians(60.0f), 4.0f / 3.0f, 0.1f, 100.0f) * glm::lookAt(glm::vec3{0}, glm::vec3{0, 0, -1}, glm::vec3{0, 1, 0});
  EXPECT_FALSE(outsideView(clipFromDisplay, {-1, -1, -6}, {1, 1, -4}));
  EXPECT_TRUE(outsideView(clipFromDisplay, {-1, -1, 4}, {1, 1, 6}));
  EXPECT_TRUE(outsideView(clipFromDisplay, {20, -1, -6}, {22, 1, -4}));
  EXPECT_TRUE(outsideView(clipFromDisplay, {-1, -1, -300}, {1, 1, -200}));
  EXPECT_FALSE(outsideView(clipFromDisplay, {-1, -1, -1}, {1, 1, 1}));
  // The box through a transform of its own: one behind the camera moved ahead of it.
  EXPECT_FALSE(outsideView(clipFromDisplay * glm::translate(glm::mat4{1}, glm::vec3{0, 0, -10}), {-1, -1, 4}, {1, 1, 6}));
}

}  // namespace
}  // namespace app

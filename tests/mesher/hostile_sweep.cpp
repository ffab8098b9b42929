// The hostile sweep of docs/BENCHMARKS.md: random hostile polygons (hostile_polygons.h) meshed
// within a work limit; reports how many were meshed and refused, the most quadrants made for an
// element output, the slowest, and every invalid mesh (as a polygon case for `walkrad mesh`).
//   mesher_hostile SEED COUNT [MAX_QUADRANTS]
#include "mesher/mesh_check.h"
#include "mesher/mesher.h"
#include "tests/mesher/hostile_polygons.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char** argv) {
  using namespace mesher;
  unsigned seed = 0;
  size_t count = 0, maxQuadrants = size_t{1} << 16;
  try {
    if (argc < 3 || argc > 4) throw std::invalid_argument("arguments");
    seed = static_cast<unsigned>(std::stoul(argv[1]));
    count = std::stoul(argv[2]);
    if (argc == 4) maxQuadrants = std::stoul(argv[3]);
  } catch (const std::exception&) {
    std::fprintf(stderr, "usage: mesher_hostile SEED COUNT [MAX_QUADRANTS]\n");
    return 2;
  }
  std::mt19937 random(seed);
  Mesher mesher;
  size_t meshed = 0, refused = 0, invalid = 0, elements = 0, quadrants = 0;
  double worstRatio = 0;
  std::string worstCase;
  std::vector<std::pair<double, std::string>> slowest;  // the five slowest, slowest first
  for (size_t i = 0; i < count; ++i) {
    const test::HostilePolygon hostile = test::randomHostilePolygon(random);
    const auto start = std::chrono::steady_clock::now();
    Mesh mesh;
    bool ok = true;
    try {
      mesher.mesh(hostile.polygon, {hostile.patchSize, maxQuadrants}, mesh);
    } catch (const MeshRefused&) {
      ok = false;
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    quadrants += mesher.quadrantsMade();
    if (slowest.size() < 5 || ms > slowest.back().first) {
      char work[96];
      std::snprintf(work, sizeof work, " (%zu quadrants, %s): ", mesher.quadrantsMade(), ok ? "meshed" : "refused");
      slowest.emplace_back(ms, hostile.kind + work + test::polygonCaseJson(hostile));
      std::sort(slowest.begin(), slowest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      if (slowest.size() > 5) slowest.pop_back();
    }
    if (!ok) {
      ++refused;
      continue;
    }
    ++meshed;
    elements += mesh.elements.size();
    const double ratio = static_cast<double>(mesher.quadrantsMade()) / static_cast<double>(mesh.elements.size());
    if (ratio > worstRatio) worstRatio = ratio, worstCase = hostile.kind + " " + test::polygonCaseJson(hostile);
    const MeshCheck c = checkMesh(hostile.polygon, mesh);
    if (!valid(c)) {
      ++invalid;
      std::printf("invalid (%zu T-vertices, %zu not convex, %zu unmatched, %zu repeated, area %.17g of %.17g): %s %s\n", c.tVertices,
                  c.notCounterClockwiseOrConvex, c.unmatchedInnerEdges, c.repeatedEdges, c.elementArea, c.polygonArea,
                  hostile.kind.c_str(), test::polygonCaseJson(hostile).c_str());
    }
  }
  std::printf("%zu meshed (%zu elements), %zu refused over %zu quadrants, %zu invalid meshes; %zu quadrants made in all\n", meshed,
              elements, refused, maxQuadrants, invalid, quadrants);
  std::printf("most quadrants an element: %.1f, %s\n", worstRatio, worstCase.c_str());
  for (const auto& [ms, text] : slowest) std::printf("slow: %.1f ms, %s\n", ms, text.c_str());
  return invalid > 0;
}

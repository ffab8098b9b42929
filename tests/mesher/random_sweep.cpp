// The broad sweep of docs/BENCHMARKS.md: the mesher tests' two kinds of random polygons, 1,000 of
// each per seed, over more seeds than the tests mesh. Prints each polygon with an element below
// the angle bound or an invalid mesh (the independent check), then the totals.
//   mesher_sweep FIRST_SEED SEEDS
#include "mesher/mesh_check.h"
#include "mesher/mesher.h"
#include "tests/mesher/random_polygons.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
  using namespace mesher;
  unsigned first = 0, seeds = 0;
  try {
    if (argc != 3) throw std::invalid_argument("two arguments");
    first = static_cast<unsigned>(std::stoul(argv[1]));
    seeds = static_cast<unsigned>(std::stoul(argv[2]));
  } catch (const std::exception&) {
    std::fprintf(stderr, "usage: mesher_sweep FIRST_SEED SEEDS\n");
    return 2;
  }
  Mesher mesher;
  size_t below = 0, elements = 0, invalid = 0;
  test::forEachSweepPolygon(first, seeds, [&](const test::RandomTestPolygon& random, unsigned seed, bool concave, int trial) {
    const Mesh mesh = mesher.mesh(random.polygon, {random.patchSize});
    const MeshCheck c = checkMesh(random.polygon, mesh);
    const bool bad = !valid(c);
    if (c.belowAngleBound || bad)
      std::printf("seed %u %s trial %d: %zu below the bound%s\n", seed, concave ? "concave" : "with holes", trial, c.belowAngleBound,
                  bad ? ", invalid" : "");
    below += c.belowAngleBound, elements += mesh.elements.size(), invalid += bad;
  });
  std::printf("%zu of %zu elements below the bound, %zu invalid meshes\n", below, elements, invalid);
}

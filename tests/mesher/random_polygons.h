// Random valid polygons with holes for the mesher's property tests.
#pragma once

#include "mesher/triangulate.h"

#include <random>

namespace mesher::test {

// A convex outer ring of 3-11 sides around a random centre (offset up to `offset` from the
// origin), with 0-9 disjoint convex holes on a grid inside its largest inscribed circle; hole
// winding alternates with `trial`.
PolygonWithHoles randomPolygonWithHoles(std::mt19937& random, int trial, double offset = 500);

// A concave, star-shaped outer ring of 6-40 points (radii from 30% to 100%), with up to three
// small holes near its centre. `offset` moves it from the origin.
PolygonWithHoles randomStarPolygon(std::mt19937& random, int trial, double offset = 500);

// The mesher's random test polygons: trial `trial` of one kind, convex with holes or concave (a
// star, every second one 1e5 from the origin), with the patch size it is meshed at.
struct RandomTestPolygon {
  PolygonWithHoles polygon;
  double patchSize = 0;
};
RandomTestPolygon randomTestPolygon(std::mt19937& random, bool concave, int trial);
// The one of them that trial `trial` of a generator seeded `seed` makes.
RandomTestPolygon randomTestPolygon(unsigned seed, bool concave, int trial);
// Calls visit(polygon, seed, concave, trial) for the 1,000 of each kind of each seed from
// `first` on, the generator of a seed and kind seeded seed * 2 + concave (the broad sweep).
template <typename Visit>
void forEachSweepPolygon(unsigned first, unsigned seeds, Visit visit) {
  for (unsigned seed = first; seed < first + seeds; ++seed)
    for (int concave = 0; concave < 2; ++concave) {
      std::mt19937 random(seed * 2 + static_cast<unsigned>(concave));
      for (int trial = 0; trial < 1000; ++trial) visit(randomTestPolygon(random, concave != 0, trial), seed, concave != 0, trial);
    }
}

}  // namespace mesher::test

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

}  // namespace mesher::test

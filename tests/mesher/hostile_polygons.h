// Polygons a stranger could send the mesher: needles and slivers, vertices a hair apart, combs of
// thin or slanted teeth, huge and tiny coordinates and patch sizes. The mesher's limits
// (mesher.h) are tested on them: every one is meshed validly or refused, with work bounded.
#pragma once

#include "mesher/triangulate.h"

#include <random>
#include <string>

namespace mesher::test {

struct HostilePolygon {
  PolygonWithHoles polygon;
  double patchSize = 1;
  std::string kind;  // which family made it, for reports
};

// A comb standing on the base [0, teeth * pitch] x [0, 1]: `teeth` teeth of width `width`, one
// every `pitch`, `height` tall, their tops moved `slant` along x. Counter-clockwise.
Ring2 comb(int teeth, double pitch, double width, double height, double slant = 0);

// A regular polygon of `sides` sides (counter-clockwise).
Ring2 regularPolygon(Vec2 center, double radius, int sides, double turnDeg = 0);

// One of the families above, drawn at random: a valid polygon (simple rings with area, holes
// strictly inside), up to 64 vertices, with a patch size from ten times its extent down to a
// hundred-thousandth of it.
HostilePolygon randomHostilePolygon(std::mt19937& random);

// Whether a polygon is one the mesher takes (what `walkrad mesh` checks a polygon case for):
// finite points, simple rings with area, holes strictly inside the outer ring and apart.
bool validPolygon(const PolygonWithHoles& polygon);

// The polygon as a polygon case for `walkrad mesh` (spec/cli.md), every digit kept.
std::string polygonCaseJson(const HostilePolygon& polygon);

}  // namespace mesher::test

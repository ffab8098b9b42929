// Surfaces of the shipped scenes that the mesher's tests take as they are (plane coordinates).
#pragma once

#include "mesher/triangulate.h"

namespace mesher::test {

// The office bookcase's side, in metres: a 1 cm upright (x 4.99 to 5) with shelves 2 cm thick
// reaching to x 4.7. The upright's outer edge is the tree's root border, and a grid line runs
// 0.6 mm from its inner one.
inline PolygonWithHoles bookcaseSide() {
  return {{{5.0, 2.0}, {4.7, 2.0}, {4.7, 1.98}, {4.99, 1.98}, {4.99, 1.51}, {4.7, 1.51}, {4.7, 1.49}, {4.99, 1.49},
           {4.99, 1.04}, {4.7, 1.04}, {4.7, 1.02}, {4.99, 1.02}, {4.99, 0.57}, {4.7, 0.57}, {4.7, 0.55}, {4.99, 0.55},
           {4.99, 0.08}, {4.7, 0.08}, {4.7, 0.0}, {5.0, 0.0}, {5.0, 0.08}, {5.0, 1.98}},
          {}};
}

}  // namespace mesher::test

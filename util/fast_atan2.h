// atan2 for hot loops that choose by angles or sum many of them: the polynomial of Abramowitz and
// Stegun 4.4.49, error below 2e-8 radians, several times faster than libm's. The mesher's choice
// of pieces and the radiosity solver's contour integrals use it.
#pragma once

#include <cmath>
#include <numbers>

namespace util {

// The polynomial's coefficients of z^3, z^5, ... z^17 (atan z = z (1 + z^2 (c0 + z^2 (c1 + ...)))),
// for vector versions that must give the same bits.
inline constexpr double kFastAtanCoefficients[8] = {-0.3333314528, 0.1999355085, -0.1420889944, 0.1065626393,
                                                    -0.0752896400, 0.0429096138, -0.0161657367, 0.0028662257};

// atan2(y, x) for y >= 0, in [0, pi]; 0 for (0, 0).
inline double fastAtan2(double y, double x) {
  const double ax = std::abs(x);
  if (y == 0 && ax == 0) return 0;
  const bool steep = y > ax;
  const double z = steep ? ax / y : y / ax, z2 = z * z;
  double inner = z2 * kFastAtanCoefficients[7];
  for (int k = 6; k >= 0; --k) inner = z2 * (kFastAtanCoefficients[k] + inner);
  const double atanZ = z * (1 + inner);
  const double a = steep ? std::numbers::pi / 2 - atanZ : atanZ;
  return x < 0 ? std::numbers::pi - a : a;
}

}  // namespace util

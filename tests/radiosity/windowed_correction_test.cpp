// The geometry of corrections in a window (radiosity/windowed_correction.h): a sphere's window
// holds every pixel a polygon inside it draws and every target read inside it, whatever the
// viewpoint; a patch whose patch sphere misses the window has no element in it.
#include "radiosity/windowed_correction.h"

#include "pxpl5/hemisphere.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace radiosity {
namespace {

TEST(RadiosityWindow, ASpheresWindowHoldsThePixelsOfWhatIsInside) {
  constexpr int kResolution = 128;
  pxpl5::HemisphereRenderer renderer({kResolution, pxpl5::Projection::kHemisphere, 1});
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto unit = [&] {
    glm::dvec3 v;
    do v = {u(random), u(random), u(random)};
    while (glm::length(v) > 1 || glm::length(v) < 0.1);
    return glm::normalize(v);
  };
  int drawn = 0, empty = 0, whole = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const glm::dvec3 eye{u(random), u(random), u(random)}, up = unit();
    // A triangle inside a sphere at 0.3 to 3 from the eye, some nearly holding it.
    const glm::dvec3 centre = eye + unit() * (0.3 + 2.7 * (u(random) + 1) / 2);
    const double radius = (0.02 + 0.5 * (u(random) + 1) / 2) * glm::length(centre - eye) * (trial % 10 == 0 ? 2 : 1);
    std::vector<glm::vec3> corners;
    for (int k = 0; k < 3; ++k) corners.emplace_back(centre + unit() * radius * 0.999);
    const std::vector<pxpl5::Polygon> polygons{{0, 3, 0}};
    const HemisphereAxes axes = hemisphereAxes(glm::vec3(up));
    const pxpl5::PixelRect window = sphereWindow(axes, eye, kResolution, centre, radius);
    const pxpl5::HemisphereFrame& frame = renderer.render({glm::vec3(eye), glm::vec3(up), {}}, {corners, polygons});
    whole += pixelsOf(window) == int64_t{kResolution} * kResolution;
    empty += window.empty();
    for (int y = 0; y < kResolution; ++y)
      for (int x = 0; x < kResolution; ++x) {
        if (frame.items[static_cast<size_t>(y) * frame.stride + x] == pxpl5::kNoValue) continue;
        ++drawn;
        ASSERT_TRUE(x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1)
            << "trial " << trial << ": pixel " << x << "," << y << " outside " << window.x0 << "," << window.y0 << " "
            << window.x1 << "," << window.y1;
      }
    // The item buffer's reading of points inside the sphere (the triangle's corners pulled in).
    for (const glm::vec3& c : corners) {
      int x = 0, y = 0;
      if (!targetPixel(axes, eye, kResolution, glm::mix(glm::dvec3(c), centre, 0.25), x, y)) continue;
      EXPECT_TRUE(x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1) << "trial " << trial;
    }
  }
  EXPECT_GT(drawn, 10000);
  EXPECT_GT(empty, 0);  // some spheres below the horizon
  EXPECT_GT(whole, 0);  // some holding the eye
}

// Clusters of a flat strip of elements: every element inside one of the spheres, at most the
// given number of elements to a sphere, and the spheres much smaller than one around them all.
TEST(RadiosityWindow, SphereClustersHoldTheirElementsInSmallGroups) {
  std::vector<glm::dvec3> centre;
  std::vector<double> radius;
  for (int i = 0; i < 40; ++i)
    for (int k = 0; k < 10; ++k) centre.emplace_back(0.1 * i, 0, 0.1 * k), radius.push_back(0.071);
  std::vector<uint32_t> elements(centre.size());
  for (uint32_t j = 0; j < elements.size(); ++j) elements[j] = j;
  std::vector<uint32_t> shuffled = elements;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(3));
  const std::vector<Sphere> spheres = sphereClusters(centre, radius, elements, 32);
  const std::vector<Sphere> again = sphereClusters(centre, radius, shuffled, 32);
  ASSERT_EQ(spheres.size(), again.size());
  EXPECT_GE(spheres.size(), elements.size() / 32);
  EXPECT_LE(spheres.size(), 2 * elements.size() / 32 + 1);
  for (size_t c = 0; c < spheres.size(); ++c) {
    EXPECT_EQ(spheres[c].centre, again[c].centre);
    EXPECT_EQ(spheres[c].radius, again[c].radius);
    EXPECT_LT(spheres[c].radius, 0.5);  // one around all of them: over 2
  }
  for (uint32_t j = 0; j < centre.size(); ++j)
    EXPECT_TRUE(std::any_of(spheres.begin(), spheres.end(), [&](const Sphere& s) {
      return glm::length(centre[j] - s.centre) + radius[j] <= s.radius * (1 + 1e-12);
    })) << "element " << j;
}

TEST(RadiosityWindow, UniteAndOverlap) {
  const pxpl5::PixelRect a{0, 0, 10, 10}, b{20, 5, 30, 8}, none{};
  EXPECT_TRUE(overlaps(a, {9, 9, 12, 12}));
  EXPECT_FALSE(overlaps(a, {10, 0, 12, 12}));
  EXPECT_FALSE(overlaps(a, none));
  const pxpl5::PixelRect both = unite(a, b);
  EXPECT_EQ(both.x0, 0);
  EXPECT_EQ(both.x1, 30);
  EXPECT_EQ(both.y1, 10);
  EXPECT_EQ(pixelsOf(unite(none, b)), 30);
  EXPECT_EQ(pixelsOf(none), 0);
}

}  // namespace
}  // namespace radiosity

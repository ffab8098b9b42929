// Form factors from the emulated machine against closed forms: Lambert's contour formula for
// unoccluded polygons, a closed box, occlusion, the horizon, tiny and huge polygons, threads.
#include "pxpl5/hemisphere.h"
#include "pxpl5/projections.h"

#include "tests/pxpl5/scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <cstdio>
#include <random>

namespace pxpl5 {
namespace {

using test::lambertFactor;
using test::Soup;

double factorOf(const HemisphereFrame& frame, uint32_t id) { return test::factorOfIds(frame, id, id + 1); }

std::vector<glm::dvec3> ring(const Soup& soup, size_t polygon) {
  const Polygon& p = soup.polygons[polygon];
  std::vector<glm::dvec3> r;
  for (uint32_t k = 0; k < p.vertexCount; ++k) r.emplace_back(soup.vertices[p.firstVertex + k]);
  return r;
}

HemisphereSettings settings(int resolution, Projection projection = Projection::kHemisphere, int threads = 1) {
  HemisphereSettings s;
  s.resolution = resolution;
  s.projection = projection;
  s.graphicsProcessors = threads;
  return s;
}

// A random viewpoint and a random convex polygon (3 to 7 vertices on an ellipse) wholly above
// its horizon, with a form factor of at least 0.01.
struct Configuration {
  Viewpoint view;
  Soup soup;
  double exact = 0;
};

Configuration randomConfiguration(std::mt19937& random) {
  std::uniform_real_distribution<double> u(0, 1);
  const auto unit = [&] {
    glm::dvec3 v;
    do v = {2 * u(random) - 1, 2 * u(random) - 1, 2 * u(random) - 1};
    while (glm::length(v) > 1 || glm::length(v) < 0.1);
    return glm::normalize(v);
  };
  for (;;) {
    Configuration c;
    const glm::dvec3 point{u(random) * 4 - 2, u(random) * 4 - 2, u(random) * 4 - 2}, normal = unit();
    glm::dvec3 towards = unit();
    if (glm::dot(towards, normal) < 0.15) continue;
    const glm::dvec3 centre = point + towards * (0.5 + 3 * u(random));
    const glm::dvec3 facing = unit();
    const glm::dvec3 s = glm::normalize(glm::cross(facing, unit())), t = glm::cross(facing, s);
    const int n = 3 + static_cast<int>(u(random) * 5);
    const double rs = 0.2 + 1.2 * u(random), rt = 0.2 + 1.2 * u(random), phase = u(random);
    std::vector<glm::vec3> vertices;
    bool above = true;
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * (k + phase + 0.3 * u(random)) / n;
      const glm::dvec3 q = centre + s * (rs * std::cos(angle)) + t * (rt * std::sin(angle));
      above = above && glm::dot(q - point, normal) > 0.02;
      vertices.emplace_back(q);
    }
    if (!above) continue;
    c.view.point = glm::vec3(point);
    c.view.normal = glm::vec3(normal);
    c.soup.add(vertices, 42);
    c.exact = lambertFactor(glm::dvec3(c.view.point), glm::normalize(glm::dvec3(c.view.normal)), ring(c.soup, 0));
    if (c.exact < 0.01) continue;
    return c;
  }
}

TEST(Pxpl5Hemisphere, UnoccludedFactorsMatchLambertAndConvergeWithResolution) {
  std::mt19937 random(2024);
  std::vector<Configuration> configurations;
  for (int i = 0; i < 300; ++i) configurations.push_back(randomConfiguration(random));
  double previousMean = 1;
  for (int resolution : {128, 256, 512}) {
    HemisphereRenderer renderer(settings(resolution));
    double sum = 0, worst = 0;
    for (const Configuration& c : configurations) {
      const HemisphereFrame& frame = renderer.render(c.view, c.soup.view());
      const double error = std::abs(factorOf(frame, 42) - c.exact) / c.exact;
      sum += error;
      worst = std::max(worst, error);
    }
    const double mean = sum / static_cast<double>(configurations.size());
    std::printf("hemisphere %d: mean relative error %.4f%%, max %.4f%%\n", resolution, 100 * mean, 100 * worst);
    if (resolution >= 256) {
      EXPECT_LT(mean, 0.005);
    }
    // Boundary pixels grow as N and a polygon's pixels as N^2, so doubling N should at least
    // about halve the relative error (more where boundary errors cancel).
    EXPECT_LT(mean, previousMean * 0.6) << "the error shrinks with resolution";
    previousMean = mean;
  }
}

TEST(Pxpl5Hemisphere, HemicubeAlsoMatchesLambert) {
  std::mt19937 random(77);
  std::vector<Configuration> configurations;
  for (int i = 0; i < 200; ++i) configurations.push_back(randomConfiguration(random));
  double previousMean = 1;
  for (int resolution : {128, 256}) {
    HemisphereRenderer renderer(settings(resolution, Projection::kHemicube));
    double sum = 0, worst = 0;
    for (const Configuration& c : configurations) {
      const double error = std::abs(factorOf(renderer.render(c.view, c.soup.view()), 42) - c.exact) / c.exact;
      sum += error;
      worst = std::max(worst, error);
    }
    const double mean = sum / static_cast<double>(configurations.size());
    std::printf("hemicube %d: mean relative error %.4f%%, max %.4f%%\n", resolution, 100 * mean, 100 * worst);
    EXPECT_LT(mean, 0.02);
    EXPECT_LT(mean, previousMean);
    previousMean = mean;
  }
}

TEST(Pxpl5Hemisphere, ClosedBoxSumsToOne) {
  const Soup box = test::closedBox({0, 0, 0}, {3, 2, 2.5f}, 6);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> u(0, 1);
  for (Projection projection : {Projection::kHemisphere, Projection::kHemicube}) {
    HemisphereRenderer renderer(settings(256, projection));
    for (int trial = 0; trial < 20; ++trial) {
      Viewpoint view;
      view.point = {0.1f + 2.8f * u(random), 0.1f + 1.8f * u(random), 0.1f + 2.3f * u(random)};
      view.normal = {u(random) - 0.5f, u(random) - 0.5f, u(random) - 0.5f};
      const HemisphereFrame& frame = renderer.render(view, box.view());
      // No pixel sees through a crack: 1 to rounding (the hemicube's weights are floats).
      EXPECT_NEAR(frame.total, 1.0, projection == Projection::kHemisphere ? 1e-12 : 1e-6);
      // Each face against Lambert (the parts above the horizon): 6 x 36 quads.
      for (int face = 0; face < 6; ++face) {
        double exact = 0;
        for (size_t i = static_cast<size_t>(face) * 36; i < static_cast<size_t>(face + 1) * 36; ++i)
          exact += lambertFactor(glm::dvec3(view.point), glm::normalize(glm::dvec3(view.normal)), ring(box, i));
        const double got = test::factorOfIds(frame, static_cast<uint32_t>(face * 36), static_cast<uint32_t>(face * 36 + 36));
        EXPECT_NEAR(got, exact, 0.004 + 0.01 * exact) << "face " << face;
      }
    }
    // On the floor, looking up: the floor is the point's own plane and is not drawn.
    const HemisphereFrame& frame = renderer.render({{1.5f, 1.0f, 0.0f}, {0, 0, 1}, {}}, box.view());
    EXPECT_NEAR(frame.total, 1.0, projection == Projection::kHemisphere ? 1e-12 : 1e-6);
    EXPECT_EQ(test::factorOfIds(frame, 0, 36), 0.0);
  }
}

// The eye at the origin looking up +z; a square at height 2 and an occluder at height 1.
Soup occlusionScene(float occluderX0, float occluderX1) {
  Soup soup;
  soup.add({{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}}, 1);
  soup.add({{occluderX0, -0.6f, 1}, {occluderX1, -0.6f, 1}, {occluderX1, 0.6f, 1}, {occluderX0, 0.6f, 1}}, 2);
  return soup;
}

TEST(Pxpl5Hemisphere, OccludedPolygons) {
  const Viewpoint view{{0, 0, 0}, {0, 0, 1}, {}};
  for (Projection projection : {Projection::kHemisphere, Projection::kHemicube}) {
    HemisphereRenderer renderer(settings(512, projection));
    // Fully hidden: the occluder's shadow [-1.2, 1.2]^2 at height 2 covers the square.
    Soup full = occlusionScene(-0.6f, 0.6f);
    const HemisphereFrame& hidden = renderer.render(view, full.view());
    EXPECT_EQ(factorOf(hidden, 1), 0.0);
    EXPECT_NEAR(factorOf(hidden, 2), lambertFactor({0, 0, 0}, {0, 0, 1}, ring(full, 1)), 0.002);
    // Drawn in the other order: the same.
    std::swap(full.polygons[0], full.polygons[1]);
    EXPECT_EQ(factorOf(renderer.render(view, full.view()), 1), 0.0);

    // Half hidden: the occluder over x in [-0.6, 0] shades x in [-1.2, 0] at height 2.
    const Soup half = occlusionScene(-0.6f, 0.0f);
    const HemisphereFrame& frame = renderer.render(view, half.view());
    const double visibleHalf = lambertFactor({0, 0, 0}, {0, 0, 1}, {{0, -1, 2}, {1, -1, 2}, {1, 1, 2}, {0, 1, 2}});
    const double occluder = lambertFactor({0, 0, 0}, {0, 0, 1}, ring(half, 1));
    SCOPED_TRACE(projection == Projection::kHemisphere ? "hemisphere" : "hemicube");
    EXPECT_NEAR(factorOf(frame, 1), visibleHalf, 0.005 * visibleHalf);
    EXPECT_NEAR(factorOf(frame, 2), occluder, 0.005 * occluder);

    // Skipping the occluder's id shows the whole square.
    const uint32_t skip[] = {2};
    const HemisphereFrame& skipped = renderer.render({{0, 0, 0}, {0, 0, 1}, skip}, half.view());
    EXPECT_NEAR(factorOf(skipped, 1), lambertFactor({0, 0, 0}, {0, 0, 1}, ring(half, 0)), 0.002);
    EXPECT_EQ(factorOf(skipped, 2), 0.0);
  }
}

TEST(Pxpl5Hemisphere, PolygonsAtTheHorizon) {
  HemisphereRenderer renderer(settings(512));
  const Viewpoint view{{0, 0, 0}, {0, 0, 1}, {}};
  Soup soup;
  soup.add({{2, -1, -1}, {2, 1, -1}, {2, 1, 1}, {2, -1, 1}}, 1);            // a wall crossing the horizon
  soup.add({{-1, 2, 0}, {1, 2, 0}, {1, 2, 1}, {-1, 2, 1}}, 2);             // standing on it
  soup.add({{-1, -2, -1}, {1, -2, -1}, {1, -2, -0.01f}, {-1, -2, -0.01f}}, 3);  // wholly below
  soup.add({{-3, -1, 0}, {-3, 1, 0}, {-2, 0, 0.5f}}, 4);                    // an edge on the horizon
  const HemisphereFrame& frame = renderer.render(view, soup.view());
  for (uint32_t id : {1u, 2u, 4u}) {
    const double exact = lambertFactor({0, 0, 0}, {0, 0, 1}, ring(soup, id - 1));
    EXPECT_NEAR(factorOf(frame, id), exact, 0.005 * exact) << "id " << id;
  }
  EXPECT_EQ(factorOf(frame, 3), 0.0);
}

TEST(Pxpl5Hemisphere, TinyPolygonsTileLikeTheirUnion) {
  // A 1 x 1 square at distance 3 cut into 120 x 120 quads, each far below a pixel at 128: the
  // tiles leave no crack, so they cover the pixels the whole square covers.
  HemisphereRenderer renderer(settings(128));
  const Viewpoint view{{0.2f, 0.1f, 0}, {0.1f, 0, 1}, {}};
  Soup whole, tiles;
  whole.addGrid({-0.5f, -0.5f, 3}, {1, 0, 0}, {0, 1, 0}, 1, 0);
  tiles.addGrid({-0.5f, -0.5f, 3}, {1, 0, 0}, {0, 1, 0}, 120, 0);
  const double one = renderer.render(view, whole.view()).total;
  const double union_ = renderer.render(view, tiles.view()).total;
  EXPECT_NEAR(union_, one, 1e-12);
  EXPECT_GT(renderer.render(view, tiles.view()).factors.size(), 100u);
  EXPECT_NEAR(one, lambertFactor(glm::dvec3(view.point), glm::normalize(glm::dvec3(view.normal)), ring(whole, 0)), 0.01 * one);
  // One tiny triangle alone: at most a pixel or two.
  Soup speck;
  speck.add({{0, 0, 3}, {0.001f, 0, 3}, {0, 0.001f, 3}}, 9);
  EXPECT_LE(renderer.render(view, speck.view()).total, 3 * renderer.render(view, whole.view()).weights[64 * 128 + 64]);
}

TEST(Pxpl5Hemisphere, HugePolygons) {
  for (Projection projection : {Projection::kHemisphere, Projection::kHemicube}) {
    HemisphereRenderer renderer(settings(256, projection));
    const Viewpoint view{{0, 0, 0}, {0, 0, 1}, {}};
    Soup ceiling;
    // 20,000 times wider than its distance: nearly the whole hemisphere, and still well above
    // the own-plane test's 1e-6 of its size.
    ceiling.add({{-1e4f, -1e4f, 1}, {1e4f, -1e4f, 1}, {1e4f, 1e4f, 1}, {-1e4f, 1e4f, 1}}, 1);
    const double exact = lambertFactor({0, 0, 0}, {0, 0, 1}, ring(ceiling, 0));
    EXPECT_NEAR(renderer.render(view, ceiling.view()).total, exact, 2e-3);
    // A huge wall through the horizon: half the hemisphere behind x = 1.
    Soup wall;
    wall.add({{1, -1e4f, -1e4f}, {1, 1e4f, -1e4f}, {1, 1e4f, 1e4f}, {1, -1e4f, 1e4f}}, 1);
    EXPECT_NEAR(renderer.render(view, wall.view()).total, 0.5, 2e-3);
  }
}

Soup randomTriangles(int count, uint32_t seed) {
  Soup soup;
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> u(-3, 3);
  for (int i = 0; i < count; ++i) {
    const glm::vec3 c{u(random), u(random), u(random)};
    soup.add({c, c + glm::vec3{u(random), u(random), u(random)} * 0.2f, c + glm::vec3{u(random), u(random), u(random)} * 0.2f},
             static_cast<uint32_t>(i / 2));  // two triangles per id
  }
  return soup;
}

TEST(Pxpl5Hemisphere, SameAnswerForOneTwoAndEightThreadsAndForTheReference) {
  const Soup soup = randomTriangles(5000, 3);
  const Viewpoint view{{0.1f, 0.2f, 0.3f}, {0.3f, -0.2f, 1}, {}};
  for (Projection projection : {Projection::kHemisphere, Projection::kHemicube}) {
    HemisphereRenderer one(settings(256, projection, 1));
    const HemisphereFrame expected = one.render(view, soup.view());
    const std::vector<uint32_t> items(expected.items.begin(), expected.items.end());
    EXPECT_GT(expected.factors.size(), 500u);
    EXPECT_TRUE(std::is_sorted(expected.factors.begin(), expected.factors.end(), [](auto& a, auto& b) { return a.id < b.id; }));
    HemisphereSettings reference = settings(256, projection, 1);
    reference.evaluator = Evaluator::kScalarReference;
    HemisphereRenderer scalar(reference);
    HemisphereRenderer two(settings(256, projection, 2)), eight(settings(256, projection, 8));
    for (HemisphereRenderer* r : {&scalar, &two, &eight}) {
      const HemisphereFrame& got = r->render(view, soup.view());
      ASSERT_TRUE(std::equal(items.begin(), items.end(), got.items.begin()));
      ASSERT_EQ(got.factors.size(), expected.factors.size());
      for (size_t i = 0; i < got.factors.size(); ++i) {
        EXPECT_EQ(got.factors[i].id, expected.factors[i].id);
        EXPECT_EQ(got.factors[i].factor, expected.factors[i].factor);
      }
    }
  }
}

// A windowed frame has the whole frame's items inside the window and each id's factor is the
// weight of its pixels there; a window is cheaper by what it leaves out. Both projections.
TEST(Pxpl5Hemisphere, WindowedFrameIsTheWholeFrameInsideItsWindow) {
  const Soup soup = randomTriangles(5000, 7), other = randomTriangles(3000, 8);
  const Viewpoint view{{0.1f, 0.2f, 0.3f}, {0.3f, -0.2f, 1}, {}};
  for (Projection projection : {Projection::kHemisphere, Projection::kHemicube}) {
    HemisphereRenderer whole(settings(256, projection, 2)), windowed(settings(256, projection, 2));
    const HemisphereFrame& full = whole.render(view, soup.view());
    const uint64_t fullPrimitives = whole.counters().regionPrimitives;
    for (const PixelRect window : {PixelRect{60, 90, 150, 170}, PixelRect{0, 0, 256, 40}, PixelRect{250, 500, 300, 900}}) {
      const HemisphereFrame& earlier = windowed.render(view, other.view());  // other items everywhere
      const std::vector<uint32_t> stale(earlier.items.begin(), earlier.items.end());
      const HemisphereFrame& got = windowed.render(view, soup.view(), window);
      EXPECT_LT(windowed.counters().regionPrimitives, fullPrimitives);
      std::map<uint32_t, double> expected;  // per id, the weight of its pixels in the window
      for (int y = 0; y < full.height; ++y) {
        for (int x = 0; x < full.width; ++x) {
          const size_t at = static_cast<size_t>(y) * static_cast<size_t>(full.stride) + static_cast<size_t>(x);
          const bool in = x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1;
          ASSERT_EQ(got.items[at], in ? full.items[at] : stale[at]) << x << "," << y;
          if (in && full.items[at] != kNoValue) expected[soup.polygons[full.items[at]].id] += full.weights[at];
        }
      }
      ASSERT_EQ(got.factors.size(), expected.size());
      double total = 0;
      for (const IdFactor& f : got.factors) {
        EXPECT_NEAR(f.factor, expected[f.id], 1e-6 * f.factor);
        EXPECT_LE(f.factor, factorOf(full, f.id) * (1 + 1e-12));
        total += f.factor;
      }
      EXPECT_NEAR(got.total, total, 1e-12);
    }
  }
}

// Polygons of 3 to 8 vertices in random order (the vector set-up's lanes then mix vertex
// counts), some with a repeated vertex, some through the viewpoint's plane, many across its
// horizon, all around the point.
Soup mixedPolygons(int count, uint32_t seed) {
  Soup soup;
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> u(-3, 3), unit(0, 1);
  for (int i = 0; i < count; ++i) {
    const glm::vec3 c{u(random), u(random), u(random)};
    const glm::vec3 s = glm::vec3{u(random), u(random), u(random)} * 0.1f, t = glm::vec3{u(random), u(random), u(random)} * 0.1f;
    const int n = 3 + static_cast<int>(unit(random) * 6);
    std::vector<glm::vec3> ring;
    for (int k = 0; k < n; ++k) {
      const float angle = 6.2831853f * static_cast<float>(k) / static_cast<float>(n);
      ring.push_back(c + s * std::cos(angle) + t * std::sin(angle));
    }
    if (i % 11 == 0) ring[1] = ring[0];                          // a repeated vertex
    if (i % 13 == 0) for (glm::vec3& q : ring) q.z = 0.3f;       // in the plane of the point below
    soup.add(ring, static_cast<uint32_t>(i));
  }
  return soup;
}

TEST(Pxpl5Hemisphere, VectorSetUpEmitsTheReferencesPrimitives) {
  Viewpoint roomView;
  const Soup room = test::benchmarkRoom(3000, roomView);
  const Soup mixed = mixedPolygons(4001, 11);
  const uint32_t skip[] = {5, 6, 40};
  struct Case {
    const Soup* soup;
    Viewpoint view;
  };
  const Case cases[] = {{&room, roomView}, {&mixed, {{0.1f, 0.2f, 0.3f}, {0.3f, -0.2f, 1}, {}}},
                        {&mixed, {{0, 0, 0.3f}, {0, 0, 1}, skip}}, {&mixed, {{-0.5f, 0.4f, 0}, {-1, 0.5f, 0.2f}, {}}}};
  for (const Case& c : cases) {
    const PolygonSoup soup = c.soup->view();
    const ProjectionInput input{&soup, localFrame(c.view), c.view.skipIds, 256};
    // Batches of 37 polygons: groups of four and a remainder, at every offset.
    Machine vector({256, 256, 1, Evaluator::kVector}), reference({256, 256, 1, Evaluator::kVector});
    std::vector<float> weights;
    loadHemispherePlanes(vector, 256, weights);
    loadHemispherePlanes(reference, 256, weights);
    vector.renderFrame(soup.polygons.size(), [&](size_t begin, size_t end, Emitter& out) { setupHemisphere(input, begin, end, out); }, 37);
    reference.renderFrame(soup.polygons.size(), [&](size_t begin, size_t end, Emitter& out) { setupHemisphereReference(input, begin, end, out); },
                          37);
    // Every primitive's bounds and stream (the ring's counts) and every pixel's winner and depth.
    const FrameCounters& a = vector.counters();
    const FrameCounters& b = reference.counters();
    EXPECT_GT(a.primitivesOut, soup.polygons.size() / 4);
    EXPECT_EQ(a.primitivesOut, b.primitivesOut);
    EXPECT_EQ(a.regionPrimitives, b.regionPrimitives);
    EXPECT_EQ(a.instructions, b.instructions);
    EXPECT_EQ(a.ringBytes, b.ringBytes);
    EXPECT_EQ(a.emulatedPixelOps, b.emulatedPixelOps);
    EXPECT_EQ(a.pixelsWritten, b.pixelsWritten);
    ASSERT_TRUE(std::equal(vector.valuePlane().begin(), vector.valuePlane().end(), reference.valuePlane().begin()));
    ASSERT_EQ(std::memcmp(vector.depthPlane().data(), reference.depthPlane().data(), vector.depthPlane().size_bytes()), 0);
  }
}

TEST(Pxpl5Hemisphere, IdsAreSummedAndSortedWhateverTheirOrder) {
  HemisphereRenderer renderer(settings(128));
  Soup soup;
  soup.add({{-1, -1, 2}, {0, -1, 2}, {0, 1, 2}, {-1, 1, 2}}, 9);
  soup.add({{0, -1, 2}, {1, -1, 2}, {1, 1, 2}}, 4);
  soup.add({{0, -1, 2}, {1, 1, 2}, {0, 1, 2}}, 9);
  const HemisphereFrame& frame = renderer.render({{0, 0, 0}, {0, 0, 1}, {}}, soup.view());
  ASSERT_EQ(frame.factors.size(), 2u);
  EXPECT_EQ(frame.factors[0].id, 4u);
  EXPECT_EQ(frame.factors[1].id, 9u);
  const double square = lambertFactor({0, 0, 0}, {0, 0, 1}, {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}});
  EXPECT_NEAR(frame.total, square, 0.01 * square);
  EXPECT_NEAR(frame.factors[1].factor, 0.75 * square, 0.02 * square);  // by symmetry, three quarters
}

TEST(Pxpl5Hemisphere, RejectsBadInput) {
  EXPECT_THROW(HemisphereRenderer(settings(7)), std::invalid_argument);
  EXPECT_THROW(HemisphereRenderer(settings(101)), std::invalid_argument);
  HemisphereRenderer renderer(settings(64));
  const std::vector<glm::vec3> vertices{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  const Viewpoint view;
  const std::vector<Polygon> twoVertices{{0, 2, 0}}, pastTheEnd{{1, 3, 0}}, farPastTheEnd{{0xfffffff0u, 3, 0}};
  EXPECT_THROW(renderer.render(view, {vertices, twoVertices}), std::invalid_argument);
  EXPECT_THROW(renderer.render(view, {vertices, pastTheEnd}), std::invalid_argument);
  EXPECT_THROW(renderer.render(view, {vertices, farPastTheEnd}), std::invalid_argument);
  EXPECT_THROW(renderer.render({{0, 0, 0}, {0, 0, 0}, {}}, {vertices, {}}), std::invalid_argument);
  EXPECT_NO_THROW(renderer.render(view, {vertices, {}}));
  EXPECT_EQ(renderer.render(view, {vertices, {}}).total, 0.0);
}

TEST(Pxpl5Hemisphere, CountersDescribeTheFrame) {
  HemisphereRenderer renderer(settings(256));
  Viewpoint view;
  const Soup room = test::benchmarkRoom(2000, view);
  renderer.render(view, room.view());
  const FrameCounters& c = renderer.counters();
  EXPECT_EQ(c.primitivesIn, room.polygons.size());
  EXPECT_GT(c.primitivesOut, c.primitivesIn / 3);
  EXPECT_LE(c.primitivesOut, c.primitivesIn);
  EXPECT_GE(c.regionPrimitives, c.primitivesOut);
  EXPECT_EQ(c.machinePixelOps, c.instructions * 128 * 128);
  EXPECT_LT(c.emulatedPixelOps, c.machinePixelOps / 10);  // bounding boxes save most of the broadcast
  EXPECT_GT(c.pixelsWritten, 40000u);
}

}  // namespace
}  // namespace pxpl5

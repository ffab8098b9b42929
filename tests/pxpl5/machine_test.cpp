// The emulated machine on its own: coverage by edge expressions, the quadratic evaluator, depth,
// the stored term, counters, and the vectorised evaluator against the scalar reference.
#include "pxpl5/pxpl5.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <limits>
#include <mutex>
#include <random>

namespace pxpl5 {
namespace {

// x >= x0, x < x1 (as x <= x1 - 1), y likewise.
std::vector<Expression> rectangleEdges(int x0, int y0, int x1, int y1) {
  return {{1, 0, static_cast<float>(-x0)}, {-1, 0, static_cast<float>(x1 - 1)}, {0, 1, static_cast<float>(-y0)},
          {0, -1, static_cast<float>(y1 - 1)}};
}

Expression constantDepth(float w) { return {0, 0, w}; }

size_t countValue(const Machine& machine, uint32_t value) {
  size_t n = 0;
  for (uint32_t v : machine.valuePlane()) n += v == value;
  return n;
}

TEST(Pxpl5Machine, RectangleCoversItsPixelsAcrossRegions) {
  Machine machine({300, 200, 1, Evaluator::kVector});
  EXPECT_EQ(machine.pixelStride(), 384);
  machine.renderFrame(1, [](size_t, size_t, Emitter& out) {
    out.convex({0, 0, 300, 200}, rectangleEdges(100, 50, 260, 140), constantDepth(1), 7);
  });
  EXPECT_EQ(countValue(machine, 7), 160u * 90u);
  EXPECT_EQ(machine.valuePlane()[static_cast<size_t>(50 * 384 + 100)], 7u);
  EXPECT_EQ(machine.valuePlane()[static_cast<size_t>(50 * 384 + 99)], kNoValue);
  EXPECT_EQ(machine.valuePlane()[static_cast<size_t>(139 * 384 + 259)], 7u);
  EXPECT_EQ(machine.valuePlane()[static_cast<size_t>(140 * 384 + 259)], kNoValue);

  // Bounds of the whole screen: 3 x 2 regions, one stream each of 4 edges + 2 instructions.
  const FrameCounters& c = machine.counters();
  EXPECT_EQ(c.primitivesIn, 1u);
  EXPECT_EQ(c.primitivesOut, 1u);
  EXPECT_EQ(c.regionPrimitives, 6u);
  EXPECT_EQ(c.ringMessages, 6u);
  EXPECT_EQ(c.instructions, 36u);
  EXPECT_EQ(c.ringBytes, 6u * (16 + 5 * 16));
  EXPECT_EQ(c.machinePixelOps, 36u * 128 * 128);
  EXPECT_EQ(c.emulatedPixelOps, 304u * 200 * 5);  // in runs of eight: 300 pixels take 38
  EXPECT_EQ(c.pixelsWritten, 160u * 90u);
}

TEST(Pxpl5Machine, RegionProgramSeesEveryFinishedRegionOnce) {
  Machine machine({300, 200, 2, Evaluator::kVector});
  std::mutex mutex;
  std::vector<PixelRect> regions;
  size_t covered = 0;
  machine.renderFrame(
      1, [](size_t, size_t, Emitter& out) { out.convex({0, 0, 300, 200}, rectangleEdges(100, 50, 260, 140), constantDepth(1), 7); }, 256,
      [&](PixelRect region, int renderer) {
        size_t n = 0;
        for (int y = region.y0; y < region.y1; ++y)
          for (int x = region.x0; x < region.x1; ++x) n += machine.valuePlane()[static_cast<size_t>(y * 384 + x)] == 7;
        std::lock_guard lock(mutex);
        EXPECT_GE(renderer, 0);
        EXPECT_LT(renderer, 2);
        regions.push_back(region);
        covered += n;
      });
  ASSERT_EQ(regions.size(), 6u);
  std::sort(regions.begin(), regions.end(), [](const PixelRect& a, const PixelRect& b) { return std::pair(a.y0, a.x0) < std::pair(b.y0, b.x0); });
  EXPECT_EQ(regions[2].x0, 256);
  EXPECT_EQ(regions[2].x1, 300);  // clipped to the screen
  EXPECT_EQ(regions[5].y1, 200);
  EXPECT_EQ(covered, 160u * 90u);  // each region's pixels were final when it was handed over
}

TEST(Pxpl5Machine, QuadraticExpressionDrawsADisk) {
  // r^2 - (x - cx)^2 - (y - cy)^2 >= 0, straight from the quadratic evaluator.
  Machine machine({256, 256, 1, Evaluator::kVector});
  const float cx = 100.3f, cy = 140.7f, r = 60.0f;
  const Expression disk{2 * cx, 2 * cy, r * r - cx * cx - cy * cy, -1, 0, -1};
  machine.renderFrame(1, [&](size_t, size_t, Emitter& out) {
    out.convex({0, 0, 256, 256}, std::span(&disk, 1), constantDepth(1), 3);
  });
  const size_t inside = countValue(machine, 3);
  EXPECT_NEAR(static_cast<double>(inside), std::numbers::pi * r * r, 2 * std::numbers::pi * r);
  size_t expected = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const double dx = x - static_cast<double>(cx), dy = y - static_cast<double>(cy);
      expected += dx * dx + dy * dy <= static_cast<double>(r) * r - 0.01;
    }
  EXPECT_NEAR(static_cast<double>(inside), static_cast<double>(expected), 4.0);  // float rounding on the rim only
}

TEST(Pxpl5Machine, NearerWinsAndTiesKeepTheFirst) {
  Machine machine({128, 128, 1, Evaluator::kVector});
  machine.renderFrame(3, [](size_t begin, size_t end, Emitter& out) {
    for (size_t i = begin; i < end; ++i) {
      if (i == 0) out.convex({0, 0, 128, 128}, rectangleEdges(0, 0, 64, 128), constantDepth(1), 10);    // far, left
      if (i == 1) out.convex({0, 0, 128, 128}, rectangleEdges(32, 0, 128, 128), constantDepth(2), 11);  // near, right
      if (i == 2) out.convex({0, 0, 128, 128}, rectangleEdges(0, 0, 128, 64), constantDepth(2), 12);    // ties with 11
    }
  });
  const auto at = [&](int x, int y) { return machine.valuePlane()[static_cast<size_t>(y * 128 + x)]; };
  EXPECT_EQ(at(10, 100), 10u);
  EXPECT_EQ(at(40, 100), 11u);
  EXPECT_EQ(at(40, 10), 11u);  // the tie keeps the earlier primitive
  EXPECT_EQ(at(10, 10), 12u);
  EXPECT_EQ(machine.depthPlane()[static_cast<size_t>(100 * 128 + 40)], 2.0f);
}

TEST(Pxpl5Machine, StoredTermAndPermanentlyDisabledPixels) {
  Machine machine({128, 128, 1, Evaluator::kVector});
  // Term = 1 on the left half; "term - 0.5 >= 0" selects it. Row 5 is never written.
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      machine.termPlane()[static_cast<size_t>(y * 128 + x)] = x < 64 ? 1.0f : 0.0f;
      machine.clearDepthPlane()[static_cast<size_t>(y * 128 + x)] = y == 5 ? std::numeric_limits<float>::infinity() : 0.0f;
    }
  const Expression left{0, 0, -0.5f, 0, 0, 0, 1};
  machine.renderFrame(1, [&](size_t, size_t, Emitter& out) { out.convex({0, 0, 128, 128}, std::span(&left, 1), constantDepth(1), 1); });
  EXPECT_EQ(countValue(machine, 1), 64u * 127u);
  EXPECT_EQ(machine.valuePlane()[static_cast<size_t>(5 * 128 + 3)], kNoValue);
  EXPECT_EQ(machine.valuePlane()[static_cast<size_t>(6 * 128 + 3)], 1u);
}

TEST(Pxpl5Machine, RejectsPrimitivesWithoutEdgesOrWithTooMany) {
  Machine machine({128, 128, 1, Evaluator::kVector});
  const std::vector<Expression> many(33, Expression{0, 0, 1});
  EXPECT_THROW(machine.renderFrame(1, [&](size_t, size_t, Emitter& out) { out.convex({0, 0, 8, 8}, {}, constantDepth(1), 1); }),
               std::invalid_argument);
  EXPECT_THROW(machine.renderFrame(1, [&](size_t, size_t, Emitter& out) { out.convex({0, 0, 8, 8}, many, constantDepth(1), 1); }),
               std::invalid_argument);
  EXPECT_THROW(Machine({0, 128, 1, Evaluator::kVector}), std::invalid_argument);
  // On a graphics-processor thread the error reaches the caller too, and the machine still works.
  Machine threaded({256, 256, 4, Evaluator::kVector});
  const auto program = [&](size_t begin, size_t, Emitter& out) {
    if (begin == 300) out.convex({0, 0, 8, 8}, many, constantDepth(1), 1);
    out.convex({0, 0, 8, 8}, rectangleEdges(0, 0, 4, 4), constantDepth(1), 1);
  };
  EXPECT_THROW(threaded.renderFrame(1000, program, 100), std::invalid_argument);
  threaded.renderFrame(300, program, 100);
  EXPECT_EQ(countValue(threaded, 1), 16u);
}

// Random triangles and conics with random depth planes over a random term plane.
struct RandomFrame {
  std::vector<PixelRect> bounds;
  std::vector<std::vector<Expression>> edges;
  std::vector<Expression> depth;

  explicit RandomFrame(uint32_t seed, int width, int height, int count) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < count; ++i) {
      const float cx = u(random) * static_cast<float>(width), cy = u(random) * static_cast<float>(height);
      const float size = 2 + 60 * u(random) * u(random);
      std::vector<Expression> e;
      if (i % 5 == 0) {  // a disk
        e.push_back({2 * cx, 2 * cy, size * size - cx * cx - cy * cy, -1, 0, -1});
      } else {  // a triangle (counter-clockwise in x right, y down is clockwise; orient by area)
        float px[3], py[3];
        for (int k = 0; k < 3; ++k) px[k] = cx + size * (u(random) - 0.5f) * 2, py[k] = cy + size * (u(random) - 0.5f) * 2;
        const float area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
        const float s = area >= 0 ? 1.0f : -1.0f;
        for (int k = 0; k < 3; ++k) {
          const int l = (k + 1) % 3;
          const float a = -(py[l] - py[k]) * s, b = (px[l] - px[k]) * s;
          e.push_back({a, b, -(a * px[k] + b * py[k]), 0, 0, 0, u(random) - 0.5f});
        }
      }
      edges.push_back(e);
      bounds.push_back({static_cast<int>(cx - size) - 1, static_cast<int>(cy - size) - 1, static_cast<int>(cx + size) + 2,
                        static_cast<int>(cy + size) + 2});
      depth.push_back({(u(random) - 0.5f) * 0.01f, (u(random) - 0.5f) * 0.01f, 1 + u(random), 0, 0, 0, u(random)});
      // Now and then a depth of zeros of either sign, whose own sign shows where the clear
      // depth is below zero.
      if (i % 7 == 1) depth.back() = {-0.0f, -0.0f, -0.0f, -0.0f, 0, -0.0f, -0.0f};
    }
  }
  SetupProgram program() const {
    return [this](size_t begin, size_t end, Emitter& out) {
      for (size_t i = begin; i < end; ++i) out.convex(bounds[i], edges[i], depth[i], static_cast<uint32_t>(i));
    };
  }
};

void loadRandomTerm(Machine& machine, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> u(0, 1);
  for (float& t : machine.termPlane()) t = u(random);
}

TEST(Pxpl5Machine, VectorEvaluatorMatchesTheScalarReferenceBitForBit) {
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const RandomFrame frame(seed, 333, 260, 600);
    Machine vector({333, 260, 1, Evaluator::kVector}), reference({333, 260, 1, Evaluator::kScalarReference});
    loadRandomTerm(vector, seed);
    loadRandomTerm(reference, seed);
    if (seed % 2 == 0) {
      std::fill(vector.clearDepthPlane().begin(), vector.clearDepthPlane().end(), -1.0f);
      std::fill(reference.clearDepthPlane().begin(), reference.clearDepthPlane().end(), -1.0f);
    }
    vector.renderFrame(frame.bounds.size(), frame.program(), 64);
    reference.renderFrame(frame.bounds.size(), frame.program(), 64);
    ASSERT_TRUE(std::equal(vector.valuePlane().begin(), vector.valuePlane().end(), reference.valuePlane().begin()));
    ASSERT_EQ(std::memcmp(vector.depthPlane().data(), reference.depthPlane().data(), vector.depthPlane().size_bytes()), 0);  // bits
    EXPECT_EQ(vector.counters().pixelsWritten, reference.counters().pixelsWritten);
    EXPECT_GT(vector.counters().pixelsWritten, 10000u);
    EXPECT_GE(vector.counters().emulatedPixelOps, reference.counters().emulatedPixelOps);  // runs of eight
  }
}

TEST(Pxpl5Machine, SameFrameForAnyNumberOfGraphicsProcessors) {
  const RandomFrame frame(9, 512, 512, 3000);
  Machine one({512, 512, 1, Evaluator::kVector});
  one.renderFrame(frame.bounds.size(), frame.program(), 100);
  for (int threads : {2, 8}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    Machine many({512, 512, threads, Evaluator::kVector});
    for (int repeat = 0; repeat < 3; ++repeat) {  // the same machine, frame after frame
      many.renderFrame(frame.bounds.size(), frame.program(), 100);
      ASSERT_TRUE(std::equal(one.valuePlane().begin(), one.valuePlane().end(), many.valuePlane().begin()));
      ASSERT_TRUE(std::equal(one.depthPlane().begin(), one.depthPlane().end(), many.depthPlane().begin()));
      const FrameCounters& a = one.counters();
      const FrameCounters& b = many.counters();
      EXPECT_EQ(a.instructions, b.instructions);
      EXPECT_EQ(a.ringBytes, b.ringBytes);
      EXPECT_EQ(a.emulatedPixelOps, b.emulatedPixelOps);
      EXPECT_EQ(a.pixelsWritten, b.pixelsWritten);
      // The processors' loads add up to the totals.
      ASSERT_EQ(b.graphicsProcessors.size(), static_cast<size_t>(threads));
      uint64_t in = 0, rendered = 0, ops = 0, regions = 0;
      for (const ProcessorLoad& l : b.graphicsProcessors) in += l.primitives;
      for (const ProcessorLoad& l : b.renderers) rendered += l.primitives, ops += l.pixelOps, regions += l.tasks;
      EXPECT_EQ(in, b.primitivesIn);
      EXPECT_EQ(rendered, b.regionPrimitives);
      EXPECT_EQ(ops, b.emulatedPixelOps);
      EXPECT_EQ(regions, 16u);
    }
  }
}

// The graphics processors' output is kept, batch by batch, for the next frame; beyond
// MachineSettings::scratchBytes a frame gives back what it left more than half spare. After a
// frame of many primitives one of few: unbounded, the batches keep the first frame's storage;
// bounded, they hold about what the second needs, and draw the same.
TEST(Pxpl5Machine, GivesBackBatchStorageAFrameLeftSpareBeyondItsBound) {
  const RandomFrame frame(3, 512, 512, 4000);
  const auto everyNth = [&](size_t n) -> SetupProgram {
    return [&frame, n](size_t begin, size_t end, Emitter& out) {
      for (size_t i = begin; i < end; ++i)
        if (i % n == 0) out.convex(frame.bounds[i], frame.edges[i], frame.depth[i], static_cast<uint32_t>(i));
    };
  };
  MachineSettings bounded{512, 512, 2, Evaluator::kVector};
  bounded.scratchBytes = 0;
  Machine a({512, 512, 2, Evaluator::kVector}), b(bounded);
  a.renderFrame(frame.bounds.size(), everyNth(1), 100);
  b.renderFrame(frame.bounds.size(), everyNth(1), 100);
  const uint64_t full = a.counters().scratchBytes;
  a.renderFrame(frame.bounds.size(), everyNth(50), 100);
  b.renderFrame(frame.bounds.size(), everyNth(50), 100);
  EXPECT_EQ(a.counters().scratchBytes, full);
  EXPECT_LT(b.counters().scratchBytes, full / 10);
  EXPECT_TRUE(std::equal(a.valuePlane().begin(), a.valuePlane().end(), b.valuePlane().begin()));
}

// A scissored frame gives the whole frame's pixels inside its window (windows across region
// borders, at the screen's edge, past it, empty) and leaves every pixel outside as the frame
// before left it.
TEST(Pxpl5Machine, WindowRendersTheWholeFramesPixelsInsideAndTouchesNothingOutside) {
  const RandomFrame frame(4, 333, 260, 2000), other(5, 333, 260, 2000);
  Machine whole({333, 260, 2, Evaluator::kVector});
  whole.renderFrame(frame.bounds.size(), frame.program(), 100);
  const std::vector<uint32_t> value(whole.valuePlane().begin(), whole.valuePlane().end());
  const std::vector<float> depth(whole.depthPlane().begin(), whole.depthPlane().end());
  const size_t stride = static_cast<size_t>(whole.pixelStride());
  for (Evaluator evaluator : {Evaluator::kVector, Evaluator::kScalarReference}) {
    for (const PixelRect window : {PixelRect{100, 50, 200, 140}, PixelRect{0, 0, 13, 7}, PixelRect{120, 120, 140, 135},
                                   PixelRect{300, 200, 400, 300}, PixelRect{-20, -20, 5, 400}, PixelRect{50, 50, 50, 90}}) {
      SCOPED_TRACE(std::to_string(window.x0) + "," + std::to_string(window.y0) + " " + std::to_string(window.x1) + "," + std::to_string(window.y1));
      Machine machine({333, 260, 2, evaluator});
      machine.renderFrame(other.bounds.size(), other.program(), 100);
      const std::vector<uint32_t> before(machine.valuePlane().begin(), machine.valuePlane().end());
      const std::vector<float> depthBefore(machine.depthPlane().begin(), machine.depthPlane().end());
      std::vector<PixelRect> regions;
      std::mutex mutex;
      machine.renderFrame(window, frame.bounds.size(), frame.program(), 100, [&](PixelRect r, int) {
        std::lock_guard lock(mutex);
        regions.push_back(r);
      });
      uint64_t regionPixels = 0;
      for (const PixelRect& r : regions) {
        EXPECT_FALSE(r.empty());
        EXPECT_TRUE(r.x0 >= window.x0 && r.y0 >= window.y0 && r.x1 <= window.x1 && r.y1 <= window.y1);
        regionPixels += static_cast<uint64_t>(r.x1 - r.x0) * static_cast<uint64_t>(r.y1 - r.y0);
      }
      uint64_t inside = 0;
      for (int y = 0; y < 260; ++y) {
        for (int x = 0; x < 333; ++x) {
          const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
          const bool in = x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1;
          inside += in;
          ASSERT_EQ(machine.valuePlane()[at], in ? value[at] : before[at]) << x << "," << y;
          ASSERT_EQ(std::bit_cast<uint32_t>(machine.depthPlane()[at]), std::bit_cast<uint32_t>(in ? depth[at] : depthBefore[at]));
        }
      }
      EXPECT_EQ(regionPixels, inside);
      EXPECT_LE(machine.counters().regionPrimitives, whole.counters().regionPrimitives);
    }
  }
}

}  // namespace
}  // namespace pxpl5

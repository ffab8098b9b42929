// What the graphics processors hand to the ring: set-up primitives binned by screen region.
// Internal to pxpl5.
#pragma once

#include "pxpl5/pxpl5.h"
#include "util/scratch.h"

#include <algorithm>
#include <vector>

namespace pxpl5 {

struct Screen {
  int width = 0, height = 0;
  int stride = 0;  // a multiple of kRegionSize
  int regionsX = 0, regionsY = 0;
  int regionCount() const { return regionsX * regionsY; }
  PixelRect region(int r) const {
    const int x0 = (r % regionsX) * kRegionSize, y0 = (r / regionsX) * kRegionSize;
    return {x0, y0, std::min(x0 + kRegionSize, stride), std::min(y0 + kRegionSize, height)};
  }
};

// A linear expression as the ring carries it (README: 16 bytes): d, e and f are zeros. The
// emitter stores a + 0 and c + 0 (a negative zero made positive), after which the zeros' terms
// add nothing in the contract's formula, so the fused evaluator may leave them out and still
// give the reference's bits. Against the caller's expression only the sign of a zero result
// can differ, which changes no pixel's outcome.
struct LinearExpression {
  float a = 0, b = 0, c = 0, t = 0;
  static LinearExpression of(const Expression& e) { return {e.a + 0.0f, e.b, e.c + 0.0f, e.t}; }
  Expression whole() const { return {a, b, c, 0, 0, 0, t}; }
};

// A primitive's expressions are its edges, then its depth: edgeCount + 1 of them from `first`
// in the batch's `linear` or (any of them quadratic) `quadratic` list.
struct SetupPrimitive {
  PixelRect bounds;  // within the screen, not empty
  uint32_t first = 0, edgeCount = 0;
  uint32_t value = 0;
  bool quadratic = false;
};

// One graphics processor's output for one batch of the caller's primitives: its set-up
// primitives and, per region, which of them touch it (in emission order, so the caller's order).
struct Emitter::Batch {
  const Screen* screen = nullptr;
  PixelRect clip;  // the frame's window within the screen: primitives are clipped to it
  std::vector<SetupPrimitive> primitives;
  std::vector<LinearExpression> linear;
  std::vector<Expression> quadratic;
  std::vector<uint32_t> binStart;  // regionCount + 1 offsets into binned
  std::vector<uint32_t> binned;    // primitive indices grouped by region
  std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (region, primitive) before grouping
  // The ring's bookkeeping of this batch's instruction streams, set by countStreams()
  // (machine.cpp) after grouping.
  uint64_t instructions = 0, ringBytes = 0;
  std::vector<uint64_t> regionWork;  // per region, bounding-box pixels of the streams sent to it
  void countStreams();

  // What the batch holds for the next frame, and giving back what this one left spare
  // (util/scratch.h; MachineSettings::scratchBytes).
  size_t heldBytes() const { return util::heldBytes(primitives, linear, quadratic, binned, pairs); }
  void releaseSpare() { util::releaseSpare(primitives, linear, quadratic, binned, pairs); }
  void clear() {
    primitives.clear();
    linear.clear();
    quadratic.clear();
    pairs.clear();
  }
  // Counting sort of `pairs` by region into binStart/binned; stable, so emission order stays.
  void groupByRegion() {
    const size_t regions = static_cast<size_t>(screen->regionCount());
    binStart.assign(regions + 1, 0);
    for (const auto& p : pairs) ++binStart[p.first + 1];
    for (size_t r = 0; r < regions; ++r) binStart[r + 1] += binStart[r];
    binned.resize(pairs.size());
    std::vector<uint32_t>& fill = scratch;
    fill.assign(binStart.begin(), binStart.end() - 1);
    for (const auto& p : pairs) binned[fill[p.first]++] = p.second;
  }
  std::vector<uint32_t> scratch;
};

}  // namespace pxpl5

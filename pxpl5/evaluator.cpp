#include "pxpl5/evaluator.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace pxpl5 {

namespace {

// The contract's formula (pxpl5.h), term by term in its grouping.
float evaluate(const Expression& ex, float x, float y, float term) {
  const float rowA = ex.a + ex.e * y;
  const float rowC = (ex.b * y + ex.c) + ex.f * (y * y);
  return ((rowA * x + ex.d * (x * x)) + rowC) + ex.t * term;
}

// The primitive's expressions whole (a..f, t), in `whole` if they travel as linear ones.
const Expression* wholeExpressions(const SetupPrimitive& primitive, PrimitiveExpressions expressions, Expression* whole) {
  if (primitive.quadratic) return expressions.quadratic;
  for (uint32_t k = 0; k <= primitive.edgeCount; ++k) whole[k] = expressions.linear[k].whole();
  return whole;
}

// One expression's coefficients with the row's y folded in.
struct RowTerms {
  float a = 0, c = 0, d = 0, t = 0;
};

RowTerms rowTerms(const Expression& ex, float y) {
  return {ex.a + ex.e * y, (ex.b * y + ex.c) + ex.f * (y * y), ex.d, ex.t};
}

// Instruction by instruction over a row of the area, as the machine broadcasts them: each loop
// runs over contiguous floats with no branch (the enable flag is a mask, the conditional writes
// are selects), so the compiler vectorises it (README: the vectorisation report). Without
// quadratic terms d*(x*x) is zero and is left out; that changes no outcome (only the sign of a
// zero that no depth test can pass).
template <bool kQuadratic>
[[gnu::always_inline]] inline void evaluateRows(const SetupPrimitive& primitive, const Expression* edges, PixelRect area, const PixelMemory& memory,
                  EvaluatorStats& stats) {
  const Expression& depthExpression = edges[primitive.edgeCount];
  const uint32_t n = primitive.edgeCount;
  const uint32_t value = primitive.value;
  const int lo = area.x0, width = area.x1 - area.x0;
  alignas(64) float xs[kRegionSize];
  alignas(64) uint32_t on[kRegionSize];
  for (int i = 0; i < width; ++i) xs[i] = static_cast<float>(lo + i);
  uint32_t written = 0;
  for (int y = area.y0; y < area.y1; ++y) {
    const float fy = static_cast<float>(y);
    const size_t rowStart = static_cast<size_t>(y) * static_cast<size_t>(memory.stride) + static_cast<size_t>(lo);
    // Distinct planes (restrict spares the compiler a run-time overlap check).
    const float* __restrict term = memory.term + rowStart;
    float* __restrict depth = memory.depth + rowStart;
    uint32_t* __restrict values = memory.value + rowStart;
    // The first edge enables the pixels where it is >= 0; each further edge disables more.
    for (int i = 0; i < width; ++i) on[i] = ~0u;
    for (uint32_t k = 0; k < n; ++k) {
      const RowTerms r = rowTerms(edges[k], fy);
      for (int i = 0; i < width; ++i) {
        float v = r.a * xs[i];
        if constexpr (kQuadratic) v = v + r.d * (xs[i] * xs[i]);
        v = (v + r.c) + r.t * term[i];
        on[i] &= v >= 0 ? ~0u : 0u;
      }
    }
    // Depth: enabled pixels where the primitive is nearer take its depth and value.
    const RowTerms d = rowTerms(depthExpression, fy);
    for (int i = 0; i < width; ++i) {
      float w = d.a * xs[i];
      if constexpr (kQuadratic) w = w + d.d * (xs[i] * xs[i]);
      w = (w + d.c) + d.t * term[i];
      // Selects by bit masks: written as "wins ? w : depth[i]" the compiler turns the store
      // into a branch and gives up vectorising.
      const uint32_t wins = on[i] & (w > depth[i] ? ~0u : 0u);
      depth[i] = std::bit_cast<float>((std::bit_cast<uint32_t>(w) & wins) | (std::bit_cast<uint32_t>(depth[i]) & ~wins));
      values[i] = (value & wins) | (values[i] & ~wins);
      written += wins & 1u;
    }
  }
  stats.pixelOps += static_cast<uint64_t>(width) * static_cast<uint64_t>(area.y1 - area.y0) * (n + 1);
  stats.written += written;
}

// The same for the common primitives (linear, 3 to 6 edges), the edge count known to the
// compiler: one pass per row in which each pixel runs the whole stream, over whole runs of
// eight pixels (lanes outside the area start disabled) so that no scalar remainder loop runs.
// Rows are short (a small polygon's bounds), so this matters more than the lanes wasted. The
// runs start at the area, not at a multiple of eight (a five-pixel row is one run, not two),
// moved left where they would leave the region: another renderer may be writing the next one.
// Same expressions, same bits (the zeros a stored linear expression leaves out add nothing: batch.h).
//
// Written in GCC's vector extension, a run one vector of eight floats (one AVX2 register, two
// SSE2 ones in the baseline clone): left to the loop vectoriser, the same loop reloaded its
// coefficients on every run and checked at run time that the depth row overlapped nothing.
constexpr int kLanes = 8;
using Floats = float __attribute__((vector_size(kLanes * sizeof(float))));
using Lanes = uint32_t __attribute__((vector_size(kLanes * sizeof(uint32_t))));
using Mask = int32_t __attribute__((vector_size(kLanes * sizeof(int32_t))));  // a comparison's all ones or zero

// Every lane s (not 0 + s, which would make a negative zero positive).
template <class V, class T>
[[gnu::always_inline]] inline V splat(T s) {
  V v;
  for (int l = 0; l < kLanes; ++l) v[l] = s;
  return v;
}
template <class V, class T>
[[gnu::always_inline]] inline V loadRun(const T* at) {
  V v;
  std::memcpy(&v, at, sizeof v);
  return v;
}
template <class V, class T>
[[gnu::always_inline]] inline void storeRun(T* at, const V& v) {
  std::memcpy(at, &v, sizeof v);
}

template <int kEdges>
[[gnu::always_inline]] inline void evaluateRowsFused(const SetupPrimitive& primitive, const LinearExpression* ex, PixelRect area,
                                                     const PixelMemory& memory, EvaluatorStats& stats) {
  constexpr int kTerms = kEdges + 1;  // the edges, then the depth
  const int width = (area.x1 - area.x0 + kLanes - 1) & ~(kLanes - 1);  // a multiple of kLanes: no remainder
  const int runs = width / kLanes;
  const int regionEnd = (area.x0 & ~(kRegionSize - 1)) + kRegionSize;
  const int lo = std::min(area.x0, regionEnd - width);
  // What is the same on every row: each lane's a*x, whether it lies in the area, each t.
  Floats ax[kTerms][kRegionSize / kLanes];
  Mask inArea[kRegionSize / kLanes];
  Floats t[kTerms];
  for (int r = 0; r < runs; ++r) {
    Mask xi;
    for (int l = 0; l < kLanes; ++l) xi[l] = lo + r * kLanes + l;
    const Floats x = __builtin_convertvector(xi, Floats);
    for (int k = 0; k < kTerms; ++k) ax[k][r] = ex[k].a * x;
    inArea[r] = (xi >= area.x0) & (xi < area.x1);
  }
  for (int k = 0; k < kTerms; ++k) t[k] = splat<Floats>(ex[k].t);
  // Ask for the rows' pixel memory at once: they lie a stride apart, which the hardware
  // prefetcher does not foresee, and their misses then overlap instead of stalling row by row.
  // A row's first line only: most rows are short, and asking for the last as well cost as much
  // as it saved.
  for (int y = area.y0; y < area.y1; ++y) {
    const size_t rowStart = static_cast<size_t>(y) * static_cast<size_t>(memory.stride) + static_cast<size_t>(lo);
    __builtin_prefetch(memory.term + rowStart);
    __builtin_prefetch(memory.depth + rowStart, 1);
    __builtin_prefetch(memory.value + rowStart, 1);
  }
  const Lanes value = splat<Lanes>(primitive.value);
  Lanes won{};  // pixels written, counted per lane and added up once
  // The planes as locals: the stores could alias `memory`, whose pointers would be reloaded.
  const float* const termPlane = memory.term;
  float* const depthPlane = memory.depth;
  uint32_t* const valuePlane = memory.value;
  for (int y = area.y0; y < area.y1; ++y) {
    const float fy = static_cast<float>(y);
    Floats rowC[kTerms];
    for (int k = 0; k < kTerms; ++k) rowC[k] = splat<Floats>(ex[k].b * fy + ex[k].c);
    const size_t rowStart = static_cast<size_t>(y) * static_cast<size_t>(memory.stride) + static_cast<size_t>(lo);
    for (int r = 0; r < runs; ++r) {
      const size_t at = rowStart + static_cast<size_t>(r * kLanes);
      const Floats term = loadRun<Floats>(termPlane + at);
      Mask on = inArea[r];
      for (int k = 0; k < kEdges; ++k) on &= (ax[k][r] + rowC[k]) + t[k] * term >= 0;
      const Floats w = (ax[kEdges][r] + rowC[kEdges]) + t[kEdges] * term;
      const Floats depth = loadRun<Floats>(depthPlane + at);
      const Mask wins = on & (w > depth);
      storeRun(depthPlane + at, wins ? w : depth);
      storeRun(valuePlane + at, wins ? value : loadRun<Lanes>(valuePlane + at));
      won -= reinterpret_cast<const Lanes&>(wins);  // all ones (-1) where it wins
    }
  }
  for (int l = 0; l < kLanes; ++l) stats.written += won[l];
  stats.pixelOps += static_cast<uint64_t>(width) * static_cast<uint64_t>(area.y1 - area.y0) * kTerms;
}

}  // namespace

void evaluateReference(const SetupPrimitive& primitive, PrimitiveExpressions expressions, PixelRect area, const PixelMemory& memory,
                       EvaluatorStats& stats) {
  Expression whole[Emitter::kMaxEdges + 1];
  const Expression* edges = wholeExpressions(primitive, expressions, whole);
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      const size_t at = static_cast<size_t>(y) * static_cast<size_t>(memory.stride) + static_cast<size_t>(x);
      const float fx = static_cast<float>(x), fy = static_cast<float>(y), term = memory.term[at];
      bool on = true;
      for (uint32_t k = 0; k < primitive.edgeCount; ++k) on = on && evaluate(edges[k], fx, fy, term) >= 0;
      const float w = evaluate(edges[primitive.edgeCount], fx, fy, term);
      if (on && w > memory.depth[at]) {
        memory.depth[at] = w;
        memory.value[at] = primitive.value;
        ++stats.written;
      }
    }
  }
  stats.pixelOps += static_cast<uint64_t>(area.x1 - area.x0) * static_cast<uint64_t>(area.y1 - area.y0) * (primitive.edgeCount + 1);
}

// Compiled twice, for AVX2 (eight lanes) and for the build's baseline (SSE2, four), the choice
// made once at load time from the CPU: the default build must run on any x86-64.
// (ThreadSanitizer's runtime is not ready when the clone's resolver runs at load time.)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
[[gnu::target_clones("avx2", "default")]]
#endif
void evaluateVector(const SetupPrimitive& primitive, PrimitiveExpressions expressions, PixelRect area, const PixelMemory& memory,
                    EvaluatorStats& stats) {
  if (primitive.quadratic) return evaluateRows<true>(primitive, expressions.quadratic, area, memory, stats);
  switch (primitive.edgeCount) {
    case 3: return evaluateRowsFused<3>(primitive, expressions.linear, area, memory, stats);
    case 4: return evaluateRowsFused<4>(primitive, expressions.linear, area, memory, stats);
    case 5: return evaluateRowsFused<5>(primitive, expressions.linear, area, memory, stats);
    case 6: return evaluateRowsFused<6>(primitive, expressions.linear, area, memory, stats);
    default: {
      Expression whole[Emitter::kMaxEdges + 1];
      return evaluateRows<false>(primitive, wholeExpressions(primitive, expressions, whole), area, memory, stats);
    }
  }
}

}  // namespace pxpl5

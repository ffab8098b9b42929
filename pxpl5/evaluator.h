// A renderer's pixel processors running one primitive's instruction stream over one region:
// enable the pixels of the primitive's bounds, disable those where an edge expression is
// negative, then depth-test and write the survivors. Two evaluators give the same bits: a
// plain per-pixel reference and one written in GCC vector extensions. Internal to pxpl5.
#pragma once

#include "pxpl5/batch.h"

namespace pxpl5 {

// A region's pixel memory, seen through the screen planes.
struct PixelMemory {
  float* depth = nullptr;
  uint32_t* value = nullptr;
  const float* term = nullptr;
  int stride = 0;
};

struct EvaluatorStats {
  uint64_t pixelOps = 0;  // pixel-instruction evaluations done
  uint64_t written = 0;   // pixels that took the primitive's depth and value
};

// A primitive's expressions (SetupPrimitive): `linear` or `quadratic` as the primitive says.
struct PrimitiveExpressions {
  const LinearExpression* linear = nullptr;
  const Expression* quadratic = nullptr;
};

// `area` is the primitive's bounds within the region.
void evaluateReference(const SetupPrimitive& primitive, PrimitiveExpressions expressions, PixelRect area, const PixelMemory& memory,
                       EvaluatorStats& stats);
void evaluateVector(const SetupPrimitive& primitive, PrimitiveExpressions expressions, PixelRect area, const PixelMemory& memory,
                    EvaluatorStats& stats);

}  // namespace pxpl5

// walkrad's Pixel-Planes 5 (Fuchs et al., SIGGRAPH 1989) in software. Plain data in, plain data
// out; no globals, no GL, nothing about radiosity. README.md says what follows the real machine
// and where it simplifies.
//
// A frame runs in two phases, as on the machine. The graphics processors (worker threads) run
// the caller's setup program over the caller's primitives: each set-up primitive is a bounded
// pixel area, edge expressions that disable the pixels outside it, a depth expression and a
// value. Each primitive is binned to the 128 x 128 screen regions it touches and its instruction
// stream travels the ring to the renderers. Renderers take regions as they come free and
// broadcast each stream to their pixel processors, which evaluate the expressions against their
// own coordinates and per-pixel memory, keep the nearest depth and its value.
//
// Names: x is the pixel column, y the row, both integers (the evaluator's coordinates); a
// "plane" is one value per pixel, row-major with stride `pixelStride()`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace pxpl5 {

constexpr int kRegionSize = 128;            // a renderer's pixel-processor array is 128 x 128
constexpr uint32_t kNoValue = 0xffffffffu;  // the value plane after a clear

// The expression evaluator's output at pixel (x, y):
//   ((a + e*y)*x + d*(x*x)) + ((b*y + c) + f*(y*y)) + t*term(x, y)
// a..f are the quadratic expression evaluator's coefficients; t scales the per-pixel stored term
// plane (README: on the real machine a multiply by pixel memory). The grouping is part of the
// contract: the vectorised and the reference evaluators give the same bits.
struct Expression {
  float a = 0, b = 0, c = 0;  // linear: a x + b y + c
  float d = 0, e = 0, f = 0;  // quadratic: d x^2 + e x y + f y^2
  float t = 0;                // times the stored term
  bool quadratic() const { return d != 0 || e != 0 || f != 0; }
};

// Pixels [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

enum class Evaluator {
  kVector,           // rows of eight pixels per instruction, in GCC vector extensions
  kScalarReference,  // one pixel at a time, plainly; the vectorised evaluator must match it bit for bit
};

struct MachineSettings {
  int width = 512, height = 512;  // screen pixels (> 0); regions cover it in 128 x 128 tiles
  int graphicsProcessors = 1;     // worker threads for both phases (>= 1); results do not depend on it
  Evaluator evaluator = Evaluator::kVector;
  // The graphics processors' output is kept from frame to frame, batch by batch; beyond this many
  // bytes in all, a batch's storage that a frame left more than half spare is freed instead.
  // Frames from different points fill different batches, so without a bound they come to hold
  // the sum of each batch's largest (util/scratch.h).
  size_t scratchBytes = size_t{64} << 20;
};

// Load of one processor in the last frame. Which thread took which work varies between runs;
// the frame totals do not.
struct ProcessorLoad {
  uint64_t tasks = 0;       // primitive batches (graphics processor) or regions (renderer)
  uint64_t primitives = 0;  // set up and sent (graphics processor) or rendered (renderer)
  uint64_t pixelOps = 0;    // pixel-instruction evaluations done by the emulator (renderer)
};

// Readable after a frame; totals are identical for any number of graphics processors.
struct FrameCounters {
  uint64_t primitivesIn = 0;       // the caller's primitives handed to the setup program
  uint64_t primitivesOut = 0;      // set-up primitives emitted (a caller's primitive may give 0..n)
  uint64_t regionPrimitives = 0;   // (primitive, region) pairs: one instruction stream each
  uint64_t instructions = 0;       // instructions broadcast to renderers
  uint64_t ringMessages = 0;       // instruction streams sent over the ring
  uint64_t ringBytes = 0;          // their size, in the emulator's encoding (see README)
  uint64_t machinePixelOps = 0;    // instructions x 16,384: what the real renderers would evaluate
  uint64_t emulatedPixelOps = 0;   // what the emulator evaluated (bounding boxes, rows narrowed)
  uint64_t pixelsWritten = 0;      // depth-test winners
  uint64_t scratchBytes = 0;       // what the graphics processors' output holds after the frame
                                   // for the next (MachineSettings::scratchBytes)
  std::vector<ProcessorLoad> graphicsProcessors, renderers;  // one entry per thread
};

// What a graphics processor's setup program writes into. Not thread-shared: each graphics
// processor has its own.
class Emitter {
 public:
  // Emits a primitive covering the pixels of `bounds` (clipped to the screen) at which every
  // edge expression is >= 0 and the depth expression is greater than the depth plane; those
  // pixels take the depth and `value`. Ties keep the earlier primitive (the caller's order).
  // 1..kMaxEdges edges. Returns false (and emits nothing) when the clipped bounds are empty.
  static constexpr size_t kMaxEdges = 32;
  bool convex(PixelRect bounds, std::span<const Expression> edges, const Expression& depth, uint32_t value);

 private:
  friend class Machine;
  struct Batch;
  Batch* batch_ = nullptr;
};

// The setup program: called on a graphics processor for the caller's primitives [begin, end),
// in order. It must be safe to call concurrently for disjoint ranges.
using SetupProgram = std::function<void(size_t begin, size_t end, Emitter& out)>;

// Called on a renderer as soon as a region's pixels are final, as the real renderers then sent
// them over the ring: the region (clipped to the screen) and the renderer's index in
// [0, graphicsProcessors). It may read the depth and value planes within the region only, and
// must be safe to call concurrently for different regions.
using RegionProgram = std::function<void(PixelRect region, int renderer)>;

class Machine {
 public:
  // Allocates the pixel memory and starts graphicsProcessors - 1 worker threads (the caller's
  // thread is the first). The term plane starts at 0 and the clear-depth plane at 0.
  explicit Machine(const MachineSettings& settings);
  ~Machine();
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  const MachineSettings& settings() const;
  int pixelStride() const;  // >= width, a multiple of 128; planes hold pixelStride() * height values

  // Per-pixel memory the caller loads once and that stays across frames: the stored term the
  // expressions' t multiplies, and the depth each frame starts from. A pixel whose clear depth
  // is +infinity is never written (a permanently disabled processor). Pixels of the stride
  // padding are disabled that way by the machine.
  std::span<float> termPlane();
  std::span<float> clearDepthPlane();

  // Runs one frame: clears depth and values, runs `setup` over [0, primitiveCount) on the
  // graphics processors (batches of `batchSize` primitives, any number per thread), bins, sends
  // and renders, and calls `regionDone` (if given) for every region once it is rendered. Output
  // depends only on the inputs, never on the number of threads. An exception from the setup
  // program (or the emitter, or regionDone) reaches the caller; that frame's planes and
  // counters are then unspecified, and the machine stays usable.
  void renderFrame(size_t primitiveCount, const SetupProgram& setup, size_t batchSize = 256, const RegionProgram& regionDone = {});
  // The same frame within `window` only (a scissor; clipped to the screen): primitives are
  // clipped to it and those wholly outside dropped before binning, only the regions it touches
  // render, and only its pixels are cleared and written, with the values the whole frame would
  // give them; the pixels outside keep what they held. regionDone gets the regions clipped to
  // the window. The counters count what was sent and rendered. An empty window renders nothing.
  void renderFrame(PixelRect window, size_t primitiveCount, const SetupProgram& setup, size_t batchSize = 256,
                   const RegionProgram& regionDone = {});

  // Runs a host program on the graphics processors between frames, as the real machine's i860s
  // ran general code: job(task, processor) for every task in [0, taskCount), taken in order by
  // whichever processor comes free. The first exception a job throws is rethrown here.
  void runOnGraphicsProcessors(size_t taskCount, const std::function<void(size_t task, int processor)>& job);

  // The last frame's result and counters.
  std::span<const float> depthPlane() const;
  std::span<const uint32_t> valuePlane() const;
  const FrameCounters& counters() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace pxpl5

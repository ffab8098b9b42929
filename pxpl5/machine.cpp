// The machine: pixel memory, the two phases of a frame, the ring's bookkeeping.
//
// Sections: Emitter (a graphics processor's output, binning and the ring's counts) | Machine
// state | renderFrame.
#include "pxpl5/batch.h"
#include "pxpl5/evaluator.h"
#include "pxpl5/worker_pool.h"
#include "util/scratch.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace pxpl5 {

// ---- Emitter ------------------------------------------------------------------------------

namespace {

// Bytes of one instruction stream in the emulator's encoding (README): a 16-byte header (bounds
// as four 16-bit coordinates, value, edge count and flags) and each expression's non-zero
// coefficient set (linear with term: 4 floats; quadratic: 7).
uint64_t streamBytes(const SetupPrimitive& p) {
  return 16 + (p.edgeCount + 1) * (p.quadratic ? 28u : 16u);
}

}  // namespace

bool Emitter::convex(PixelRect bounds, std::span<const Expression> edges, const Expression& depth, uint32_t value) {
  if (edges.empty() || edges.size() > kMaxEdges) throw std::invalid_argument("pxpl5: a primitive needs 1 to 32 edges");
  Batch& batch = *batch_;
  const Screen& screen = *batch.screen;
  const PixelRect& clip = batch.clip;
  bounds = {std::max(bounds.x0, clip.x0), std::max(bounds.y0, clip.y0), std::min(bounds.x1, clip.x1), std::min(bounds.y1, clip.y1)};
  if (bounds.empty()) return false;
  const auto index = static_cast<uint32_t>(batch.primitives.size());
  // Whether any of d, e, f is non-zero, on their bits (either zero, the sign bit shifted out):
  // without a branch per coefficient, which took about a quarter of this function's instructions.
  const auto squares = [](const Expression& e) {
    return ((std::bit_cast<uint32_t>(e.d) | std::bit_cast<uint32_t>(e.e) | std::bit_cast<uint32_t>(e.f)) << 1) != 0;
  };
  bool quadratic = squares(depth);
  for (const Expression& e : edges) quadratic |= squares(e);
  const size_t first = quadratic ? batch.quadratic.size() : batch.linear.size();
  batch.primitives.push_back({bounds, static_cast<uint32_t>(first), static_cast<uint32_t>(edges.size()), value, quadratic});
  if (quadratic) {
    batch.quadratic.insert(batch.quadratic.end(), edges.begin(), edges.end());
    batch.quadratic.push_back(depth);
  } else {
    for (const Expression& e : edges) batch.linear.push_back(LinearExpression::of(e));
    batch.linear.push_back(LinearExpression::of(depth));
  }
  // Sort to the regions the bounds touch (the graphics processor's bucket sort).
  for (int ry = bounds.y0 / kRegionSize; ry <= (bounds.y1 - 1) / kRegionSize; ++ry)
    for (int rx = bounds.x0 / kRegionSize; rx <= (bounds.x1 - 1) / kRegionSize; ++rx)
      batch.pairs.emplace_back(static_cast<uint32_t>(ry * screen.regionsX + rx), index);
  return true;
}

// Each (primitive, region) pair is one instruction stream.
void Emitter::Batch::countStreams() {
  const size_t regions = static_cast<size_t>(screen->regionCount());
  instructions = ringBytes = 0;
  regionWork.assign(regions, 0);
  for (size_t r = 0; r < regions; ++r) {
    for (uint32_t i = binStart[r]; i < binStart[r + 1]; ++i) {
      const SetupPrimitive& p = primitives[binned[i]];
      instructions += p.edgeCount + 2;  // enable bounds, edges, depth test and write
      ringBytes += streamBytes(p);
      regionWork[r] += static_cast<uint64_t>(p.bounds.x1 - p.bounds.x0) * static_cast<uint64_t>(p.bounds.y1 - p.bounds.y0);
    }
  }
}

// ---- Machine state -----------------------------------------------------------------------


// One plane of pixel memory, starting `skew` cache lines past a 4 KiB boundary. With a row
// stride of 512 pixels (2 KiB) a region's rows fall into a quarter of the L1 cache's sets; the
// planes, all at the same offset from a page, shared those sets and evicted each other's rows in
// the middle of a primitive (the rows a primitive asks for at once did not fit). Skewed 8 lines
// apart, they use different sets (simulated L1 misses of a 20,000-polygon frame at 512: -30%).
template <class T>
struct Plane {
  std::vector<T> memory;
  std::span<T> pixels;
  void allocate(size_t count, T fill, size_t skew) {
    constexpr size_t kPage = 4096 / sizeof(T), kLine = 64 / sizeof(T);
    memory.assign(count + 2 * kPage, fill);
    const size_t pastPage = reinterpret_cast<uintptr_t>(memory.data()) % 4096 / sizeof(T);
    pixels = std::span(memory).subspan((kPage - pastPage) % kPage + skew * kLine, count);
  }
};

struct Machine::State {
  MachineSettings settings;
  Screen screen;
  WorkerPool pool;
  Plane<float> term, clearDepth, depth;
  Plane<uint32_t> value;
  std::vector<Emitter::Batch> batches;
  std::vector<int> regionOrder;
  std::vector<uint64_t> regionWork;  // bounding-box pixels per region, to hand out the busiest first
  FrameCounters counters;

  explicit State(const MachineSettings& s) : settings(s), pool(s.graphicsProcessors) {}
};

Machine::Machine(const MachineSettings& settings) {
  if (settings.width <= 0 || settings.height <= 0 || settings.graphicsProcessors < 1)
    throw std::invalid_argument("pxpl5: the screen needs a positive size and at least one graphics processor");
  state_ = std::make_unique<State>(settings);
  Screen& s = state_->screen;
  s.width = settings.width;
  s.height = settings.height;
  s.regionsX = (settings.width + kRegionSize - 1) / kRegionSize;
  s.regionsY = (settings.height + kRegionSize - 1) / kRegionSize;
  s.stride = s.regionsX * kRegionSize;
  const size_t pixels = static_cast<size_t>(s.stride) * static_cast<size_t>(s.height);
  state_->term.allocate(pixels, 0.0f, 0);
  state_->depth.allocate(pixels, 0.0f, 8);
  state_->value.allocate(pixels, kNoValue, 16);
  state_->clearDepth.allocate(pixels, 0.0f, 24);
  for (int y = 0; y < s.height; ++y)
    for (int x = s.width; x < s.stride; ++x)
      state_->clearDepth.pixels[static_cast<size_t>(y) * static_cast<size_t>(s.stride) + static_cast<size_t>(x)] = std::numeric_limits<float>::infinity();
  state_->counters.graphicsProcessors.resize(static_cast<size_t>(settings.graphicsProcessors));
  state_->counters.renderers.resize(static_cast<size_t>(settings.graphicsProcessors));
}

Machine::~Machine() = default;

const MachineSettings& Machine::settings() const { return state_->settings; }
int Machine::pixelStride() const { return state_->screen.stride; }
std::span<float> Machine::termPlane() { return state_->term.pixels; }
std::span<float> Machine::clearDepthPlane() { return state_->clearDepth.pixels; }
std::span<const float> Machine::depthPlane() const { return state_->depth.pixels; }
std::span<const uint32_t> Machine::valuePlane() const { return state_->value.pixels; }
const FrameCounters& Machine::counters() const { return state_->counters; }

void Machine::runOnGraphicsProcessors(size_t taskCount, const std::function<void(size_t, int)>& job) {
  state_->pool.run(taskCount, job);
}

// ---- renderFrame ---------------------------------------------------------------------------

void Machine::renderFrame(size_t primitiveCount, const SetupProgram& setup, size_t batchSize, const RegionProgram& regionDone) {
  renderFrame({0, 0, state_->screen.width, state_->screen.height}, primitiveCount, setup, batchSize, regionDone);
}

void Machine::renderFrame(PixelRect window, size_t primitiveCount, const SetupProgram& setup, size_t batchSize,
                          const RegionProgram& regionDone) {
  State& st = *state_;
  const Screen& screen = st.screen;
  window = {std::max(window.x0, 0), std::max(window.y0, 0), std::min(window.x1, screen.width), std::min(window.y1, screen.height)};
  if (window.empty()) window = {};
  FrameCounters& counters = st.counters;
  for (ProcessorLoad& load : counters.graphicsProcessors) load = {};
  for (ProcessorLoad& load : counters.renderers) load = {};

  // Graphics processors: set up, bin and count each batch of the caller's primitives.
  batchSize = std::max<size_t>(batchSize, 1);
  const size_t batchCount = (primitiveCount + batchSize - 1) / batchSize;
  if (st.batches.size() < batchCount) st.batches.resize(batchCount);
  const auto setUpBatch = [&](size_t b, int worker) {
    Emitter::Batch& batch = st.batches[b];
    batch.screen = &screen;
    batch.clip = window;
    batch.clear();
    Emitter emitter;
    emitter.batch_ = &batch;
    const size_t begin = b * batchSize, end = std::min(begin + batchSize, primitiveCount);
    setup(begin, end, emitter);
    batch.groupByRegion();
    batch.countStreams();
    ProcessorLoad& load = counters.graphicsProcessors[static_cast<size_t>(worker)];
    ++load.tasks;
    load.primitives += end - begin;
  };

  // The ring: the batches' instruction streams (one per (primitive, region) pair) added up.
  // Then the renderers' order: the regions the window touches as they come free, the busiest
  // first so that none is left to finish alone.
  const int regions = screen.regionCount();
  std::vector<uint64_t>& regionWork = st.regionWork;
  st.regionOrder.clear();
  for (int r = 0; r < regions && !window.empty(); ++r) {
    const PixelRect region = screen.region(r);
    if (region.x0 < window.x1 && window.x0 < region.x1 && region.y0 < window.y1 && window.y0 < region.y1) st.regionOrder.push_back(r);
  }
  const size_t activeRegions = st.regionOrder.size();
  const auto ringAndOrder = [&] {
    counters.primitivesIn = primitiveCount;
    counters.primitivesOut = counters.regionPrimitives = counters.instructions = counters.ringBytes = 0;
    regionWork.assign(static_cast<size_t>(regions), 0);
    for (size_t b = 0; b < batchCount; ++b) {
      const Emitter::Batch& batch = st.batches[b];
      counters.primitivesOut += batch.primitives.size();
      counters.regionPrimitives += batch.binned.size();
      counters.instructions += batch.instructions;
      counters.ringBytes += batch.ringBytes;
      for (size_t r = 0; r < static_cast<size_t>(regions); ++r) regionWork[r] += batch.regionWork[r];
    }
    counters.ringMessages = counters.regionPrimitives;
    counters.machinePixelOps = counters.instructions * kRegionSize * kRegionSize;
    std::stable_sort(st.regionOrder.begin(), st.regionOrder.end(),
                     [&](int a, int b) { return regionWork[static_cast<size_t>(a)] > regionWork[static_cast<size_t>(b)]; });
  };

  // Renderers: each clears its region and runs the streams in the caller's order.
  const PixelMemory memory{st.depth.pixels.data(), st.value.pixels.data(), st.term.pixels.data(), screen.stride};
  const bool reference = st.settings.evaluator == Evaluator::kScalarReference;
  std::vector<EvaluatorStats> stats(st.counters.renderers.size());
  const auto renderRegion = [&](size_t task, int worker) {
    const int r = st.regionOrder[task];
    const PixelRect whole = screen.region(r);
    const PixelRect region{std::max(whole.x0, window.x0), std::max(whole.y0, window.y0), std::min(whole.x1, window.x1),
                           std::min(whole.y1, window.y1)};
    for (int y = region.y0; y < region.y1; ++y) {
      const size_t row = static_cast<size_t>(y) * static_cast<size_t>(screen.stride) + static_cast<size_t>(region.x0);
      const size_t n = static_cast<size_t>(region.x1 - region.x0);
      std::memcpy(&st.depth.pixels[row], &st.clearDepth.pixels[row], n * sizeof(float));
      std::fill_n(&st.value.pixels[row], n, kNoValue);
    }
    ProcessorLoad& load = counters.renderers[static_cast<size_t>(worker)];
    EvaluatorStats& s = stats[static_cast<size_t>(worker)];
    ++load.tasks;
    const uint64_t opsBefore = s.pixelOps;
    for (size_t b = 0; b < batchCount; ++b) {
      const Emitter::Batch& batch = st.batches[b];
      for (uint32_t i = batch.binStart[static_cast<size_t>(r)]; i < batch.binStart[static_cast<size_t>(r) + 1]; ++i) {
        const SetupPrimitive& p = batch.primitives[batch.binned[i]];
        const PixelRect area{std::max(p.bounds.x0, region.x0), std::max(p.bounds.y0, region.y0), std::min(p.bounds.x1, region.x1),
                             std::min(p.bounds.y1, region.y1)};
        const PrimitiveExpressions expressions = p.quadratic ? PrimitiveExpressions{nullptr, batch.quadratic.data() + p.first}
                                                             : PrimitiveExpressions{batch.linear.data() + p.first, nullptr};
        if (reference)
          evaluateReference(p, expressions, area, memory, s);
        else
          evaluateVector(p, expressions, area, memory, s);
        ++load.primitives;
      }
    }
    load.pixelOps += s.pixelOps - opsBefore;
    if (regionDone) regionDone(region, worker);
  };

  // Both phases in one run of the pool: tasks [0, batchCount) set up batches, the rest render
  // regions. Whoever finishes the last batch adds up the ring and orders the regions; a region
  // task taken before that waits for it, at most as long as the other processor's last batch
  // (tasks are taken in order). A phase of its own cost a hand-over per frame: waking a sleeping
  // worker took 20 to 50 us. `ready`: 0 while batches run, 1 when regions may render, 2 when a
  // batch failed (the pool then rethrows its exception; a waiting renderer gives up).
  std::atomic<size_t> batchesDone{0};
  std::atomic<int> ready{0};
  if (batchCount == 0) ringAndOrder(), ready.store(1);
  st.pool.run(batchCount + activeRegions, [&](size_t task, int worker) {
    if (task < batchCount) {
      try {
        setUpBatch(task, worker);
        if (batchesDone.fetch_add(1, std::memory_order_acq_rel) + 1 == batchCount) ringAndOrder(), ready.store(1, std::memory_order_release);
      } catch (...) {
        ready.store(2, std::memory_order_release);
        ready.notify_all();
        throw;
      }
      if (ready.load(std::memory_order_relaxed) == 1) ready.notify_all();
      return;
    }
    int state = ready.load(std::memory_order_acquire);
    while (state == 0) {
      ready.wait(0, std::memory_order_acquire);
      state = ready.load(std::memory_order_acquire);
    }
    if (state == 1) renderRegion(task - batchCount, worker);
  });
  counters.emulatedPixelOps = counters.pixelsWritten = 0;
  for (const EvaluatorStats& s : stats) {
    counters.emulatedPixelOps += s.pixelOps;
    counters.pixelsWritten += s.written;
  }
  // The batches' storage stays for the next frame, within a bound.
  counters.scratchBytes = util::releaseSpareBeyond(st.batches, st.settings.scratchBytes);
}

}  // namespace pxpl5

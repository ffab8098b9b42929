// Progressive-refinement shooting (Cohen, Chen, Wallace, Greenberg 1988).
//
// Sections: setup | receivers of one shot | Solver.
//
// One shot of patch p with unshot radiance dB (area A_p): a hemisphere frame at p's centre gives
// the form factor F_pj to every element j by pixel counts, then two kinds of receiver get better
// factors:
//  - Near receivers (closer than nearFieldRatio x p's radius): the centre's factor is off by
//    about (radius / distance)^2, 20% for two unit squares a unit apart. Their factor is
//    integrated over p's area (near_field.h: clusters of p's elements far for their size count
//    by a few points, elements close by are split until each piece is small for its distance),
//    times their visibility from the centre's frame.
//  - Small receivers (factor under smallReceiverPixels pixels): a pixel is either wholly theirs
//    or not, so their count is off by up to a pixel, which for a tiny element is all of it. Their
//    factor is the analytic one from the centre (form_factors.h: Lambert's formula, or the
//    receiver's Gauss rule when it is far for its size) times their visibility read from the item
//    buffer at a few points. This is what lets elements of very different areas sit side by
//    side (the UNC program's failure, thesis chapter 6): a small element gets the light its
//    solid angle says, not a random number of pixels.
// The new factors differ from the pixel counts they replace by some total D. The frame saw
// every direction once (pixel weights sum to 1), so energy is kept by taking D from everything
// else the centre saw, the sky included, in proportion: the shot's factors plus what escapes
// still sum to 1. (Where the rest is too small for that, everything is scaled to sum to 1.)
// Each receiver j whose front faces the shooter then gets dB_j = rho_j dB F_pj A_p / A_j: the
// reciprocity relation F_jp = F_pj A_p / A_j turns the shooter's factor into the receiver's
// (leaving out A_p / A_j is the UNC program's other failure). dB_j is added to j's radiance and,
// as unshot light, to j's patch, weighted by j's share of the patch's area. With
// SolverSettings::overshoot, dB also holds what p will reflect of the unshot light its frame
// sees (overshoot.h), and p is left with that much negative unshot light.
#include "radiosity/radiosity.h"

#include "radiosity/ambient.h"
#include "radiosity/form_factors.h"
#include "radiosity/item_buffer.h"
#include "radiosity/near_field.h"
#include "radiosity/overshoot.h"
#include "radiosity/windowed_correction.h"

#include "pxpl5/hemisphere.h"
#include "util/check.h"
#include "util/scratch.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <map>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace radiosity {

namespace {

constexpr double kPi = std::numbers::pi;
// Every shot and every take-back moves light from ledger to ledger and loses none: what is left
// is rounding (debug builds check it after each step).
constexpr double kLedgerTolerance = 1e-9;

double channelSum(const glm::dvec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// A shooter's centre that sees more than this share of backs is inside a solid (choosePoint).
constexpr double kMostBacks = 0.25;

// A visibility ratio of pixels to the analytic factor this close to 1 is an unoccluded receiver
// whose pixel count is a little short (its edges cut pixels), not a shadow.
constexpr double kUnoccludedRatio = 0.95;

bool insideConvex(const Polygon3& p, const glm::dvec3& normal, const glm::dvec3& q) {
  for (int k = 0; k < p.n; ++k) {
    const glm::dvec3 a = p.v[k], b = p.v[(k + 1) % p.n];
    const double scale = glm::length(b - a) * glm::length(q - a);
    if (glm::dot(glm::cross(b - a, q - a), normal) < -1e-12 * scale) return false;
  }
  return true;
}

}  // namespace

struct Solver::State {
  SolverSettings settings;
  pxpl5::HemisphereRenderer renderer;

  struct SurfaceData {
    uint32_t firstElement = 0, elementCount = 0;
    uint32_t firstPatch = 0, patchCount = 0;
    glm::dvec3 reflectance{0}, emission{0};
    std::vector<std::array<uint32_t, 4>> corners;
    size_t vertexCount = 0;
    // As given: the elements' shooting patches before any split, and their keys (Surface).
    std::vector<uint32_t> patchOfElement;
    std::vector<uint64_t> keys;
    uint64_t keyOf(uint32_t element) const { return keys.empty() ? element : keys[element]; }
  };
  std::vector<SurfaceData> surfaces;
  // Per surface, its unit normal: every element's (normalOf), so held once, and apart from the
  // rest for the loops over every element.
  std::vector<glm::dvec3> surfaceNormal;

  // Per element (global index = the pxpl5 polygon index and id). Its Receiver (form_factors.h,
  // 320 bytes, mostly copies of the arrays below) is made when it is judged (receiverOf): only
  // its polygon and its Gauss rule's weights are held, the weights because they are the costly
  // part of the rule and most elements are judged, as small receivers, by most shots.
  std::vector<Polygon3> polygon;
  std::vector<std::array<double, 4>> ruleWeight;
  std::vector<glm::dvec3> centre, radiance;
  const glm::dvec3& normalOf(uint32_t j) const { return surfaceNormal[surfaceOf[j]]; }
  ElementPlanes planes() const { return {surfaceNormal, offset, surfaceOf}; }
  std::vector<glm::dvec3> elementUnshot;  // per element; its patch's unshot is their area-weighted mean
  // Per element, what it has shot along this geometry, so that a take-back after an edit
  // (Solver::edit) sends back exactly what the shots sent, however unevenly the patch's elements
  // were lit each time and however each shot's energy was kept (distribute): the radiance sent,
  // and the same weighed by each shot's scale of its judged receivers (near ones integrate over
  // the patch element by element). A patch's is its elements' area-weighted mean. Only the
  // elements of patches that have shot have sent anything: their records are held apart, and an
  // element without one (sentAt kNone) has sent nothing.
  struct Sent {
    glm::dvec3 light{0}, judged{0};
  };
  std::vector<uint32_t> sentAt;  // per element: its record in sentRecords, or kNone
  std::vector<Sent> sentRecords;
  Sent sentOf(uint32_t e) const { return sentAt[e] == kNone ? Sent{} : sentRecords[sentAt[e]]; }
  Sent& sentRecord(uint32_t e) {
    if (sentAt[e] == kNone) sentAt[e] = static_cast<uint32_t>(sentRecords.size()), sentRecords.emplace_back();
    return sentRecords[sentAt[e]];
  }
  std::vector<double> radius, area, offset;
  std::vector<uint32_t> surfaceOf, patchOf;
  // Where the item buffer is read for element j's visibility: its centroid, then the points a
  // quarter of the way in from its corners. Made when read (few elements are), not held.
  static constexpr size_t kTargets = 5;
  std::array<glm::dvec3, kTargets> targetsOf(uint32_t j) const {
    const Polygon3& p = polygon[j];
    std::array<glm::dvec3, kTargets> out;
    out[0] = centre[j];
    for (int k = 0; k < 4; ++k) out[1 + k] = p.v[k % p.n] + 0.25 * (centre[j] - p.v[k % p.n]);
    return out;
  }
  // Element j as makeReceiver made it when the solver took it.
  Receiver receiverOf(uint32_t j) const {
    Receiver r;
    r.polygon = polygon[j];
    r.centre = centre[j];
    r.radius = radius[j];
    r.normal = normalOf(j);
    r.offset = offset[j];
    r.area = area[j];
    r.lanes = gaussLanes(polygon[j], ruleWeight[j]);
    return r;
  }

  // Per patch; its elements are patchElements[patchFirst[p], patchLast[p]).
  std::vector<uint32_t> patchElements, patchFirst, patchLast, patchSurface;
  std::vector<glm::dvec3> patchCentre, unshot;
  std::vector<double> patchArea, patchRadius;
  std::vector<uint8_t> pointChosen;  // patchCentre[p] checked for seeing fronts (see choosePoint)
  // The share of backs patchCentre[p] saw when choosePoint chose it, else NaN: a window
  // correction updates it by what changed in its window (Solver::frameInWindow).
  std::vector<double> pointBackShare;
  // The energy scales of a frame (distribute): of its pixel factors, of its judged ones.
  struct FrameScale {
    glm::dvec3 pixels{1}, judged{1};
  };
  FrameScale lastScale;  // of the last distribute
  // A take-back's weighing of a frame (distribute): its judged receivers' factors by `judged`,
  // its pixel receivers' and the sky's by what makes the whole send `total` (per channel): for a
  // patch's record, what each of its shots sent there.
  struct Replay {
    glm::dvec3 total{0}, judged{0};
  };
  // Per patch, its tree over its elements (near_field.h), in patchElements' order: only a patch
  // that shoots (or is split, or corrected) reads it, and a tree is about twice the rest of its
  // patch's elements' state, so it is held from the first time it is needed (treeOf). Null: not
  // made yet.
  std::vector<std::unique_ptr<PatchTree>> trees;
  // Patch p's tree, made now if it is not yet: from its elements in ascending order, the order
  // setUpPatch had them in when it ordered them by the tree it dropped, which makes the same
  // tree and the same order. Not on several threads at once.
  const PatchTree& treeOf(uint32_t p);
  ElementShapes shapes() const { return {polygon, centre, area}; }
  // Scratch: the elements of the patch whose receivers are judged, as receivers in its tree's
  // order (planPatchToReceiver's pieces).
  std::vector<Receiver> pieces;
  // Makes patch p's tree and pieces, which the graphics processors read as they judge its
  // receivers.
  void readyToJudge(uint32_t p) {
    treeOf(p);
    pieces.clear();
    for (uint32_t e : elementsOf(p)) pieces.push_back(receiverOf(e));
  }

  std::vector<glm::vec3> soupVertices;
  std::vector<pxpl5::Polygon> soupPolygons;

  // Scratch of one shot, sized once.
  std::vector<double> pixelFactor;
  std::vector<uint8_t> replaced;
  struct NewFactor {
    uint32_t element;
    glm::dvec3 front, back;  // per channel
  };
  // What judging a near or small receiver found that does not depend on the light: a small one's
  // factor, a near one's visibility from the centre. A near one that is seen, or whose front the
  // centre cannot tell about, gets its factor by an integral over the shooter, planned once
  // (near_field.h) and weighed by the light in every shot: the plans are kept beside the judged
  // receivers, one per such receiver, in their order.
  struct Judged {
    enum Kind : uint32_t { kSmallFront, kNear, kNearBehind };
    uint32_t element;
    Kind kind;
    double value;
    bool integrated() const { return kind == kNearBehind || (kind == kNear && value > 0); }
  };
  std::vector<glm::dvec3> shares, sending;
  std::vector<NodeLight> nodeLight;
  // The receivers of a shot are judged in a fixed number of chunks, whatever the number of
  // graphics processors, and added up in chunk order: the same sums with any thread count. Many
  // small chunks, because a shot's near receivers (most of the work) sit together in element
  // order: taken by two processors, 16 chunks left the office's receiver work 19% longer than
  // half of it, 256 leave it 5% longer.
  static constexpr size_t kReceiverChunks = 256;
  // Receivers judged, with the plans of their integrals (judgeReceivers). What it holds for the
  // next shot, and giving back what this one left spare: util/scratch.h, SolverSettings::scratchBytes.
  struct Judgement {
    std::vector<Judged> judged;
    NearPlans plans;
    // Entries in each list, and the bytes they take.
    struct Counts {
      uint32_t judged = 0, plans = 0, steps = 0, factors = 0;
      Counts operator+(const Counts& o) const { return {judged + o.judged, plans + o.plans, steps + o.steps, factors + o.factors}; }
      size_t bytes() const {
        return judged * sizeof(Judged) + plans * sizeof(NearPlanSize) + steps * sizeof(NearStep) + factors * sizeof(glm::dvec2);
      }
    };
    Counts counts() const {
      return {static_cast<uint32_t>(judged.size()), static_cast<uint32_t>(plans.sizes.size()),
              static_cast<uint32_t>(plans.steps.size()), static_cast<uint32_t>(plans.factors.size())};
    }
    NearPlansView plansView() const { return {plans.steps, plans.factors, plans.sizes}; }
    void clear() {
      judged.clear();
      plans.steps.clear();
      plans.factors.clear();
      plans.sizes.clear();
    }
    size_t heldBytes() const { return util::heldBytes(judged, plans.steps, plans.factors, plans.sizes); }
    void releaseSpare() { util::releaseSpare(judged, plans.steps, plans.factors, plans.sizes); }
  };
  struct ReceiverChunk {
    // Held to the end of a shot that may be kept (keepShot copies it); empty in another shot,
    // which judges the chunk in its graphics processor's `judging`.
    Judgement judgement;
    std::vector<NewFactor> factors;
    double replacedPixels = 0;
    glm::dvec3 replacedNew{0};
    uint64_t near = 0, small = 0;
    size_t heldBytes() const { return judgement.heldBytes() + util::heldBytes(factors); }
    void releaseSpare() { judgement.releaseSpare(), util::releaseSpare(factors); }
  };
  std::array<ReceiverChunk, kReceiverChunks> chunks;
  // Per graphics processor, the judgement of the chunk it integrates in a shot that will not be
  // kept, dropped once integrated: a building's shot from a patch that sees most of it near held
  // 550 MB of plans in its chunks at once.
  std::vector<Judgement> judging;

  // Per patch, its first shot's pixel factors, judged receivers and their plans, chunk by chunk
  // (SolverSettings::shotCacheBytes); none kept while chunkStart is empty.
  struct KeptShot {
    std::vector<pxpl5::IdFactor> factors;
    double total = 0;
    std::vector<Judged> judged;
    NearPlans plans;
    using ChunkStart = Judgement::Counts;
    std::vector<ChunkStart> chunkStart;  // kReceiverChunks + 1 offsets into `judged` and `plans`
    static size_t bytesFor(size_t factors, const ChunkStart& end) {
      return factors * sizeof(pxpl5::IdFactor) + end.bytes() + (kReceiverChunks + 1) * sizeof(ChunkStart);
    }
    size_t bytes() const { return chunkStart.empty() ? 0 : bytesFor(factors.size(), chunkStart.back()); }
    // Chunk c's judged receivers and their plans.
    std::span<const Judged> judgedOf(size_t c) const {
      return std::span(judged).subspan(chunkStart[c].judged, chunkStart[c + 1].judged - chunkStart[c].judged);
    }
    NearPlansView plansOf(size_t c) const {
      const ChunkStart &from = chunkStart[c], &to = chunkStart[c + 1];
      return {std::span(plans.steps).subspan(from.steps, to.steps - from.steps),
              std::span(plans.factors).subspan(from.factors, to.factors - from.factors),
              std::span(plans.sizes).subspan(from.plans, to.plans - from.plans)};
    }
  };
  std::vector<std::unique_ptr<KeptShot>> keptShots;  // per patch; null: none kept
  size_t keptBytes = 0;

  double pixelShare = 0;  // the form factor of one disk pixel, from the first frame
  Stats stats;

  explicit State(const SolverSettings& s)
      : settings(s),
        renderer(pxpl5::HemisphereSettings{s.resolution, pxpl5::Projection::kHemisphere, s.graphicsProcessors}),
        judging(static_cast<size_t>(renderer.settings().graphicsProcessors)) {}

  // The elements and patches of `input`'s surfaces; in an edit, those `input` leaves null are
  // `kept`'s (the state before), as they were given to it.
  void build(std::span<const Surface* const> input, const State* kept = nullptr);
  double visibility(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye, uint32_t j,
                    double unoccluded) const;
  // The near and small receivers among elements [begin, end) of shooter p's frame judged (see
  // shoot), with the plans of the near ones' integrals, into `into`, their counts into `out`
  // (integrateJudged gives their factors).
  void judgeReceivers(uint32_t p, const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, uint32_t begin,
                      uint32_t end, ReceiverChunk& out, Judgement& into);
  // The same from receivers judged before and their plans (a kept shot's chunk).
  void rejudgeReceivers(uint32_t p, std::span<const Judged> judged, const NearPlansView& plans, ReceiverChunk& out);
  // Judged receivers' factors into out.factors and out.replacedNew, the near ones' integrals by
  // their plans in p's light (nodeLight).
  void integrateJudged(uint32_t p, std::span<const Judged> judged, const NearPlansView& plans, ReceiverChunk& out);
  // Patch p's kept shot, or null.
  const KeptShot* keptShot(uint32_t p) const {
    return p < keptShots.size() && pointChosen[p] ? keptShots[p].get() : nullptr;
  }
  // Before patch p's first shot from `frame` is judged: the bytes its judgements may take with
  // the shot still kept (its point is chosen, it has none yet; the budget and the bound of a
  // record less its frame's factors), or nothing when it is not to be kept.
  std::optional<size_t> keepRoom(uint32_t p, const pxpl5::HemisphereFrame& frame) const;
  // The record for keeping the shot just judged, whose judgements the chunks hold, sized;
  // keepShot fills and stores it.
  KeptShot shotToKeep() const;
  void keepShot(uint32_t p, const pxpl5::HemisphereFrame& frame, KeptShot& record);
  void storeShot(uint32_t p, KeptShot record);
  double backShare(const pxpl5::HemisphereFrame& frame, const glm::dvec3& eye) const;
  std::span<uint32_t> elementsOf(uint32_t p) {
    return {patchElements.data() + patchFirst[p], patchLast[p] - patchFirst[p]};
  }
  std::span<const uint32_t> elementsOf(uint32_t p) const {
    return {patchElements.data() + patchFirst[p], patchLast[p] - patchFirst[p]};
  }
  // `ordered`: p's elements in the order its tree puts them, when known (a patch of a surface no
  // edit named, from the state before), so that no tree is built to find it.
  void setUpPatch(uint32_t p, uint32_t first, uint32_t last, std::span<const uint32_t> ordered = {});
  const pxpl5::HemisphereFrame& frameFrom(uint32_t p, const glm::dvec3& point);
  const pxpl5::HemisphereFrame* choosePoint(uint32_t p);
  // Takes a point already checked (by an earlier state, or a correction's frame) as patch p's.
  void adoptPoint(uint32_t p, const glm::dvec3& point, double pointRadius, double backs) {
    pointChosen[p] = 1;
    patchCentre[p] = point;
    patchRadius[p] = pointRadius;
    pointBackShare[p] = backs;
  }
  void split(uint32_t p);
  // Lights patch p's tree for sending radiance dB (per channel) as radiance `light` from its
  // elements (in elementsOf's order; their area-weighted mean is dB): their shares into `shares`
  // and its tree. In a channel where dB is zero the shares are the elements' areas'.
  void lightPatch(uint32_t p, const glm::dvec3& dB, std::span<const glm::dvec3> light);
  // What patch p has sent along this geometry (its elements', area-weighted).
  Sent sentBy(uint32_t p) const {
    Sent sum;
    for (uint32_t e : elementsOf(p)) {
      const Sent own = sentOf(e);
      sum.light += area[e] * own.light;
      sum.judged += area[e] * own.judged;
    }
    return {sum.light / patchArea[p], sum.judged / patchArea[p]};
  }
  // Adds to the elements' Sent that patch p sent `light` (per element of p, in elementsOf's
  // order) in the last distribute.
  void recordSent(uint32_t p, std::span<const glm::dvec3> light) {
    const std::span<const uint32_t> own = elementsOf(p);
    for (size_t k = 0; k < own.size(); ++k) {
      Sent& record = sentRecord(own[k]);
      record.light += light[k];
      record.judged += light[k] * lastScale.judged;
    }
  }
  void shoot(uint32_t p, const pxpl5::HemisphereFrame* chosen);
  // Sends radiance dB from patch p along this geometry's form factors, its elements weighted by
  // `shares` (lit into its tree), from its kept shot, `chosen` or a new frame at its centre:
  // deposit(j, front, back) per receiver (factors per channel); returns the share that escaped,
  // per channel. The factors are scaled to keep the frame's energy (lastScale), or as `replay`
  // says when given (a take-back: the factors then carry the radiance, dB is 1).
  template <typename Deposit>
  glm::dvec3 distribute(uint32_t p, const pxpl5::HemisphereFrame* chosen, const Deposit& deposit,
                        const Replay* replay = nullptr);
  // Radiance dB sent from `sourceArea` reaching element j with these factors: the reflected part
  // into j's radiance, its unshot light and its patch's, the rest into the power ledgers.
  void receive(uint32_t j, double sourceArea, const glm::dvec3& dB, const glm::dvec3& front, const glm::dvec3& back);
  // The scene's element and patch spheres, for windowed_correction.h.
  SceneSpheres spheres() const {
    return {centre, radius, surfaceOf, patchCentre, patchRadius, patchFirst, patchLast, patchElements};
  }
};

// ---- setup -----------------------------------------------------------------------------------

namespace {

// A given surface's own checks (the constructor's contract), before anything is built from it.
void checkSurface(const Surface& in, const std::string& where) {
  if (!in.patchOfElement.empty() && in.patchOfElement.size() != in.elements.size())
    throw std::invalid_argument(where + ": patchOfElement has the wrong size");
  if (in.keys.empty()) return;
  if (in.keys.size() != in.elements.size()) throw std::invalid_argument(where + ": keys has the wrong size");
  std::vector<uint64_t> sorted = in.keys;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) throw std::invalid_argument(where + ": a key given twice");
}

}  // namespace

void Solver::State::build(std::span<const Surface* const> input, const State* kept) {
  size_t elementTotal = 0;
  for (size_t si = 0; si < input.size(); ++si) elementTotal += input[si] ? input[si]->elements.size() : kept->surfaces[si].elementCount;
  // Every array to its size at once: grown by doubling, they held up to twice the elements'
  // state, and more while they moved.
  surfaces.reserve(input.size());
  surfaceNormal.reserve(input.size());
  polygon.reserve(elementTotal);
  ruleWeight.reserve(elementTotal);
  for (auto* v : {&centre, &radiance, &elementUnshot}) v->reserve(elementTotal);
  sentAt.reserve(elementTotal);
  for (auto* v : {&radius, &area, &offset}) v->reserve(elementTotal);
  for (auto* v : {&surfaceOf, &patchOf, &patchElements}) v->reserve(elementTotal);
  soupVertices.reserve(elementTotal * 4);
  soupPolygons.reserve(elementTotal);

  std::vector<std::vector<uint32_t>> members;  // per global patch, its elements
  std::vector<std::pair<uint32_t, uint32_t>> patchBefore;  // a kept surface's patches: (now, in `kept`)
  for (size_t si = 0; si < input.size(); ++si) {
    const Surface* in = input[si];
    const std::string where = "radiosity::Solver: surface " + std::to_string(si);
    SurfaceData& s = surfaces.emplace_back();
    if (in) {
      checkSurface(*in, where);
      surfaceNormal.push_back(glm::normalize(in->normal));
      s.reflectance = glm::clamp(in->reflectance, 0.0, 1.0);
      s.emission = in->emission;
      s.corners = in->elements;
      s.vertexCount = in->vertices.size();
      s.patchOfElement = in->patchOfElement;
      s.keys = in->keys;
    } else {
      s = kept->surfaces[si];
      surfaceNormal.push_back(kept->surfaceNormal[si]);
    }
    s.firstElement = static_cast<uint32_t>(polygon.size());
    s.elementCount = static_cast<uint32_t>(s.corners.size());
    s.firstPatch = static_cast<uint32_t>(members.size());
    uint32_t patches = 0;
    for (uint32_t e = 0; e < s.elementCount; ++e) {
      Receiver r;
      if (in) {
        const std::array<uint32_t, 4>& c = in->elements[e];
        Polygon3 p;
        p.n = c[3] == kNone ? 3 : 4;
        for (int k = 0; k < p.n; ++k) {
          if (c[k] >= in->vertices.size())
            throw std::invalid_argument(where + ", element " + std::to_string(e) + ": corner index out of range");
          p.v[k] = in->vertices[c[k]];
        }
        r = makeReceiver(p, surfaceNormal[si]);
        if (!(r.area > 0)) throw std::invalid_argument(where + ", element " + std::to_string(e) + ": zero area");
      } else {
        r = kept->receiverOf(kept->surfaces[si].firstElement + e);  // a surface no edit named
      }
      const Polygon3& p = r.polygon;
      const auto j = static_cast<uint32_t>(polygon.size());
      polygon.push_back(p);
      ruleWeight.push_back({r.lanes.weight[0], r.lanes.weight[1], r.lanes.weight[2], r.lanes.weight[3]});
      centre.push_back(r.centre);
      offset.push_back(r.offset);
      radius.push_back(r.radius);
      area.push_back(r.area);
      surfaceOf.push_back(static_cast<uint32_t>(si));
      radiance.push_back(s.emission);
      elementUnshot.push_back(s.emission);
      sentAt.push_back(kNone);
      const uint32_t local = s.patchOfElement.empty() ? e : s.patchOfElement[e];
      patches = std::max(patches, local + 1);
      if (members.size() < s.firstPatch + patches) members.resize(s.firstPatch + patches);
      members[s.firstPatch + local].push_back(j);
      patchOf.push_back(s.firstPatch + local);
      soupPolygons.push_back({static_cast<uint32_t>(soupVertices.size()), static_cast<uint32_t>(p.n), j});
      for (int k = 0; k < p.n; ++k) soupVertices.emplace_back(p.v[k]);
    }
    s.patchCount = patches;
    if (!in)
      for (uint32_t l = 0; l < patches; ++l) patchBefore.emplace_back(s.firstPatch + l, kept->surfaces[si].firstPatch + l);
  }

  for (auto* v : {&patchFirst, &patchLast, &patchSurface}) v->reserve(members.size());
  for (auto* v : {&patchCentre, &unshot}) v->reserve(members.size());
  for (auto* v : {&patchArea, &patchRadius, &pointBackShare}) v->reserve(members.size());
  pointChosen.reserve(members.size());
  trees.reserve(members.size());
  std::vector<uint32_t> ordered;
  auto before = patchBefore.begin();
  for (size_t p = 0; p < members.size(); ++p) {
    if (members[p].empty())
      throw std::invalid_argument("radiosity::Solver: patch " + std::to_string(p) + " has no elements");
    const auto first = static_cast<uint32_t>(patchElements.size());
    patchElements.insert(patchElements.end(), members[p].begin(), members[p].end());
    // A kept surface's patch that was not split (splitting only takes elements away) has its
    // elements as before, ordered as before, moved by the surface's new first element.
    ordered.clear();
    if (before != patchBefore.end() && before->first == p) {
      const uint32_t q = (before++)->second, si = surfaceOf[members[p].front()];
      if (kept->elementsOf(q).size() == members[p].size())
        for (uint32_t e : kept->elementsOf(q))
          ordered.push_back(e - kept->surfaces[si].firstElement + surfaces[si].firstElement);
    }
    setUpPatch(static_cast<uint32_t>(p), first, static_cast<uint32_t>(patchElements.size()), ordered);
    stats.emittedPower += kPi * surfaces[patchSurface[p]].emission * patchArea[p];
  }
  pixelFactor.assign(polygon.size(), 0.0);
  replaced.assign(polygon.size(), 0);
}

// Makes patch p (a new one when p is the patch count) of patchElements[first, last): its area,
// the centre it shoots from, its radius, its tree, its unshot light (its elements' area-weighted
// mean).
void Solver::State::setUpPatch(uint32_t p, uint32_t first, uint32_t last, std::span<const uint32_t> ordered) {
  if (p == unshot.size()) {
    for (auto* v : {&patchFirst, &patchLast, &patchSurface}) v->emplace_back();
    for (auto* v : {&patchCentre, &unshot}) v->emplace_back(0.0);
    for (auto* v : {&patchArea, &patchRadius}) v->emplace_back();
    pointChosen.emplace_back();
    pointBackShare.emplace_back();
    trees.emplace_back();
  }
  if (p < keptShots.size() && keptShots[p]) keptBytes -= keptShots[p]->bytes(), keptShots[p].reset();
  patchFirst[p] = first;
  patchLast[p] = last;
  const std::span<uint32_t> own = elementsOf(p);
  double a = 0;
  glm::dvec3 c{0}, light{0};
  for (uint32_t e : own) a += area[e], c += area[e] * centre[e], light += area[e] * elementUnshot[e];
  c /= a;
  // A patch bent around a hole may have its centroid outside itself: shoot from its element
  // nearest the centroid instead.
  bool inside = false;
  for (uint32_t e : own) inside = inside || insideConvex(polygon[e], normalOf(e), c);
  if (!inside) {
    uint32_t nearest = own.front();
    for (uint32_t e : own)
      if (glm::length(centre[e] - c) < glm::length(centre[nearest] - c)) nearest = e;
    c = centre[nearest];
  }
  double r = 0;
  for (uint32_t e : own)
    for (int k = 0; k < polygon[e].n; ++k) r = std::max(r, glm::length(polygon[e].v[k] - c));
  for (uint32_t e : own) patchOf[e] = p;
  patchSurface[p] = surfaceOf[own.front()];
  patchArea[p] = a;
  patchCentre[p] = c;
  patchRadius[p] = r;
  unshot[p] = light / a;
  pointChosen[p] = 0;
  pointBackShare[p] = std::numeric_limits<double>::quiet_NaN();
  // The tree orders the patch's elements now (sums over them follow that order). Given in
  // ascending order, as build() gives them, it can be made again alike when needed, so it is
  // not held; a split's parts (in their parent's tree's order) keep theirs.
  const bool ascending = std::is_sorted(own.begin(), own.end());
  const HemisphereAxes axes = hemisphereAxes(glm::vec3(surfaceNormal[patchSurface[p]]));
  if (!ordered.empty()) {
    const auto treeOrder = [&] {
      std::vector<uint32_t> order(own.begin(), own.end());
      buildPatchTree(order, shapes(), axes.x, axes.y);
      return order;
    };
    DCHECK(ascending && std::ranges::equal(treeOrder(), ordered));
    std::copy(ordered.begin(), ordered.end(), own.begin());
    trees[p] = nullptr;
    return;
  }
  PatchTree tree = buildPatchTree(own, shapes(), axes.x, axes.y);
  ++stats.patchTrees;
  trees[p] = ascending ? nullptr : std::make_unique<PatchTree>(std::move(tree));
}

const PatchTree& Solver::State::treeOf(uint32_t p) {
  if (!trees[p]) {
    std::vector<uint32_t> given(elementsOf(p).begin(), elementsOf(p).end());
    std::sort(given.begin(), given.end());
    const HemisphereAxes axes = hemisphereAxes(glm::vec3(surfaceNormal[patchSurface[p]]));
    trees[p] = std::make_unique<PatchTree>(buildPatchTree(given, shapes(), axes.x, axes.y));
    ++stats.patchTrees;
    DCHECK(std::equal(given.begin(), given.end(), elementsOf(p).begin()));
  }
  return *trees[p];
}

// ---- receivers of one shot ---------------------------------------------------------------------

// Visibility of element j from the frame's centre, where j's unoccluded factor from there is
// `unoccluded`: the pixel count over that where j is big enough to own pixels, else the item
// buffer at its targets.
double Solver::State::visibility(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye,
                                 uint32_t j, double unoccluded) const {
  if (unoccluded >= settings.smallReceiverPixels * pixelShare) {
    const double ratio = pixelFactor[j] / unoccluded;
    return ratio >= kUnoccludedRatio ? 1.0 : ratio;
  }
  // A receiver smaller than a pixel would read the pixel of its centroid at the other points too.
  const size_t count = unoccluded < pixelShare ? 1 : 1 + static_cast<size_t>(polygon[j].n);
  const std::array<glm::dvec3, kTargets> targets = targetsOf(j);
  return itemBufferVisibility(frame, axes, eye, {targets.data(), count}, j, planes());
}

double Solver::State::backShare(const pxpl5::HemisphereFrame& frame, const glm::dvec3& eye) const {
  double back = 0;
  for (const pxpl5::IdFactor& f : frame.factors)
    if (glm::dot(normalOf(f.id), eye) <= offset[f.id]) back += f.factor;
  return back;
}

// Surfaces are one-sided and a solid's faces face out, so a point that sees mostly backs of
// faces is inside a solid: the part of a floor element or patch under a box standing on it.
// That part is dark (nothing reaches it) while the light came in on the open part, so shooting
// from inside would hand all of it to backs. The first time a patch is to shoot, its centre is
// checked. A patch of several elements whose centre sees more than a quarter backs (it is partly
// under a box) has no one point that sees what all of it does: it is split, and its parts are
// checked when they are to shoot. A single element's centre is replaced by the point a third of
// the way in from one of its corners that sees the fewest backs. The geometry does not change,
// so the choice is kept. Returns the frame from the chosen point when it is the renderer's last
// (the shot's own frame), else null; pointChosen[p] is not set when p was split.
const pxpl5::HemisphereFrame* Solver::State::choosePoint(uint32_t p) {
  const pxpl5::HemisphereFrame& centreFrame = frameFrom(p, patchCentre[p]);
  double best = backShare(centreFrame, patchCentre[p]);
  if (best <= kMostBacks) {
    pointChosen[p] = 1;
    pointBackShare[p] = best;
    return &centreFrame;
  }
  if (elementsOf(p).size() > 1) {
    split(p);
    return nullptr;
  }
  pointChosen[p] = 1;
  const uint32_t e = elementsOf(p).front();
  const Polygon3& corners = polygon[e];
  glm::dvec3 bestPoint = patchCentre[p];
  // The first point that sees no backs cannot be beaten; the frame of a point chosen last is
  // still the renderer's and serves the shot.
  const pxpl5::HemisphereFrame* last = nullptr;
  for (int k = 0; k < corners.n && best > 0; ++k) {
    const glm::dvec3 q = corners.v[k] + (centre[e] - corners.v[k]) / 3.0;
    const pxpl5::HemisphereFrame& frame = frameFrom(p, q);
    const double b = backShare(frame, q);
    last = b < best ? &frame : nullptr;
    if (b < best) best = b, bestPoint = q;
  }
  patchCentre[p] = bestPoint;
  double r = 0;
  for (int k = 0; k < corners.n; ++k) r = std::max(r, glm::length(corners.v[k] - bestPoint));
  patchRadius[p] = r;
  pointBackShare[p] = best;
  ++stats.movedShooters;
  return last;
}

// The children of patch p's tree become patches: p the first, new patches the others.
void Solver::State::split(uint32_t p) {
  treeOf(p);
  const std::unique_ptr<PatchTree> tree = std::move(trees[p]);
  const uint32_t base = patchFirst[p];
  const PatchTree::Node& root = tree->nodes.front();
  for (uint32_t c = root.child; c < root.child + root.children; ++c) {
    const uint32_t q = c == root.child ? p : static_cast<uint32_t>(unshot.size());
    setUpPatch(q, base + tree->nodes[c].first, base + tree->nodes[c].last);
  }
  ++stats.splitPatches;
}

// Patch p's hemisphere frame from `point`: every element but the patch's own.
const pxpl5::HemisphereFrame& Solver::State::frameFrom(uint32_t p, const glm::dvec3& point) {
  ++stats.frames;
  return renderer.render({glm::vec3(point), glm::vec3(surfaceNormal[patchSurface[p]]), elementsOf(p)},
                         {soupVertices, soupPolygons});
}

void Solver::State::judgeReceivers(uint32_t p, const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes,
                                   uint32_t begin, uint32_t end, ReceiverChunk& out, Judgement& into) {
  // Sums in locals, stored once: the chunks sit side by side and are judged on different threads.
  into.clear();
  double replacedPixels = 0;
  uint64_t nearCount = 0, smallCount = 0;
  const uint32_t si = patchSurface[p];
  const glm::dvec3 eye = patchCentre[p], eyeNormal = surfaceNormal[si];
  const double nearLimit = settings.nearFieldRatio * patchRadius[p];
  const double smallLimit = settings.smallReceiverPixels * pixelShare;
  for (uint32_t j = begin; j < end; ++j) {
    if (surfaceOf[j] == si) continue;                                  // a plane does not see itself
    const glm::dvec3 toward = centre[j] - eye;
    if (glm::dot(toward, eyeNormal) < -radius[j]) continue;            // wholly below the horizon
    const double gap = glm::length(toward) - radius[j];
    if (gap < nearLimit) {
      // Visibility first: a receiver the shooter's centre cannot see needs no integral. But a
      // centre behind j's plane sees at most j's back and tells nothing of what the patch's
      // elements in front of the plane see: j's front, unless another object is in the way (j's
      // own solid cannot be when it is convex). Without this a floor patch reaching around a box
      // left the box's face 15% too dark.
      const Receiver r = receiverOf(j);
      const double v = visibility(frame, axes, eye, j, pointToReceiver(eye, eyeNormal, r));
      const bool behind = glm::dot(normalOf(j), eye) <= offset[j];
      const Judged& k = into.judged.emplace_back(Judged{j, behind ? Judged::kNearBehind : Judged::kNear, v});
      if (k.integrated())
        planPatchToReceiver(*trees[p], pieces, eyeNormal, r, settings.nearFieldRatio,
                            settings.pieceRatio, settings.maxShooterSplits, into.plans);
      ++nearCount;
    } else {
      // A far receiver whose back faces the centre gets nothing but lost light whatever its
      // factor: its pixel count, right in sum over many such receivers, stands.
      if (glm::dot(normalOf(j), eye) <= offset[j]) continue;
      // Lambert's factor is at most area / (pi gap^2): most receivers are ruled out as big here.
      if (area[j] >= smallLimit * kPi * gap * gap) continue;
      const double unoccluded = pointToReceiver(eye, eyeNormal, receiverOf(j));
      if (unoccluded >= smallLimit || (unoccluded == 0 && pixelFactor[j] == 0)) continue;
      const double v = unoccluded > 0 ? visibility(frame, axes, eye, j, unoccluded) : 0;
      into.judged.push_back({j, Judged::kSmallFront, unoccluded * v});  // its front faces the centre (above)
      ++smallCount;
    }
    replacedPixels += pixelFactor[j];
  }
  out.replacedPixels = replacedPixels;
  out.near = nearCount;
  out.small = smallCount;
}

void Solver::State::rejudgeReceivers(uint32_t p, std::span<const Judged> judged, const NearPlansView& plans,
                                     ReceiverChunk& out) {
  double replacedPixels = 0;
  uint64_t nearCount = 0;
  for (const Judged& k : judged) {
    replacedPixels += pixelFactor[k.element];
    nearCount += k.kind >= Judged::kNear;
  }
  out.replacedPixels = replacedPixels;
  out.near = nearCount;
  out.small = judged.size() - nearCount;
  integrateJudged(p, judged, plans, out);
}

void Solver::State::integrateJudged(uint32_t p, std::span<const Judged> judged, const NearPlansView& plans,
                                    ReceiverChunk& out) {
  out.factors.clear();
  glm::dvec3 replacedNew{0};
  const glm::dvec3& eyeNormal = surfaceNormal[patchSurface[p]];
  size_t plan = 0, step = 0, factor = 0;
  for (const Judged& k : judged) {
    const uint32_t j = k.element;
    NewFactor f{j, glm::dvec3(0), glm::dvec3(0)};
    if (k.kind == Judged::kSmallFront) {
      f.front = glm::dvec3(k.value);
    } else if (k.integrated()) {
      const NearPlanSize size = plans.sizes[plan++];
      applyPlan(*trees[p], nodeLight, plans.steps.subspan(step, size.steps), plans.factors.subspan(factor, size.factors), eyeNormal,
                receiverOf(j), f.front, f.back);
      step += size.steps;
      factor += size.factors;
      if (k.kind != Judged::kNearBehind) f.front *= k.value;
      f.back *= k.value;
    }
    replaced[j] = 1;
    replacedNew += f.front + f.back;
    out.factors.push_back(f);
  }
  out.replacedNew = replacedNew;
}

std::optional<size_t> Solver::State::keepRoom(uint32_t p, const pxpl5::HemisphereFrame& frame) const {
  if (!pointChosen[p] || (p < keptShots.size() && keptShots[p])) return std::nullopt;
  const size_t least = KeptShot::bytesFor(frame.factors.size(), {});
  const size_t free = settings.shotCacheBytes > keptBytes ? settings.shotCacheBytes - keptBytes : 0;
  const size_t most = std::min(settings.shotCacheRecordBytes, free);
  if (least > most) return std::nullopt;
  return most - least;
}

Solver::State::KeptShot Solver::State::shotToKeep() const {
  KeptShot record;
  record.chunkStart.push_back({});
  for (const ReceiverChunk& chunk : chunks) record.chunkStart.push_back(record.chunkStart.back() + chunk.judgement.counts());
  return record;
}

void Solver::State::keepShot(uint32_t p, const pxpl5::HemisphereFrame& frame, KeptShot& record) {
  const KeptShot::ChunkStart& end = record.chunkStart.back();
  record.factors.assign(frame.factors.begin(), frame.factors.end());
  record.total = frame.total;
  record.judged.reserve(end.judged);
  record.plans.sizes.reserve(end.plans);
  record.plans.steps.reserve(end.steps);
  record.plans.factors.reserve(end.factors);
  for (const ReceiverChunk& chunk : chunks) {
    const Judgement& j = chunk.judgement;
    record.judged.insert(record.judged.end(), j.judged.begin(), j.judged.end());
    record.plans.sizes.insert(record.plans.sizes.end(), j.plans.sizes.begin(), j.plans.sizes.end());
    record.plans.steps.insert(record.plans.steps.end(), j.plans.steps.begin(), j.plans.steps.end());
    record.plans.factors.insert(record.plans.factors.end(), j.plans.factors.begin(), j.plans.factors.end());
  }
  storeShot(p, std::move(record));
}

void Solver::State::storeShot(uint32_t p, KeptShot record) {
  if (keptShots.size() <= p) keptShots.resize(unshot.size());
  keptBytes += record.bytes() - (keptShots[p] ? keptShots[p]->bytes() : 0);
  keptShots[p] = std::make_unique<KeptShot>(std::move(record));
}

void Solver::State::shoot(uint32_t p, const pxpl5::HemisphereFrame* chosen) {
  // A kept shot needs no frame (distribute reads it).
  const KeptShot* before = chosen ? nullptr : keptShot(p);
  const pxpl5::HemisphereFrame* frame = chosen || before ? chosen : &frameFrom(p, patchCentre[p]);
  const std::span<const pxpl5::IdFactor> seen = frame ? std::span<const pxpl5::IdFactor>(frame->factors)
                                                           : before ? std::span<const pxpl5::IdFactor>(before->factors) : std::span<const pxpl5::IdFactor>();
  // Overshooting (overshoot.h): the patch also sends what it will reflect of the unshot light it
  // sees, and keeps that much negative unshot light for the light to come back to. At most its
  // unshot light, and only where that is positive: a patch is never left with more light than
  // it had, or one whose overshoot does not come back (what it sees does not shoot) would shoot
  // its own overshoot again and again.
  glm::dvec3 over{0};
  if (settings.overshoot) {
    const glm::dvec3 expected = surfaces[patchSurface[p]].reflectance *
                                gatherUnshot(seen, patchCentre[p], planes(), elementUnshot);
    for (int c = 0; c < 3; ++c) over[c] = std::clamp(expected[c], 0.0, std::max(unshot[p][c], 0.0));
  }
  const glm::dvec3 dB = unshot[p] + over;
  // Each element sends its own unshot light: the near field sees the patch's elements one by
  // one, so a patch brighter at one end lights its near receivers so. A channel in which the
  // patch sends nothing leaves its elements' light (which sums to nothing) where it is.
  sending.clear();
  for (uint32_t e : elementsOf(p)) {
    glm::dvec3& light = sending.emplace_back(0.0);
    for (int c = 0; c < 3; ++c)
      if (dB[c] != 0) light[c] = elementUnshot[e][c] + over[c], elementUnshot[e][c] = -over[c];
  }
  lightPatch(p, dB, sending);
  unshot[p] = -over;
  // Deposit: reflected light becomes radiance and unshot light; the rest is absorbed.
  const glm::dvec3 escaped = distribute(p, frame, [&](uint32_t j, const glm::dvec3& front, const glm::dvec3& back) {
    receive(j, patchArea[p], dB, front, back);
  });
  stats.escapedPower += kPi * dB * patchArea[p] * escaped;
  recordSent(p, sending);
}

void Solver::State::lightPatch(uint32_t p, const glm::dvec3& dB, std::span<const glm::dvec3> light) {
  const std::span<const uint32_t> own = elementsOf(p);
  shares.clear();
  for (size_t k = 0; k < own.size(); ++k) {
    glm::dvec3 w = area[own[k]] / patchArea[p] * glm::dvec3(1);
    for (int c = 0; c < 3; ++c)
      if (dB[c] != 0) w[c] = area[own[k]] * light[k][c] / (patchArea[p] * dB[c]);
    shares.push_back(w);
  }
  lightPatchTree(treeOf(p), shares, nodeLight);
}

void Solver::State::receive(uint32_t j, double sourceArea, const glm::dvec3& dB, const glm::dvec3& front,
                            const glm::dvec3& back) {
  const glm::dvec3& rho = surfaces[surfaceOf[j]].reflectance;
  const glm::dvec3 power = kPi * dB * sourceArea;
  const glm::dvec3 gained = rho * dB * front * (sourceArea / area[j]);
  radiance[j] += gained;
  elementUnshot[j] += gained;
  unshot[patchOf[j]] += gained * (area[j] / patchArea[patchOf[j]]);
  stats.absorbedPower += (1.0 - rho) * power * front;
  stats.backPower += power * back;
}

template <typename Deposit>
glm::dvec3 Solver::State::distribute(uint32_t p, const pxpl5::HemisphereFrame* chosen, const Deposit& deposit,
                                     const Replay* replay) {
  const uint32_t si = patchSurface[p];
  const glm::dvec3 eye = patchCentre[p], eyeNormal = surfaceNormal[si];

  // A kept shot of p stands for its frame and judgement (the same geometry, the same point).
  const KeptShot* before = chosen ? nullptr : keptShot(p);
  const pxpl5::HemisphereFrame* frame = chosen || before ? chosen : &frameFrom(p, eye);
  const std::span<const pxpl5::IdFactor> factors = frame ? std::span<const pxpl5::IdFactor>(frame->factors)
                                                           : before ? std::span<const pxpl5::IdFactor>(before->factors) : std::span<const pxpl5::IdFactor>();
  const double total = frame ? frame->total : before ? before->total : 0.0;
  if (pixelShare == 0 && frame) pixelShare = frame->weights[static_cast<size_t>(frame->height / 2) * frame->stride + frame->width / 2];
  for (const pxpl5::IdFactor& f : factors) pixelFactor[f.id] = f.factor;
  const HemisphereAxes axes = hemisphereAxes(glm::vec3(eyeNormal));

  // Near and small receivers get new factors, per channel (near ones weigh the shooter's
  // elements by their unshot light), judged on the graphics processors (which read p's tree).
  // A shot that may be kept holds its chunks' judgements for keepShot, until they pass what its
  // record may hold; then it is not kept, and the chunks still to judge drop theirs.
  readyToJudge(p);
  const auto elements = static_cast<uint32_t>(polygon.size());
  const std::optional<size_t> room = before ? std::nullopt : keepRoom(p, *frame);
  std::atomic<bool> keeping = room.has_value();
  std::atomic<size_t> judgedBytes = 0;
  renderer.runOnGraphicsProcessors(kReceiverChunks, [&](size_t c, int worker) {
    ReceiverChunk& chunk = chunks[c];
    if (before) {
      rejudgeReceivers(p, before->judgedOf(c), before->plansOf(c), chunk);
      return;
    }
    const bool keep = keeping.load(std::memory_order_relaxed);
    if (!keep) chunk.judgement.clear();
    Judgement& judgement = keep ? chunk.judgement : judging[static_cast<size_t>(worker)];
    judgeReceivers(p, *frame, axes, static_cast<uint32_t>(c * elements / kReceiverChunks),
                   static_cast<uint32_t>((c + 1) * elements / kReceiverChunks), chunk, judgement);
    integrateJudged(p, judgement.judged, judgement.plansView(), chunk);
    const size_t bytes = judgement.counts().bytes();
    if (keep && judgedBytes.fetch_add(bytes, std::memory_order_relaxed) + bytes > *room) keeping = false;
  });
  stats.reusedShots += before != nullptr;
  double replacedPixels = 0;
  glm::dvec3 replacedNew{0};
  for (const ReceiverChunk& chunk : chunks) {
    replacedPixels += chunk.replacedPixels;
    replacedNew += chunk.replacedNew;
    stats.nearReceivers += chunk.near;
    stats.smallReceivers += chunk.small;
  }

  // Keep the energy, per channel: the difference comes out of everything else the centre saw,
  // sky included, when that is plenty (more than ten times the difference). Where nearly
  // everything is new (a small closed room, all of it near) that cannot work; then all factors
  // and the sky are scaled to sum to 1, which keeps the near factors' proportions. A frame made
  // from a window (Edit::moveShot) can hold a pixel or so more than the hemisphere: that excess
  // comes out of the rest too, or the shot would send more than it has (and its take-back,
  // which sends back what the shot had, would leave the difference in the scene).
  double kept = 0;
  for (const pxpl5::IdFactor& f : factors)
    if (!replaced[f.id]) kept += f.factor;
  const double sky = std::max(0.0, 1.0 - total), excess = std::max(0.0, total - 1.0);
  glm::dvec3 scale{1}, newScale{1};
  bool renormalised = false;
  for (int c = 0; c < 3 && !replay; ++c) {
    const double difference = replacedNew[c] - replacedPixels + excess;
    if (kept + sky >= 10 * std::abs(difference)) {
      if (kept + sky > 0) scale[c] = (kept + sky - difference) / (kept + sky);
    } else {
      scale[c] = newScale[c] = 1.0 / (kept + sky + replacedNew[c]);
      renormalised = true;
    }
  }
  for (int c = 0; c < 3 && replay; ++c) {
    newScale[c] = replay->judged[c];
    scale[c] = kept + sky > 0 ? (replay->total[c] - newScale[c] * replacedNew[c]) / (kept + sky) : 0.0;
  }
  stats.renormalisedShots += renormalised;
  lastScale = {scale, newScale};

  // Deposited, clearing the scratch marks on the way: one pass over each list (the new factors
  // were written by other threads; each pass over them was a round of cache misses).
  const auto depositAll = [&] {
    for (const pxpl5::IdFactor& f : factors) {
      pixelFactor[f.id] = 0;
      if (replaced[f.id]) continue;
      const glm::dvec3 factor = f.factor * scale;
      if (glm::dot(normalOf(f.id), eye) > offset[f.id]) deposit(f.id, factor, glm::dvec3(0));
      else deposit(f.id, glm::dvec3(0), factor);
    }
    for (const ReceiverChunk& chunk : chunks)
      for (const NewFactor& f : chunk.factors) {
        replaced[f.element] = 0;
        deposit(f.element, f.front * newScale, f.back * newScale);
      }
  };
  // A first shot that is to be kept is kept meanwhile, on another graphics processor when there
  // is one: both only read the frame and the chunks, and they write apart. Keeping is task 0,
  // which the calling thread takes at once: it is the longer (fresh pages to fill), so the
  // deposit can wait the tens of microseconds a worker takes to wake. Other shots (kept
  // already, or past the budget) pay no hand-over.
  std::optional<KeptShot> toKeep = keeping ? std::optional(shotToKeep()) : std::nullopt;
  if (!toKeep) {
    depositAll();
  } else {
    renderer.runOnGraphicsProcessors(2, [&](size_t task, int) {
      if (task == 0) keepShot(p, *frame, *toKeep);
      else depositAll();
    });
  }
  // The chunks' and processors' storage stays for the next shot, within a bound.
  stats.scratchBytes = util::releaseSpareBeyond(chunks, settings.scratchBytes) +
                       util::releaseSpareBeyond(judging, settings.scratchBytes);
  return sky * scale;
}

// ---- Solver --------------------------------------------------------------------------------------

Solver::Solver(std::span<const Surface> surfaces, const SolverSettings& settings)
    : state_(std::make_unique<State>(settings)) {
  std::vector<const Surface*> given;
  given.reserve(surfaces.size());
  for (const Surface& s : surfaces) given.push_back(&s);
  state_->build(given);
}

Solver::~Solver() = default;

// ---- edits (after Chen 1990) ---------------------------------------------------------------------

struct Solver::Edit {
  std::unique_ptr<State> before;     // the geometry the light to take back was sent along
  std::vector<uint32_t> elementNow;  // per element of `before`: its index now, or kNone
  struct TakeBack {
    uint32_t patch = 0;  // in `before`
    double power = 0;    // the part of its shot power that can change course, summed over channels
  };
  std::vector<TakeBack> pending;  // least power first: taken from the back
  double pendingPower = 0, editPower = 0;  // of the take-backs pending, and of all the edit's
  std::vector<uint32_t> elements, patches;  // scratch of one correction

  // What changed, for corrections in a window (frameInWindow).
  std::vector<uint32_t> elementBefore;             // per element now: its index before, or kNone
  std::vector<uint8_t> changedBefore, changedNow;  // per element: moved, went or came
  std::vector<uint32_t> changed[2];                // those elements, before and now
  struct Cluster {
    glm::dvec3 centre{0};
    double radius = 0;
    uint32_t surface = 0;
  };
  std::vector<Cluster> clusters;  // per surface and geometry, spheres around its changed elements
  static constexpr size_t kClusterElements = 32;
  // A correction in a window is found in two parts: what its window holds (frames before and
  // now, the receivers judged again), which reads only geometry that no correction changes, and
  // the deposits, which must come in turn. So the first part of the next pending correction is
  // done beside this one's, on the other graphics processor: each Window has its own scratch and
  // renderer (of one graphics processor, which runs on the thread that calls it). Their results
  // are the same as one after the other.
  struct Window {
    explicit Window(int resolution);
    pxpl5::HemisphereRenderer renderer;
    double pixelShare = 0;  // the factor of one disk pixel
    // What frameInWindow makes the frame now from, for patch `patch` before, `now` now.
    uint32_t patch = kNone, now = kNone;
    bool windowable = false;
    double pointBacks = 0;      // the share of backs its point sees now (choosePoint's measure)
    uint64_t frames = 0;        // hemisphere frames rendered for it
    pxpl5::HemisphereFrame frame[2];
    std::vector<uint32_t> judged[2];
    // Scratch.
    WindowCull cull;
    std::vector<uint32_t> drawn[3];  // elements drawn: unchanged, gone (before), came (now)
    std::vector<uint32_t> marked;  // per element before: the correction that marked it for judging
    uint32_t correction = 0;
    std::vector<pxpl5::Polygon> soup;
    std::vector<uint32_t> items[3];  // per pixel, the element seen (within the window): before, now, gone
    std::vector<uint8_t> differs;    // per pixel of the changed window
    std::vector<uint32_t> pixelCount, counted;  // per element, its pixels in the grown window
  };
  std::array<std::unique_ptr<Window>, 2> windows;  // made at the first correction in a window
  bool nextPrepared = false;  // windows[1] holds the next pending correction's window
  // Finds what patch p's window holds into w (windowable false when it cannot be corrected so).
  // Reads `before`, `now` and what changed, writes only w.
  void findWindow(const State& now, uint32_t p, Window& w) const;
  // Moves patch p's kept shot in `old` (which it must have; the geometry before) to patch q now,
  // of p's elements, unmoved: its elements as they are now. With p's window w, what changed
  // there: the pixel factors less what the window saw before plus what it sees now, the
  // receivers it judged again judged on its frame now (their pixels there are whole). What a new
  // frame at its point would give, without rendering it. Uses now's scratch.
  void moveShot(State& old, State& now, uint32_t p, uint32_t q, const Window* w);
  std::vector<uint8_t> rejudged;  // scratch of moveShot: per element before, judged again in the window
  State::ReceiverChunk judging;
  // The window of pending patch p (just taken from `pending`): prepared by the last call, or
  // found now beside the next pending patch's.
  Window& windowOf(State& now, uint32_t p);

  // The patch of `now` whose elements are patch p's of `before` in the same order, or kNone.
  // unmovedPatch: the same, where none of them moved.
  uint32_t samePatch(const State& b, const State& now, uint32_t p) const {
    const std::span<const uint32_t> own = b.elementsOf(p);
    const uint32_t first = elementNow[own.front()];
    if (first == kNone) return kNone;
    const uint32_t q = now.patchOf[first];
    const std::span<const uint32_t> theirs = now.elementsOf(q);
    if (theirs.size() != own.size()) return kNone;
    for (size_t k = 0; k < own.size(); ++k)
      if (elementNow[own[k]] != theirs[k]) return kNone;
    return q;
  }
  // Takes back the light that reached element j (before) from a patch of area `area`, with these
  // factors carrying its radiance per channel: from j now, or, when j is gone, off the ledgers
  // (its reflected part off the removed light's).
  void takeBack(State& now, uint32_t j, double area, const glm::dvec3& front, const glm::dvec3& back) const {
    if (const uint32_t i = elementNow[j]; i != kNone) {
      now.receive(i, area, glm::dvec3(-1), front, back);
      return;
    }
    const glm::dvec3& rho = before->surfaces[before->surfaceOf[j]].reflectance;
    const double power = -kPi * area;
    now.stats.absorbedPower += (1.0 - rho) * power * front;
    now.stats.backPower += power * back;
    now.stats.removedPower += rho * power * front;
  }
  uint32_t unmovedPatch(const State& b, const State& now, uint32_t p) const {
    const std::span<const uint32_t> own = b.elementsOf(p);
    if (std::any_of(own.begin(), own.end(), [&](uint32_t j) { return changedBefore[j] != 0; })) return kNone;
    return samePatch(b, now, p);
  }
};

namespace {

bool sameCorners(const Polygon3& a, const Polygon3& b) {
  return a.n == b.n && std::equal(a.v.begin(), a.v.begin() + a.n, b.v.begin());
}

}  // namespace

void Solver::edit(std::span<const SurfaceChange> changes) {
  while (correct()) {
  }
  State& old = *state_;
  std::vector<const Surface*> given(old.surfaces.size(), nullptr);
  for (const SurfaceChange& c : changes) {
    if (c.surface >= given.size())
      throw std::invalid_argument("radiosity::Solver::edit: no surface " + std::to_string(c.surface) + " of " +
                                  std::to_string(given.size()));
    if (given[c.surface]) throw std::invalid_argument("radiosity::Solver::edit: surface " + std::to_string(c.surface) + " named twice");
    given[c.surface] = &c.now;
  }
  auto now = std::make_unique<State>(old.settings);
  State& n = *now;
  n.build(given, &old);
  const uint64_t trees = n.stats.patchTrees;  // the replaced surfaces' patches'
  n.stats = old.stats;  // the ledgers go on; emission does not change
  n.stats.patchTrees += trees;
  n.stats.editedSurfaces += changes.size();
  n.pixelShare = old.pixelShare;

  // Elements go on by their keys (on a surface no change named: all of them, as they were):
  // they keep their light.
  auto edit = std::make_unique<Edit>();
  edit->elementNow.assign(old.polygon.size(), kNone);
  std::vector<uint8_t> changedBefore(old.polygon.size(), 0), mappedNow(n.polygon.size(), 0);
  std::vector<uint32_t> changed[2];  // elements that moved or went (before), moved or came (now)
  for (size_t si = 0; si < given.size(); ++si) {
    const State::SurfaceData &a = old.surfaces[si], &b = n.surfaces[si];
    if (!given[si])
      for (uint32_t k = 0; k < a.elementCount; ++k) edit->elementNow[a.firstElement + k] = b.firstElement + k;
  }
  std::vector<std::pair<uint64_t, uint32_t>> byKey;  // an edited surface's elements before, by key
  for (const SurfaceChange& c : changes) {
    if (c.meshedAnew) continue;
    const State::SurfaceData &a = old.surfaces[c.surface], &b = n.surfaces[c.surface];
    byKey.clear();
    for (uint32_t k = 0; k < a.elementCount; ++k) byKey.emplace_back(a.keyOf(k), a.firstElement + k);
    std::sort(byKey.begin(), byKey.end());
    for (uint32_t k = 0; k < b.elementCount; ++k) {
      const auto found = std::lower_bound(byKey.begin(), byKey.end(), std::pair{b.keyOf(k), uint32_t{0}});
      if (found != byKey.end() && found->first == b.keyOf(k)) edit->elementNow[found->second] = b.firstElement + k;
    }
  }
  for (uint32_t j = 0; j < old.polygon.size(); ++j) {
    const uint32_t i = edit->elementNow[j];
    if (i == kNone) {
      // Gone: its unshot light leaves with it.
      n.stats.removedPower += kPi * old.elementUnshot[j] * old.area[j];
      changedBefore[j] = 1;
      changed[0].push_back(j);
      continue;
    }
    mappedNow[i] = 1;
    n.radiance[i] = old.radiance[j];
    n.elementUnshot[i] = old.elementUnshot[j];
    if (!sameCorners(old.polygon[j], n.polygon[i])) {
      changedBefore[j] = 1;
      changed[0].push_back(j);
      changed[1].push_back(i);
    }
  }
  for (uint32_t i = 0; i < n.polygon.size(); ++i)
    if (!mappedNow[i]) {
      n.stats.removedPower -= kPi * n.elementUnshot[i] * n.area[i];  // starts at its emission
      changed[1].push_back(i);
    }
  edit->elementBefore.assign(n.polygon.size(), kNone);
  for (uint32_t j = 0; j < old.polygon.size(); ++j)
    if (edit->elementNow[j] != kNone) edit->elementBefore[edit->elementNow[j]] = j;
  // Patches split before (their centres were under a solid) are split alike now where their
  // elements are the same, so that their light is corrected part by part as it was sent.
  const uint64_t splits = n.stats.splitPatches;
  for (uint32_t q = 0; q < n.unshot.size(); ++q) {
    for (;;) {
      const std::span<const uint32_t> theirs = n.elementsOf(q);
      const uint32_t first = edit->elementBefore[theirs.front()];
      if (theirs.size() < 2 || first == kNone || old.elementsOf(old.patchOf[first]).size() >= theirs.size()) break;
      bool within = true;  // the old patch's elements all in this one
      for (uint32_t j : old.elementsOf(old.patchOf[first]))
        within = within && edit->elementNow[j] != kNone && n.patchOf[edit->elementNow[j]] == q;
      const PatchTree::Node& root = n.treeOf(q).nodes.front();
      if (!within || root.children < 2) break;
      n.split(q);
    }
  }
  n.stats.splitPatches = splits;
  edit->changedNow.assign(n.polygon.size(), 0);
  for (uint32_t i : changed[1]) edit->changedNow[i] = 1;
  // Per surface and geometry, spheres around its changed elements (a few dozen in each): a
  // tighter bound on what a patch sees of them than their sum, and the window a correction looks
  // through.
  for (int side = 0; side < 2; ++side) {
    const State& s = side == 0 ? old : n;
    std::map<uint32_t, std::vector<uint32_t>> bySurface;
    for (uint32_t j : changed[side]) bySurface[s.surfaceOf[j]].push_back(j);
    for (auto& [surface, elements] : bySurface)
      for (const Sphere& c : sphereClusters(s.centre, s.radius, elements, Edit::kClusterElements))
        edit->clusters.push_back({c.centre, c.radius, surface});
  }

  // The light of patch p that can change course is what reaches the changed elements, before or
  // after: at most their form factors from p's centre, each bounded by area / (pi d^2) (all of
  // it nearer than their size), and at most the factors of the spheres around them, each
  // (radius / d)^2 (d less the patch's size, for the near field's points). Elements of p's own
  // plane and below its horizon it does not see. A patch that moved or lost elements takes back
  // all of its light.
  const auto reach = [](const State& s, const glm::dvec3& eye, const glm::dvec3& up, uint32_t surface, double size,
                        const std::vector<uint32_t>& elements) {
    double factor = 0;
    for (uint32_t j : elements) {
      if (s.surfaceOf[j] == surface) continue;
      const glm::dvec3 toward = s.centre[j] - eye;
      if (glm::dot(toward, up) < -s.radius[j]) continue;  // below the horizon
      const double d = glm::length(toward), r = s.radius[j] + size;
      if (d <= 2 * r) return 1.0;
      factor += s.area[j] / (kPi * (d - r) * (d - r));
      if (factor >= 1) return 1.0;
    }
    return factor;
  };
  const auto clusterReach = [&](const glm::dvec3& eye, const glm::dvec3& up, uint32_t surface, double size) {
    double factor = 0;
    for (const Edit::Cluster& c : edit->clusters) {
      if (c.surface == surface) continue;
      const glm::dvec3 toward = c.centre - eye;
      if (glm::dot(toward, up) < -c.radius) continue;
      const double d = glm::length(toward) - size;
      if (d <= c.radius) return 1.0;
      factor += (c.radius / d) * (c.radius / d);
    }
    return std::min(factor, 1.0);
  };
  // Light that stays where it was sent is still shot light, of the elements that sent it, when
  // they still form the patch that sent it (it is taken back along that patch's frame).
  for (uint32_t p = 0; p < old.unshot.size(); ++p) {
    double power = 0;
    for (uint32_t j : old.elementsOf(p)) power += kPi * channelSum(old.sentOf(j).light) * old.area[j];
    if (power == 0) continue;
    const uint32_t same = edit->samePatch(old, n, p);
    bool itself = same == kNone;
    for (uint32_t j : old.elementsOf(p)) itself = itself || changedBefore[j];
    const uint32_t si = old.patchSurface[p];
    const glm::dvec3 up = old.surfaceNormal[si], eye = old.patchCentre[p];
    const double size = old.patchRadius[p];
    const double share =
        itself ? 1.0
               : std::min({1.0, reach(old, eye, up, si, size, changed[0]) + reach(n, eye, up, si, size, changed[1]),
                           clusterReach(eye, up, si, size)});
    if (share > 0) {
      edit->pending.push_back({p, power * share});
      continue;
    }
    // It sees nothing of the change and sees what it saw: the point it chose and its frame stand.
    for (uint32_t j : old.elementsOf(p))
      if (old.sentAt[j] != kNone) n.sentRecord(edit->elementNow[j]) = old.sentRecords[old.sentAt[j]];
    n.adoptPoint(same, old.patchCentre[p], old.patchRadius[p], old.pointBackShare[p]);
    if (old.keptShot(p)) edit->moveShot(old, n, p, same, nullptr);
  }
  // The new patches' unshot light from their elements.
  for (uint32_t q = 0; q < n.unshot.size(); ++q) {
    n.unshot[q] = glm::dvec3(0);
    for (uint32_t i : n.elementsOf(q)) n.unshot[q] += n.elementUnshot[i] * (n.area[i] / n.patchArea[q]);
  }
  std::sort(edit->pending.begin(), edit->pending.end(),
            [](const Edit::TakeBack& a, const Edit::TakeBack& b) { return a.power < b.power; });
  for (const Edit::TakeBack& t : edit->pending) edit->pendingPower += t.power;
  edit->editPower = edit->pendingPower;
  if (!edit->pending.empty()) {
    edit->changed[0] = std::move(changed[0]);
    edit->changed[1] = std::move(changed[1]);
    edit->changedBefore = std::move(changedBefore);
    edit->before = std::move(state_);
    edit_ = std::move(edit);
  }
  state_ = std::move(now);
}

bool Solver::correct() {
  if (!edit_ || edit_->pending.empty()) return false;
  const Edit::TakeBack t = edit_->pending.back();
  edit_->pending.pop_back();
  edit_->pendingPower -= t.power;
  State& now = *state_;
  takeBack(t.patch);
  const bool windowed = frameInWindow(t.patch);
  sendAgain(t.patch);
  ++now.stats.corrections;
  now.stats.windowedCorrections += windowed;
  if (edit_->pending.empty()) edit_.reset();
  return true;
}

void Solver::takeBack(uint32_t p) {
  State &before = *edit_->before, &now = *state_;
  // Along p's factors before, as its shots sent it: its judged (near and small) receivers'
  // factors weighed by its elements' light as the shots weighed it, its pixel receivers and the
  // sky taking the rest of what it sent (each shot kept the frame's energy so). The factors carry
  // the radiance. What fell on removed elements comes off their ledger.
  const State::Sent S = before.sentBy(p);
  before.sending.clear();
  for (uint32_t e : before.elementsOf(p)) before.sending.push_back(before.sentOf(e).judged);
  before.lightPatch(p, S.judged, before.sending);
  const State::Replay replay{S.light, S.judged};
  const double area = before.patchArea[p];
  const glm::dvec3 escaped = before.distribute(
      p, nullptr,
      [&](uint32_t j, const glm::dvec3& front, const glm::dvec3& behind) { edit_->takeBack(now, j, area, front, behind); },
      &replay);
  now.stats.escapedPower -= kPi * area * escaped;
}

void Solver::sendAgain(uint32_t p) {
  State &before = *edit_->before, &now = *state_;
  // From the same elements, each its own light, at once, so that receivers whose light did not
  // change get back what they lost before they shoot it (the removed elements' share goes to
  // their ledger). Their patches now may group them otherwise, and may first have to settle the
  // point they shoot from (which can split them).
  std::vector<uint32_t>& from = edit_->elements;
  std::vector<uint32_t>& patches = edit_->patches;
  from.clear();
  for (uint32_t j : before.elementsOf(p)) {
    const uint32_t i = edit_->elementNow[j];
    if (i == kNone) now.stats.removedPower += kPi * before.sentOf(j).light * before.area[j];
    else from.push_back(i);
  }
  // The frame of the last point chosen is still the renderer's: it is that patch's shot frame.
  uint32_t lastChosen = kNone;
  const pxpl5::HemisphereFrame* lastFrame = nullptr;
  // A patch of the same elements, unmoved, whose point was moved off its centre (the centre is
  // inside a solid) keeps that point while it still sees few backs: one frame checks it, where
  // choosing again renders up to five (the centre's, then the candidates'). A point outside the
  // solids stays so unless a solid comes to stand on its element, which the check sees.
  if (const uint32_t same = edit_->unmovedPatch(before, now, p);
      same != kNone && !now.pointChosen[same] && before.pointChosen[p] && now.patchCentre[same] != before.patchCentre[p]) {
    const glm::dvec3 point = before.patchCentre[p];
    const pxpl5::HemisphereFrame& frame = now.frameFrom(same, point);
    if (const double backs = now.backShare(frame, point); backs <= kMostBacks) {
      now.adoptPoint(same, point, before.patchRadius[p], backs);
      lastFrame = &frame, lastChosen = same;
    }
  }
  for (bool settled = false; !settled;) {
    patches.clear();
    for (uint32_t i : from) patches.push_back(now.patchOf[i]);
    std::sort(patches.begin(), patches.end());
    patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
    settled = true;
    for (uint32_t q : patches)
      if (!now.pointChosen[q]) lastFrame = now.choosePoint(q), lastChosen = q, settled = false;
  }
  std::sort(from.begin(), from.end());
  for (uint32_t q : patches) {
    // The patch's elements that carry p's light send it, the others nothing.
    std::vector<glm::dvec3>& carried = now.sending;
    carried.clear();
    glm::dvec3 dB{0};
    for (uint32_t i : now.elementsOf(q)) {
      const bool carrying = std::binary_search(from.begin(), from.end(), i);
      dB += now.area[i] * carried.emplace_back(carrying ? before.sentOf(edit_->elementBefore[i]).light : glm::dvec3(0));
    }
    dB /= now.patchArea[q];
    now.lightPatch(q, dB, carried);
    const double area = now.patchArea[q];
    const pxpl5::HemisphereFrame* chosen = q == lastChosen && now.pointChosen[q] ? lastFrame : nullptr;
    lastChosen = kNone;  // any other patch renders a frame of its own
    const glm::dvec3 out = now.distribute(q, chosen, [&](uint32_t j, const glm::dvec3& front, const glm::dvec3& behind) {
      now.receive(j, area, dB, front, behind);
    });
    now.stats.escapedPower += kPi * dB * area * out;
    now.recordSent(q, carried);
  }
}

Solver::Edit::Window::Window(int resolution) : renderer({resolution, pxpl5::Projection::kHemisphere, 1}) {
  // Every disk pixel weighs the same: pxpl5's share, one over their number.
  const pxpl5::HemisphereFrame& empty = renderer.render({}, {}, pxpl5::PixelRect{});
  const auto disk = std::count_if(empty.weights.begin(), empty.weights.end(), [](float weight) { return weight > 0; });
  pixelShare = 1.0 / static_cast<double>(disk);
}

// A patch that did not change, shooting from the same point before and now, sees the same
// except where the changed elements are seen (windowed_correction.h). Its take-back and resend
// differ only there: both frames are rendered in that window; the receivers whose pixels or
// targets differ between them, and the changed ones, are judged in both, the frame before
// rendered again in the window grown over those of them whose pixel counts and item-buffer
// targets must be whole; and what each gets now less what it got is deposited. Energy: the frames' factors of those receivers are
// taken as the whole frames' would be before their energy is kept (distribute's scale, which
// moves light between all receivers and the sky by the frame's total correction of near and
// small receivers, here left out: at most that correction's change, a fraction of a percent
// of the difference on the shipped scenes); what the difference does not deposit leaves as
// escaped light, so the ledgers stay exact.
void Solver::Edit::findWindow(const State& now, uint32_t p, Window& w) const {
  const State& old = *before;
  w.patch = p;
  w.windowable = false;
  w.frames = 0;
  // The same patch now, of unmoved elements, shooting from the same point: its centre, or the
  // point it was moved to off a centre inside a solid (kept while it sees few backs: the caller).
  const uint32_t q = w.now = unmovedPatch(old, now, p);
  if (q == kNone || !old.pointChosen[p]) return;
  const uint32_t si = old.patchSurface[p];
  const glm::dvec3 eye = old.patchCentre[p], up = old.surfaceNormal[si];
  const HemisphereAxes axes = hemisphereAxes(glm::vec3(up));
  const int resolution = old.settings.resolution;

  // The window: where the changed elements are seen, before or now, grown over what is seen there.
  pxpl5::PixelRect changedWindow{};
  for (const Cluster& c : clusters)
    if (c.surface != si) changedWindow = unite(changedWindow, sphereWindow(axes, eye, resolution, c.centre, c.radius));
  WindowCull& cull = w.cull;
  // Near and small receivers' factors are judged from their whole pixel counts or their
  // targets' items (judgeReceivers' first tests, before any pixel is read); the rest are counts.
  const double nearLimit = old.settings.nearFieldRatio * old.patchRadius[p];
  const double smallLimit = old.settings.smallReceiverPixels * old.pixelShare;
  const auto whole = [&](uint32_t j) {
    const double gap = glm::length(old.centre[j] - eye) - old.radius[j];
    return gap < nearLimit || (glm::dot(old.normalOf(j), eye) > old.offset[j] && old.area[j] < smallLimit * kPi * gap * gap);
  };
  cull.cull(old.spheres(), axes, eye, resolution, si, changedWindow);
  // First both frames in the changed window alone, to find what differs there. The elements
  // that did not change are drawn once for both, the changed ones before and now each on their
  // own, and a pixel shows the nearest of what it has (along its direction to their planes; an
  // exact tie keeps the unchanged element): the cost of one frame and of what changed, not of
  // two frames. Now is the same as before outside the window: before's through the elements'
  // new indices.
  std::vector<uint32_t>&still = w.drawn[0], &gone = w.drawn[1], &came = w.drawn[2];
  still.clear(), gone.clear(), came.clear();
  for (uint32_t j : cull.drawn) (changedBefore[j] ? gone : still).push_back(j);
  for (uint32_t i : changed[1])
    if (now.surfaceOf[i] != si && overlaps(sphereWindow(axes, eye, resolution, now.centre[i], now.radius[i]), changedWindow))
      came.push_back(i);
  std::sort(came.begin(), came.end());
  // Draws `drawn` (elements of s) within `window` into items (their element indices).
  size_t stride = 0;
  const auto render = [&](const State& s, std::span<const uint32_t> drawn, const pxpl5::PixelRect& window,
                          std::vector<uint32_t>& items) {
    w.soup.clear();
    for (uint32_t j : drawn) w.soup.push_back(s.soupPolygons[j]);
    const pxpl5::HemisphereFrame& f = w.renderer.render({glm::vec3(eye), glm::vec3(up), {}}, {s.soupVertices, w.soup}, window);
    ++w.frames;
    items.resize(f.items.size(), pxpl5::kNoValue);
    stride = static_cast<size_t>(f.stride);
    for (int y = window.y0; y < window.y1; ++y)
      for (int x = window.x0; x < window.x1; ++x) {
        const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
        items[at] = f.items[at] == pxpl5::kNoValue ? pxpl5::kNoValue : drawn[f.items[at]];
      }
    for (pxpl5::HemisphereFrame& frame : w.frame)
      frame.weights = f.weights, frame.width = f.width, frame.height = f.height, frame.stride = f.stride;
  };
  // What pixel (x, y) of geometry s shows of element `behind` (or nothing) with `over` drawn too.
  const auto shown = [&](const State& s, uint32_t behind, uint32_t over, int x, int y) {
    if (over == pxpl5::kNoValue) return behind;
    if (behind == pxpl5::kNoValue) return over;
    const double u = (x + 0.5) * 2 / resolution - 1, v = (y + 0.5) * 2 / resolution - 1;
    const glm::dvec3 direction = axes.x * u + axes.y * v + axes.z * std::sqrt(std::max(0.0, 1 - u * u - v * v));
    const auto distance = [&](uint32_t j) {
      const glm::dvec3& normal = s.normalOf(j);
      return std::abs((s.offset[j] - glm::dot(normal, eye)) / glm::dot(normal, direction));
    };
    return distance(over) < distance(behind) ? over : behind;
  };
  std::vector<uint32_t>&itemsBefore = w.items[0], &itemsNow = w.items[1], &itemsGone = w.items[2];
  render(old, gone, changedWindow, itemsGone);
  render(now, came, changedWindow, itemsNow);
  render(old, still, changedWindow, itemsBefore);
  for (int y = changedWindow.y0; y < changedWindow.y1; ++y)
    for (int x = changedWindow.x0; x < changedWindow.x1; ++x) {
      const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
      const uint32_t behind = itemsBefore[at];
      itemsNow[at] = shown(now, behind == pxpl5::kNoValue ? pxpl5::kNoValue : elementNow[behind], itemsNow[at], x, y);
      itemsBefore[at] = shown(old, behind, itemsGone[at], x, y);
    }

  // Judged again: the changed elements, and the others whose pixels or targets differ.
  const size_t changedWidth = static_cast<size_t>(changedWindow.x1 - changedWindow.x0);
  w.differs.assign(static_cast<size_t>(pixelsOf(changedWindow)), 0);
  if (w.marked.size() < old.polygon.size()) w.marked.resize(old.polygon.size(), 0);
  const uint32_t mark = ++w.correction;
  for (int y = changedWindow.y0; y < changedWindow.y1; ++y)
    for (int x = changedWindow.x0; x < changedWindow.x1; ++x) {
      const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
      const uint32_t seenBefore = itemsBefore[at], seenNow = itemsNow[at];
      const bool changedB = seenBefore != pxpl5::kNoValue && changedBefore[seenBefore];
      const bool changedN = seenNow != pxpl5::kNoValue && changedNow[seenNow];
      const uint32_t beforeNow = seenBefore == pxpl5::kNoValue ? pxpl5::kNoValue : elementNow[seenBefore];
      if (!changedB && !changedN && beforeNow == seenNow) continue;
      w.differs[static_cast<size_t>(y - changedWindow.y0) * changedWidth + static_cast<size_t>(x - changedWindow.x0)] = 1;
      if (seenBefore != pxpl5::kNoValue && !changedB) w.marked[seenBefore] = mark;
      if (seenNow != pxpl5::kNoValue && !changedN) w.marked[elementBefore[seenNow]] = mark;
    }
  std::vector<uint32_t>&judgedBefore = w.judged[0], &judgedNow = w.judged[1];
  judgedBefore.clear();
  judgedNow.clear();
  for (uint32_t j : cull.judged) {
    if (changedBefore[j]) continue;
    if (w.marked[j] != mark) {
      // Only near and small receivers read items at their targets; the others' factors are
      // counts, unchanged when none of their pixels is.
      if (!whole(j)) continue;
      const std::array<glm::dvec3, State::kTargets> targets = old.targetsOf(j);
      for (size_t k = 0; k < State::kTargets && w.marked[j] != mark; ++k) {
        int x = 0, y = 0;
        if (!targetPixel(axes, eye, resolution, targets[k], x, y)) continue;
        if (x < changedWindow.x0 || x >= changedWindow.x1 || y < changedWindow.y0 || y >= changedWindow.y1) continue;
        if (w.differs[static_cast<size_t>(y - changedWindow.y0) * changedWidth + static_cast<size_t>(x - changedWindow.x0)])
          w.marked[j] = mark;
      }
      if (w.marked[j] != mark) continue;
    }
    judgedBefore.push_back(j);
    judgedNow.push_back(elementNow[j]);
  }
  for (uint32_t j : changed[0])
    if (old.surfaceOf[j] != si) judgedBefore.push_back(j);
  for (uint32_t i : changed[1])
    if (now.surfaceOf[i] != si) judgedNow.push_back(i);
  std::sort(judgedBefore.begin(), judgedBefore.end());
  std::sort(judgedNow.begin(), judgedNow.end());

  // Then before again in the window grown over the judged receivers whose judgement reads more
  // than their count in it (the changed ones lie within it): only those need to be whole. The
  // receivers seen there that are not judged, which the grown window would hold too, do not.
  pxpl5::PixelRect grown = changedWindow;
  for (uint32_t j : judgedBefore)
    if (!changedBefore[j] && whole(j)) grown = unite(grown, cull.rectOf(j));
  if (!contains(changedWindow, grown)) {
    cull.drawWithin(grown);
    still.clear();
    for (uint32_t j : cull.drawn)
      if (!changedBefore[j]) still.push_back(j);
    render(old, still, grown, itemsBefore);
    for (int y = changedWindow.y0; y < changedWindow.y1; ++y)
      for (int x = changedWindow.x0; x < changedWindow.x1; ++x) {
        const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
        itemsBefore[at] = shown(old, itemsBefore[at], itemsGone[at], x, y);
      }
  }
  // Now outside the changed window, and both frames' factors: their pixels in the grown window.
  for (int y = cull.window.y0; y < cull.window.y1; ++y)
    for (int x = cull.window.x0; x < cull.window.x1; ++x) {
      if (y >= changedWindow.y0 && y < changedWindow.y1 && x >= changedWindow.x0 && x < changedWindow.x1) continue;
      const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
      itemsNow[at] = itemsBefore[at] == pxpl5::kNoValue ? pxpl5::kNoValue : elementNow[itemsBefore[at]];
    }
  for (int side = 0; side < 2; ++side) {
    std::vector<uint32_t>& count = w.pixelCount;
    if (count.size() < std::max(old.polygon.size(), now.polygon.size()))
      count.resize(std::max(old.polygon.size(), now.polygon.size()), 0);
    w.counted.clear();
    for (int y = cull.window.y0; y < cull.window.y1; ++y)
      for (int x = cull.window.x0; x < cull.window.x1; ++x) {
        const size_t at = static_cast<size_t>(y) * stride + static_cast<size_t>(x);
        if (const uint32_t i = w.items[side][at]; i != pxpl5::kNoValue && count[i]++ == 0) w.counted.push_back(i);
      }
    std::sort(w.counted.begin(), w.counted.end());
    pxpl5::HemisphereFrame& frame = w.frame[side];
    frame.items = w.items[side];
    frame.factors.clear();
    frame.total = 0;
    for (uint32_t i : w.counted) {
      frame.factors.push_back({i, static_cast<double>(std::exchange(count[i], 0)) * w.pixelShare});
      frame.total += frame.factors.back().factor;
    }
  }

  // The point's share of backs changes by the window's (it must still be kept now: the caller).
  w.pointBacks = old.pointBackShare[p] - old.backShare(w.frame[0], eye) + now.backShare(w.frame[1], eye);
  w.windowable = true;
}

void Solver::Edit::moveShot(State& old, State& now, uint32_t p, uint32_t q, const Window* w) {
  State::KeptShot shot = std::move(*old.keptShots[p]);
  old.keptBytes -= shot.bytes();
  old.keptShots[p].reset();

  // Pixel factors of the elements now. The window's frames are drawn their own way
  // (windowed_correction.h), which may give an element a pixel more or less than a whole frame
  // where two elements meet: such a pixel stays, negative if need be, so that a move and the move
  // back give back the frame they began with. What is left of an element gone from the window is
  // rounding. A pixel that the whole frame gave to an unchanged element and the window to a changed
  // one is then counted twice (the unchanged element keeps it), so the total can exceed 1 by a
  // pixel or so: distribute keeps the energy all the same. The differences are summed in now's
  // scratch.
  std::vector<double>& difference = now.pixelFactor;
  if (w) {
    for (const pxpl5::IdFactor& f : w->frame[0].factors)
      if (const uint32_t i = elementNow[f.id]; i != kNone) difference[i] -= f.factor;
    for (const pxpl5::IdFactor& f : w->frame[1].factors) difference[f.id] += f.factor;
  }
  for (pxpl5::IdFactor& f : shot.factors) {
    f.id = elementNow[f.id];
    if (f.id != kNone) f.factor += std::exchange(difference[f.id], 0.0);
  }
  if (w) {
    for (const pxpl5::IdFactor& f : w->frame[1].factors)
      if (difference[f.id] != 0) shot.factors.push_back({f.id, std::exchange(difference[f.id], 0.0)});
    for (const pxpl5::IdFactor& f : w->frame[0].factors)
      if (const uint32_t i = elementNow[f.id]; i != kNone && difference[i] != 0)
        shot.factors.push_back({i, std::exchange(difference[i], 0.0)});
  }
  std::erase_if(shot.factors,
                [&](const pxpl5::IdFactor& f) { return f.id == kNone || std::abs(f.factor) < 1e-3 * now.pixelShare; });
  shot.total = 0;
  for (const pxpl5::IdFactor& f : shot.factors) shot.total += f.factor;

  // The receivers judged before, but those the window judged again, chunk by chunk; then those,
  // judged on its frame now (with the pixel factors now), in the last chunk.
  rejudged.assign(old.polygon.size(), 0);
  if (w)
    for (uint32_t j : w->judged[0]) rejudged[j] = 1;
  State::KeptShot::ChunkStart to{}, from{};
  for (size_t c = 0; c < State::kReceiverChunks; ++c) {
    const State::KeptShot::ChunkStart end = shot.chunkStart[c + 1];
    for (; from.judged < end.judged; ++from.judged) {
      const State::Judged k = shot.judged[from.judged];
      NearPlanSize size{};
      if (k.integrated()) size = shot.plans.sizes[from.plans++];
      if (const uint32_t i = elementNow[k.element]; !rejudged[k.element] && i != kNone) {
        shot.judged[to.judged++] = {i, k.kind, k.value};
        if (k.integrated()) {
          shot.plans.sizes[to.plans++] = size;
          std::copy_n(shot.plans.steps.begin() + from.steps, size.steps, shot.plans.steps.begin() + to.steps);
          std::copy_n(shot.plans.factors.begin() + from.factors, size.factors, shot.plans.factors.begin() + to.factors);
          to.steps += size.steps, to.factors += size.factors;
        }
      }
      from.steps += size.steps, from.factors += size.factors;
    }
    shot.chunkStart[c + 1] = to;
  }
  shot.judged.resize(to.judged);
  shot.plans.sizes.resize(to.plans);
  shot.plans.steps.resize(to.steps);
  shot.plans.factors.resize(to.factors);
  if (w) {
    for (const pxpl5::IdFactor& f : shot.factors) now.pixelFactor[f.id] = f.factor;
    const HemisphereAxes axes = hemisphereAxes(glm::vec3(now.surfaceNormal[now.patchSurface[q]]));
    now.readyToJudge(q);
    for (uint32_t i : w->judged[1]) {
      const State::Judgement& j = judging.judgement;
      now.judgeReceivers(q, w->frame[1], axes, i, i + 1, judging, judging.judgement);
      shot.judged.insert(shot.judged.end(), j.judged.begin(), j.judged.end());
      shot.plans.sizes.insert(shot.plans.sizes.end(), j.plans.sizes.begin(), j.plans.sizes.end());
      shot.plans.steps.insert(shot.plans.steps.end(), j.plans.steps.begin(), j.plans.steps.end());
      shot.plans.factors.insert(shot.plans.factors.end(), j.plans.factors.begin(), j.plans.factors.end());
    }
    for (const pxpl5::IdFactor& f : shot.factors) now.pixelFactor[f.id] = 0;
    shot.chunkStart.back() = {static_cast<uint32_t>(shot.judged.size()), static_cast<uint32_t>(shot.plans.sizes.size()),
                              static_cast<uint32_t>(shot.plans.steps.size()), static_cast<uint32_t>(shot.plans.factors.size())};
  }
  now.storeShot(q, std::move(shot));
}

Solver::Edit::Window& Solver::Edit::windowOf(State& now, uint32_t p) {
  if (nextPrepared && windows[1]->patch == p) {
    nextPrepared = false;
    return *windows[1];
  }
  const int resolution = before->settings.resolution;
  for (std::unique_ptr<Window>& w : windows)
    if (!w) w = std::make_unique<Window>(resolution);
  nextPrepared = !pending.empty();
  const uint32_t next = nextPrepared ? pending.back().patch : kNone;
  now.renderer.runOnGraphicsProcessors(nextPrepared ? 2 : 1,
                                       [&](size_t k, int) { findWindow(now, k == 0 ? p : next, *windows[k]); });
  return *windows[0];
}

bool Solver::frameInWindow(uint32_t p) {
  Edit& e = *edit_;
  State &before = *e.before, &now = *state_;
  // The frame now is made from p's kept one before (which its take-back has done with), and kept
  // as q's.
  if (!before.settings.windowedCorrections || !before.keptShot(p)) return false;
  const Edit::Window& w = e.windowOf(now, p);
  now.stats.frames += w.frames;
  if (!w.windowable) return false;
  const uint32_t q = w.now;
  if (!now.pointChosen[q]) {
    if (w.pointBacks > kMostBacks) return false;
    now.adoptPoint(q, before.patchCentre[p], before.patchRadius[p], w.pointBacks);
  }
  e.moveShot(before, now, p, q, &w);
  return true;
}

size_t Solver::pendingCorrections() const { return edit_ ? edit_->pending.size() : 0; }

double Solver::pendingCorrectionShare() const {
  if (!edit_ || edit_->pending.empty() || edit_->editPower <= 0) return 0;
  return std::max(0.0, edit_->pendingPower / edit_->editPower);
}

std::optional<Shooter> Solver::nextShooter() const {
  const State& s = *state_;
  double best = 0;
  std::optional<Shooter> next;
  for (uint32_t p = 0; p < s.unshot.size(); ++p) {
    const double power = channelSum(s.unshot[p]) * s.patchArea[p];
    if (power > best) best = power, next = Shooter{p, s.patchSurface[p], kPi * s.unshot[p] * s.patchArea[p]};
  }
  return next;
}

bool Solver::step() {
  const auto start = std::chrono::steady_clock::now();
  if (correct()) {
    state_->stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    DCHECK_LT(ledgerResidual(), kLedgerTolerance);
    return true;
  }
  State& s = *state_;
  // A patch's first shot settles the point it shoots from; when that splits the patch, the
  // shooter is chosen again.
  std::optional<Shooter> next;
  const pxpl5::HemisphereFrame* frame = nullptr;
  do {
    next = nextShooter();
    if (!next) return false;
    frame = s.pointChosen[next->patch] ? nullptr : s.choosePoint(next->patch);
  } while (!s.pointChosen[next->patch]);
  s.shoot(next->patch, frame);
  ++s.stats.shots;
  s.stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  DCHECK_LT(ledgerResidual(), kLedgerTolerance);
  return true;
}

double Solver::unshotFraction() const {
  const State& s = *state_;
  const double emitted = channelSum(s.stats.emittedPower);
  if (emitted <= 0) return 0;
  double unshotPower = 0;
  for (size_t p = 0; p < s.unshot.size(); ++p) unshotPower += kPi * channelSum(s.unshot[p]) * s.patchArea[p];
  return unshotPower / emitted;
}

glm::dvec3 Solver::unshotPower() const {
  const State& s = *state_;
  glm::dvec3 power{0};
  for (size_t p = 0; p < s.unshot.size(); ++p) power += kPi * s.unshot[p] * s.patchArea[p];
  return power;
}

double Solver::ledgerResidual() const {
  const Stats& s = state_->stats;
  const auto sum = [](const glm::dvec3& v) { return v.x + v.y + v.z; };  // signed, unlike channelSum
  const double emitted = sum(s.emittedPower);
  if (emitted <= 0) return 0;
  return std::abs(emitted - sum(s.absorbedPower) - sum(s.backPower) - sum(s.escapedPower) - sum(s.removedPower) -
                  sum(unshotPower())) /
         emitted;
}

uint64_t Solver::solve(double fraction, uint64_t maxShots) {
  uint64_t shots = 0;
  while (shots < maxShots && !converged(fraction) && step()) ++shots;
  return shots;
}

std::span<const glm::dvec3> Solver::elementRadiance(uint32_t surface) const {
  const State::SurfaceData& s = state_->surfaces.at(surface);
  return {state_->radiance.data() + s.firstElement, s.elementCount};
}

glm::dvec3 Solver::ambient() const {
  const State& s = *state_;
  std::vector<SurfaceLight> lights;
  lights.reserve(s.unshot.size());
  for (size_t p = 0; p < s.unshot.size(); ++p)
    lights.push_back({s.patchArea[p], s.surfaces[s.patchSurface[p]].reflectance, s.unshot[p]});
  return ambientRadiance(lights);
}

std::vector<glm::dvec3> Solver::vertexRadiance(uint32_t surface, const glm::dvec3& ambientTerm) const {
  const State& st = *state_;
  const State::SurfaceData& s = st.surfaces.at(surface);
  std::vector<glm::dvec3> sum(s.vertexCount, glm::dvec3(0));
  std::vector<double> weight(s.vertexCount, 0.0);
  for (uint32_t e = 0; e < s.elementCount; ++e) {
    const uint32_t j = s.firstElement + e;
    for (int k = 0; k < st.polygon[j].n; ++k) {
      sum[s.corners[e][k]] += st.area[j] * st.radiance[j];
      weight[s.corners[e][k]] += st.area[j];
    }
  }
  const glm::dvec3 extra = s.reflectance * ambientTerm;
  for (size_t v = 0; v < sum.size(); ++v)
    if (weight[v] > 0) sum[v] = sum[v] / weight[v] + extra;
  return sum;
}

const Stats& Solver::stats() const { return state_->stats; }
size_t Solver::surfaceCount() const { return state_->surfaces.size(); }
size_t Solver::elementCount() const { return state_->polygon.size(); }
size_t Solver::patchCount() const { return state_->unshot.size(); }
size_t Solver::vertexCount() const {
  size_t count = 0;
  for (const State::SurfaceData& s : state_->surfaces) count += s.vertexCount;
  return count;
}

}  // namespace radiosity

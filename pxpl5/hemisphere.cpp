// The form-factor service: validates the polygons, runs one machine frame with the chosen
// projection's setup program and sums each id's pixel weights.
//
// Sections: local frame and clipping | HemisphereRenderer.
#include "pxpl5/projections.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace pxpl5 {

// ---- local frame and clipping ------------------------------------------------------------

LocalFrame localFrame(const Viewpoint& view) {
  LocalFrame f;
  f.origin = glm::dvec3(view.point);
  f.z = glm::normalize(glm::dvec3(view.normal));
  // Duff et al. (2017), "Building an orthonormal basis, revisited": no branch on a near axis.
  const double sign = std::copysign(1.0, f.z.z);
  const double a = -1.0 / (sign + f.z.z), b = f.z.x * f.z.y * a;
  f.x = {1.0 + sign * f.z.x * f.z.x * a, sign * b, -sign * f.z.x};
  f.y = {b, sign + f.z.y * f.z.y * a, -f.z.y};
  return f;
}

int clipToHalfSpace(const glm::dvec3* in, int n, const glm::dvec3& k, glm::dvec3* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3& a = in[i];
    const glm::dvec3& b = in[i + 1 < n ? i + 1 : 0];
    const double da = glm::dot(k, a), db = glm::dot(k, b);
    if (da >= 0) out[m++] = a;
    if ((da >= 0) != (db >= 0)) {
      const glm::dvec3& inside = da >= 0 ? a : b;
      const glm::dvec3& outside = da >= 0 ? b : a;
      const double di = std::max(da, db), dOut = std::min(da, db);
      out[m++] = inside + (di / (di - dOut)) * (outside - inside);
    }
  }
  return m;
}

int localPolygon(const ProjectionInput& in, size_t index, glm::dvec3* v, glm::dvec3& normal, double& offset) {
  const Polygon& polygon = in.soup->polygons[index];
  for (uint32_t skip : in.skipIds)
    if (skip == polygon.id) return 0;
  const int n = static_cast<int>(polygon.vertexCount);
  for (int k = 0; k < n; ++k) v[k] = in.frame.localFromWorld(in.soup->vertices[polygon.firstVertex + static_cast<uint32_t>(k)]);
  // Newell's normal, robust for any planar winding; its length is twice the area.
  normal = glm::dvec3(0.0);
  glm::dvec3 centre(0.0);
  double extent2 = 0;
  for (int k = 0; k < n; ++k) {
    const glm::dvec3& a = v[k];
    const glm::dvec3& b = v[k + 1 < n ? k + 1 : 0];
    normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    centre += a;
    const glm::dvec3 e = b - v[0];
    extent2 = std::max(extent2, glm::dot(e, e));
  }
  offset = glm::dot(normal, centre) / static_cast<double>(n);  // one division, not three
  // The point's own plane (or a degenerate polygon): seen edge-on, it covers nothing. The plane's
  // distance |offset| / |normal| against 1e-6 of the polygon's size, squared.
  const double normal2 = glm::dot(normal, normal);
  if (!(normal2 > 0) || offset * offset <= 1e-12 * normal2 * extent2) return 0;
  return n;
}

void screenSize(Projection projection, int resolution, int& width, int& height) {
  width = resolution;
  height = projection == Projection::kHemisphere ? resolution : 3 * resolution;
}

// ---- HemisphereRenderer ------------------------------------------------------------------

// A polygon's pixels are summed in integers: counted on the disk, whose pixels all weigh the
// same, and in units of 2^-62 on the hemicube, where every float weight is a whole number of
// them (down to 2^-39). The sums are then exact, so the order in which the renderers finish
// their regions, and their number, cannot change a factor.
constexpr double kWeightUnit = 0x1p-62;

struct HemisphereRenderer::State {
  HemisphereSettings settings;
  Machine machine;
  std::vector<float> weights;
  std::vector<std::vector<int64_t>> sums;  // per renderer, per polygon index; zero between frames
  double diskShare = 0;                    // the weight of every disk pixel (hemisphere projection)
  // Per row, the pixels [weightedBegin, weightedEnd) from the first to the last of weight > 0:
  // the per-id sums skip the rest (outside the disk, never written), a fifth of the disk's square.
  std::vector<int> weightedBegin, weightedEnd;
  HemisphereFrame frame;

  State(const HemisphereSettings& s, const MachineSettings& m)
      : settings(s), machine(m), sums(static_cast<size_t>(m.graphicsProcessors)) {}
};

namespace {

MachineSettings machineSettings(const HemisphereSettings& s) {
  if (s.resolution < 8 || s.resolution % 2 != 0) throw std::invalid_argument("pxpl5: the resolution must be even and at least 8");
  MachineSettings m;
  screenSize(s.projection, s.resolution, m.width, m.height);
  m.graphicsProcessors = s.graphicsProcessors;
  m.evaluator = s.evaluator;
  return m;
}

void validate(const PolygonSoup& soup) {
  for (size_t i = 0; i < soup.polygons.size(); ++i) {
    const Polygon& p = soup.polygons[i];
    if (p.vertexCount < 3 || p.vertexCount > kMaxPolygonVertices)
      throw std::invalid_argument("pxpl5: polygon " + std::to_string(i) + " has " + std::to_string(p.vertexCount) + " vertices (3 to 24 allowed)");
    if (p.firstVertex > soup.vertices.size() || p.vertexCount > soup.vertices.size() - p.firstVertex)
      throw std::invalid_argument("pxpl5: polygon " + std::to_string(i) + " uses vertices past the end of the vertex array");
  }
}

}  // namespace

HemisphereRenderer::HemisphereRenderer(const HemisphereSettings& settings)
    : state_(std::make_unique<State>(settings, machineSettings(settings))) {
  State& st = *state_;
  if (settings.projection == Projection::kHemisphere)
    loadHemispherePlanes(st.machine, settings.resolution, st.weights);
  else
    loadHemicubePlanes(st.machine, settings.resolution, st.weights);
  st.frame.weights = st.weights;
  // In double: 1 / (pixels of the disk), so that a closed scene sums to 1 to rounding.
  st.diskShare = 1.0 / static_cast<double>(std::count_if(st.weights.begin(), st.weights.end(), [](float w) { return w > 0; }));
  st.frame.width = st.machine.settings().width;
  st.frame.height = st.machine.settings().height;
  st.frame.stride = st.machine.pixelStride();
  for (int y = 0; y < st.frame.height; ++y) {
    const float* row = st.weights.data() + static_cast<size_t>(y) * static_cast<size_t>(st.frame.stride);
    int begin = 0, end = st.frame.width;
    while (begin < end && !(row[begin] > 0)) ++begin;
    while (end > begin && !(row[end - 1] > 0)) --end;
    st.weightedBegin.push_back(begin);
    st.weightedEnd.push_back(end);
  }
}

HemisphereRenderer::~HemisphereRenderer() = default;

const HemisphereSettings& HemisphereRenderer::settings() const { return state_->settings; }
const FrameCounters& HemisphereRenderer::counters() const { return state_->machine.counters(); }

const HemisphereFrame& HemisphereRenderer::render(const Viewpoint& view, const PolygonSoup& soup) {
  return render(view, soup, {0, 0, state_->frame.width, state_->frame.height});
}

const HemisphereFrame& HemisphereRenderer::render(const Viewpoint& view, const PolygonSoup& soup, PixelRect window) {
  State& st = *state_;
  validate(soup);
  if (!(glm::length(view.normal) > 0)) throw std::invalid_argument("pxpl5: the viewpoint's normal is zero");

  // One machine frame. Each renderer sums the pixels of each polygon in the regions it
  // finishes, a run of equal items at a time, while the others still render.
  ProjectionInput input{&soup, localFrame(view), view.skipIds, st.settings.resolution};
  const bool hemisphere = st.settings.projection == Projection::kHemisphere;
  const bool reference = st.settings.evaluator == Evaluator::kScalarReference;  // plain set-up and pixels
  for (std::vector<int64_t>& sums : st.sums)
    if (sums.size() < soup.polygons.size()) sums.resize(soup.polygons.size(), 0);
  const std::span<const uint32_t> itemPlane = st.machine.valuePlane();
  const size_t stride = static_cast<size_t>(st.machine.pixelStride());
  const auto sumRegion = [&](PixelRect region, int renderer) {
    int64_t* sums = st.sums[static_cast<size_t>(renderer)].data();
    for (int y = region.y0; y < region.y1; ++y) {
      const uint32_t* items = itemPlane.data() + static_cast<size_t>(y) * stride;
      const float* weights = st.weights.data() + static_cast<size_t>(y) * stride;
      const int x1 = std::min(region.x1, st.weightedEnd[static_cast<size_t>(y)]);
      for (int x = std::max(region.x0, st.weightedBegin[static_cast<size_t>(y)]); x < x1;) {
        const uint32_t item = items[x];
        int runEnd = x + 1;
        while (runEnd < x1 && items[runEnd] == item) ++runEnd;
        if (item != kNoValue) {
          if (hemisphere) {
            sums[item] += runEnd - x;
          } else {
            for (int k = x; k < runEnd; ++k) sums[item] += static_cast<int64_t>(static_cast<double>(weights[k]) / kWeightUnit);
          }
        }
        x = runEnd;
      }
    }
  };
  st.machine.renderFrame(
      window, soup.polygons.size(),
      [&](size_t begin, size_t end, Emitter& out) {
        if (hemisphere && reference)
          setupHemisphereReference(input, begin, end, out);
        else if (hemisphere)
          setupHemisphere(input, begin, end, out);
        else
          setupHemicube(input, begin, end, out);
      },
      256, sumRegion);

  // Per id, ascending; ids usually come ascending already, then no sort is needed.
  HemisphereFrame& frame = st.frame;
  frame.items = itemPlane;
  frame.factors.clear();
  const double scale = hemisphere ? st.diskShare : kWeightUnit;
  // The renderers' sums into the first one's, in whole loops (this part runs on one thread).
  const size_t polygons = soup.polygons.size();
  int64_t* sums = st.sums[0].data();
  for (size_t r = 1; r < st.sums.size(); ++r) {
    int64_t* more = st.sums[r].data();
    for (size_t i = 0; i < polygons; ++i) sums[i] += more[i];
    std::fill_n(more, polygons, 0);
  }
  for (size_t i = 0; i < polygons; ++i) {
    const int64_t sum = std::exchange(sums[i], 0);
    if (sum != 0) frame.factors.push_back({soup.polygons[i].id, static_cast<double>(sum) * scale});
  }
  const auto byId = [](const IdFactor& a, const IdFactor& b) { return a.id < b.id; };
  if (!std::is_sorted(frame.factors.begin(), frame.factors.end(), byId)) std::stable_sort(frame.factors.begin(), frame.factors.end(), byId);
  size_t kept = 0;
  for (size_t i = 0; i < frame.factors.size(); ++i) {
    if (kept > 0 && frame.factors[kept - 1].id == frame.factors[i].id)
      frame.factors[kept - 1].factor += frame.factors[i].factor;
    else
      frame.factors[kept++] = frame.factors[i];
  }
  frame.factors.resize(kept);
  frame.total = 0;
  for (const IdFactor& f : frame.factors) frame.total += f.factor;
  return frame;
}

void HemisphereRenderer::runOnGraphicsProcessors(size_t taskCount, const std::function<void(size_t, int)>& job) {
  state_->machine.runOnGraphicsProcessors(taskCount, job);
}

}  // namespace pxpl5

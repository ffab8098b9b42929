#include "radiosity/windowed_correction.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity {

namespace {

// The range of dot(direction, axis) over the directions within angle a of unit u, given
// `along` = dot(u, axis) = cos theta and a's cosine and sine: cos(theta -+ a).
void coneRange(double along, double cosAngle, double sinAngle, double& lo, double& hi) {
  const double across = std::sqrt(std::max(0.0, 1.0 - along * along));
  hi = along >= cosAngle ? 1.0 : along * cosAngle + across * sinAngle;
  lo = along <= -cosAngle ? -1.0 : along * cosAngle - across * sinAngle;
}

// Pixels whose centres' x (or y) can be nearest to a value in [lo, hi], one more each side.
void pixelRange(double lo, double hi, int resolution, int& p0, int& p1) {
  const double half = 0.5 * resolution;
  p0 = static_cast<int>(std::floor(std::max(lo + 1, 0.0) * half)) - 1;
  p1 = static_cast<int>(std::floor(std::min(hi + 1, 2.0) * half)) + 2;
  p0 = std::max(p0, 0), p1 = std::min(p1, resolution);
}

}  // namespace

pxpl5::PixelRect sphereWindow(const HemisphereAxes& axes, const glm::dvec3& eye, int resolution, const glm::dvec3& centre,
                              double radius) {
  const glm::dvec3 toward = centre - eye;
  if (glm::dot(toward, axes.z) < -radius) return {};
  const double d = glm::length(toward);
  // Within 1% of holding the eye the cone's bounds lose their meaning: the whole image.
  if (d <= radius * 1.01) return {0, 0, resolution, resolution};
  const double sinAngle = radius / d, cosAngle = std::sqrt(1 - sinAngle * sinAngle);
  double xLo, xHi, yLo, yHi;
  coneRange(glm::dot(toward, axes.x) / d, cosAngle, sinAngle, xLo, xHi);
  coneRange(glm::dot(toward, axes.y) / d, cosAngle, sinAngle, yLo, yHi);
  pxpl5::PixelRect r;
  pixelRange(xLo, xHi, resolution, r.x0, r.x1);
  pixelRange(yLo, yHi, resolution, r.y0, r.y1);
  return r.empty() ? pxpl5::PixelRect{} : r;
}

pxpl5::PixelRect unite(const pxpl5::PixelRect& a, const pxpl5::PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

bool contains(const pxpl5::PixelRect& outer, const pxpl5::PixelRect& inner) {
  return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}

bool overlaps(const pxpl5::PixelRect& a, const pxpl5::PixelRect& b) {
  return !a.empty() && !b.empty() && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

std::vector<Sphere> sphereClusters(std::span<const glm::dvec3> centre, std::span<const double> radius,
                                   std::span<uint32_t> elements, size_t maxElements) {
  std::vector<Sphere> out;
  std::vector<std::span<uint32_t>> todo{elements};
  while (!todo.empty()) {
    const std::span<uint32_t> group = todo.back();
    todo.pop_back();
    if (group.empty()) continue;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (uint32_t j : group) lo = glm::min(lo, centre[j] - radius[j]), hi = glm::max(hi, centre[j] + radius[j]);
    if (group.size() <= std::max<size_t>(maxElements, 1)) {
      Sphere c{0.5 * (lo + hi), 0};
      for (uint32_t j : group) c.radius = std::max(c.radius, glm::length(centre[j] - c.centre) + radius[j]);
      out.push_back(c);
      continue;
    }
    const glm::dvec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const auto half = group.begin() + static_cast<std::ptrdiff_t>(group.size() / 2);
    // Ties by index, so that the split does not depend on the sort's order.
    std::nth_element(group.begin(), half, group.end(), [&](uint32_t a, uint32_t b) {
      return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
    });
    todo.push_back(group.first(group.size() / 2));
    todo.push_back(group.subspan(group.size() / 2));
  }
  return out;
}

const pxpl5::PixelRect& WindowCull::rectOf(uint32_t j) {
  if (rectMade_[j] != generation_) {
    rect_[j] = sphereWindow(axes_, eye_, resolution_, scene_.centre[j], scene_.radius[j]);
    rectMade_[j] = generation_;
  }
  return rect_[j];
}

void WindowCull::cull(const SceneSpheres& scene, const HemisphereAxes& axes, const glm::dvec3& eye, int resolution,
                      uint32_t skipSurface, const pxpl5::PixelRect& changed) {
  const size_t elements = scene.centre.size(), patches = scene.patchCentre.size();
  scene_ = scene, axes_ = axes, eye_ = eye, resolution_ = resolution, skipSurface_ = skipSurface;
  if (rect_.size() < elements) rect_.resize(elements), rectMade_.resize(elements, 0), drawnMark_.resize(elements, 0);
  ++generation_;
  judged.clear();
  patchRect_.resize(patches);

  // Patches first, then the elements of those that reach the window (all of a patch within it).
  for (size_t p = 0; p < patches; ++p) {
    patchRect_[p] = sphereWindow(axes, eye, resolution, scene.patchCentre[p], scene.patchRadius[p]);
    if (!overlaps(patchRect_[p], changed)) continue;
    const bool inside = contains(changed, patchRect_[p]);
    for (uint32_t k = scene.patchFirst[p]; k < scene.patchLast[p]; ++k) {
      const uint32_t j = scene.patchElements[k];
      if (scene.surface[j] != skipSurface && (inside || overlaps(rectOf(j), changed))) judged.push_back(j);
    }
  }
  drawWithin(changed);
}

void WindowCull::drawWithin(const pxpl5::PixelRect& grown) {
  // Every element that may be drawn in the window, in the elements' order.
  window = grown;
  drawn.clear();
  const uint32_t mark = ++drawGeneration_;
  for (size_t p = 0; p < patchRect_.size(); ++p) {
    if (!overlaps(patchRect_[p], window)) continue;
    const bool inside = contains(window, patchRect_[p]);
    for (uint32_t k = scene_.patchFirst[p]; k < scene_.patchLast[p]; ++k) {
      const uint32_t j = scene_.patchElements[k];
      if (scene_.surface[j] != skipSurface_ && (inside || overlaps(rectOf(j), window))) drawnMark_[j] = mark;
    }
  }
  for (uint32_t j = 0; j < static_cast<uint32_t>(scene_.centre.size()); ++j)
    if (drawnMark_[j] == mark) drawn.push_back(j);
}

}  // namespace radiosity

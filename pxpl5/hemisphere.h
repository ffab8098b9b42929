// Point-to-polygon form factors on the emulated machine: the Nusselt analog (thesis 2.3) as an
// item buffer over the hemisphere's base disk, and Cohen and Greenberg's hemicube (1985) beside
// it for comparison. Uses only the machine's public interface (pxpl5.h) and GLM.
//
// Frames: "world" is the caller's; "local" has the viewpoint at its origin and the normal as +z.
#pragma once

#include "pxpl5/pxpl5.h"

#include <glm/vec3.hpp>

#include <memory>
#include <span>
#include <vector>

namespace pxpl5 {

// Polygon i uses vertices[firstVertex, firstVertex + vertexCount): 3..kMaxPolygonVertices
// world-space points of a planar convex polygon, either winding. Several polygons may share an
// id; their factors add up.
struct Polygon {
  uint32_t firstVertex = 0, vertexCount = 0;
  uint32_t id = 0;
};
constexpr uint32_t kMaxPolygonVertices = 24;

struct PolygonSoup {
  std::span<const glm::vec3> vertices;
  std::span<const Polygon> polygons;
};

enum class Projection {
  kHemisphere,  // orthographic projection of the unit hemisphere onto its base disk
  kHemicube,    // five faces: the top resolution x resolution, the sides resolution x resolution/2
};

struct HemisphereSettings {
  int resolution = 256;  // pixels across the base disk or the hemicube's top face (even, >= 8)
  Projection projection = Projection::kHemisphere;
  int graphicsProcessors = 1;  // threads; the results do not depend on it
  Evaluator evaluator = Evaluator::kVector;  // kScalarReference: also the plain set-up, one polygon at a time
};

struct Viewpoint {
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // non-zero; need not be unit length
  // Polygons with these ids are not drawn (the receiver's own element, say). Searched linearly:
  // meant for a few ids.
  std::span<const uint32_t> skipIds;
};

struct IdFactor {
  uint32_t id = 0;
  double factor = 0;
};

// One frame's result; valid until the renderer's next frame.
struct HemisphereFrame {
  // The form factor from the point to each visible id: ascending ids, each once, factor > 0.
  std::vector<IdFactor> factors;
  double total = 0;  // their sum: 1 minus the share of the hemisphere that sees nothing

  // The item buffer: per pixel, the index into PolygonSoup::polygons of the polygon seen, or
  // kNoValue. Rows of `stride` values, `width` x `height` used. Hemisphere: pixel (i, j) looks
  // along local (x, y, sqrt(1 - x^2 - y^2)) with x = (i + 0.5) * 2 / resolution - 1 and the same
  // for y from j; pixels whose centre is outside the disk have weight 0 and stay kNoValue.
  // Hemicube: the top face in rows [0, resolution), then the +x, -x, +y and -y faces in
  // resolution / 2 rows each (see hemisphere.cpp for their axes).
  std::span<const uint32_t> items;
  std::span<const float> weights;  // per pixel, the share of the form factor; they sum to 1
  int width = 0, height = 0, stride = 0;
};

class HemisphereRenderer {
 public:
  // Owns a Machine sized for the projection and resolution, and its threads. Throws
  // std::invalid_argument for a resolution that is odd or below 8.
  explicit HemisphereRenderer(const HemisphereSettings& settings);
  ~HemisphereRenderer();
  HemisphereRenderer(const HemisphereRenderer&) = delete;
  HemisphereRenderer& operator=(const HemisphereRenderer&) = delete;

  const HemisphereSettings& settings() const;

  // Renders what the point sees over the hemisphere around the normal and sums the weights of
  // each id's pixels. Polygons are clipped at the horizon; polygons whose plane passes through
  // the point (within 1e-6 of their size, the point's own surface) are not drawn; both faces of
  // a polygon are drawn and occlude. Nearer wins per pixel; an exact tie keeps the polygon that
  // comes first. Buffers are reused from frame to frame. Throws std::invalid_argument, naming
  // the polygon, for a vertex range outside `vertices` or a vertex count outside 3..24.
  const HemisphereFrame& render(const Viewpoint& view, const PolygonSoup& soup);
  // The same frame within `window` only (pixels of HemisphereFrame's image; clipped to it): the
  // items inside are the ones the whole frame would have, and factors and total sum the weights
  // of those pixels alone. The items outside are left as earlier frames made them: meaningless
  // for this one. Polygons wholly outside the window are not sent to the renderers. Two frames
  // of one viewpoint that differ only by polygons inside a window are compared that way at the
  // cost of the window.
  const HemisphereFrame& render(const Viewpoint& view, const PolygonSoup& soup, PixelRect window);

  // The machine's counters for the last frame.
  const FrameCounters& counters() const;

  // The machine's graphics processors for the caller's own work between frames
  // (Machine::runOnGraphicsProcessors).
  void runOnGraphicsProcessors(size_t taskCount, const std::function<void(size_t task, int processor)>& job);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace pxpl5

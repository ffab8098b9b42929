// The scene model: what a walkrad-scene/1 file describes (spec/scene-format.md), plus the
// planar surfaces the loader derives from it for the mesher and the display.
#pragma once

#include "mesher/polygon.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

using Vec3 = glm::dvec3;
using Ring3 = std::vector<Vec3>;

enum class Axis { X, Y, Z };
enum class TaperKind { None, Linear, Radial };

struct Material {
  std::string name;
  Vec3 reflectance{0.7};  // diffuse albedo, 0..1 per channel
  Vec3 emission{0};       // outgoing radiance of a Lambertian emitter
};

struct Taper {
  TaperKind kind = TaperKind::None;
  double scale = 1;        // linear: cross-section scale at `to`
  int slices = 1;          // radial: number of stacked bands
  bool bothEnds = false;   // radial: sphere-like instead of a dome
};

struct Hole {
  mesher::Ring2 polygon;                // in the face's 2-D coordinates (see the spec)
  std::optional<uint32_t> fillMaterial;  // index into Scene::materials; none: an open hole
};

struct FaceOverride {
  std::optional<uint32_t> material;
  bool open = false;
  std::optional<double> patchSize;
  std::vector<Hole> holes;
};

struct Solid {
  mesher::Ring2 profile;  // convex, as given (either winding)
  Axis axis = Axis::Y;
  double from = 0, to = 1;
  Taper taper;
  bool inward = false;
  uint32_t material = 0;
  std::optional<double> patchSize;
  std::map<std::string, FaceOverride> faces;  // by face name: "top", "side 2", "side 1.3"
  std::string jsonPath;                        // e.g. objects[2].solids[0]
};

struct Object {
  std::string name;
  bool movable = true;
  Vec3 position{0};
  double rotateYDeg = 0;
  std::optional<double> patchSize;
  std::vector<Solid> solids;
};

struct Camera {
  std::string name;
  Vec3 position{0};
  Vec3 lookAt{0, 0, 1};
  Vec3 up{0, 1, 0};
  double fovYDeg = 60;
};

// One planar polygon with holes in world coordinates, the unit the mesher meshes.
struct Surface {
  Ring3 outer;               // counter-clockwise seen from the front
  std::vector<Ring3> holes;  // clockwise seen from the front
  size_t contactHoles = 0;   // the last holes are footprints of faces resting on it (geometry/contact_cutouts.h)
  Vec3 normal{0, 1, 0};      // unit, toward the front (the side that reflects and emits)
  double area = 0;           // outer minus holes
  uint32_t material = 0;     // index into Scene::materials
  uint32_t object = 0;       // index into Scene::objects
  std::string face;          // "side 2", "top", "top hole 0 fill"
  std::string jsonPath;      // where its face is described, for diagnostics
  double patchSize = 0;      // largest initial patch edge, in scene units

  // The surface's plane is dot(normal, p) = planeOffset().
  double planeOffset() const { return outer.empty() ? 0 : glm::dot(normal, outer.front()); }
};

// What importing a triangle model (glTF) found, for statistics and tests.
struct ImportCounts {
  size_t nodes = 0;       // top-level nodes (each an object when it holds triangles)
  size_t triangles = 0;   // read: strips and fans as triangles, the sidecar's omitted materials
                          // left out, its two-sided ones twice
  size_t degenerate = 0;  // skipped: no area
  size_t tJunctions = 0;  // edges split at a vertex lying on them
  size_t singles = 0;     // surfaces that are one triangle
};

// A scene file's settings.adaptive: adaptive refinement while solving (thesis 5.5;
// document/mesh_adaptation.h), as radiosity::RefinementSettings takes it, with the same defaults.
struct AdaptiveSettings {
  double threshold = 0.25;    // the relative luminance jump across an edge that refines
  double minElementSize = 0;  // the narrowest refined element, scene units; 0: a quarter of each surface's patch size
};

struct Scene {
  std::string file;  // as given to the loader, for messages
  std::string units = "m";
  double metersPerUnit = 1;
  double patchSize = 0;  // settings.patch_size, or derived from the scene's size when absent
  // settings.adaptive (threshold, min_element_size): adaptive refinement while solving, on by
  // default for this scene; absent: off unless asked for (walkrad --adapt-threshold).
  std::optional<AdaptiveSettings> adaptive;
  std::vector<Material> materials;
  std::vector<Object> objects;
  std::vector<Camera> cameras;
  std::vector<Surface> surfaces;
  Vec3 boundsMin{0}, boundsMax{0};  // of all surfaces
  std::optional<ImportCounts> imported;  // for a glTF model

  const Camera* findCamera(const std::string& name) const;
  // Sets boundsMin and boundsMax from the surfaces (after loading, and after a move).
  void computeBounds();
};

// The largest side of the scene's bounding box (Scene::computeBounds), in scene units.
double sceneExtent(const Scene& scene);

// Metres per unit for a `units` value (m, cm, mm, in, ft), or 0 when unknown.
double metersPerUnit(std::string_view units);

}  // namespace engine

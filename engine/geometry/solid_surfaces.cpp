#include "engine/geometry/solid_surfaces.h"

#include "engine/diagnostics.h"

#include <glm/geometric.hpp>
#include <numbers>

#include <algorithm>
#include <cmath>

namespace engine {

namespace {

// The world axes of a profile's two coordinates and of the sweep (spec: SOLID).
struct AxisFrame {
  Vec3 a, b, sweep;
};

AxisFrame axisFrame(Axis axis) {
  switch (axis) {
    case Axis::X: return {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
    case Axis::Y: return {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
    case Axis::Z: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  }
  return {};
}

// Cross-section scale at fraction t of the sweep.
double taperScale(const Taper& taper, double t) {
  switch (taper.kind) {
    case TaperKind::None: return 1;
    case TaperKind::Linear: return 1 + (taper.scale - 1) * t;
    case TaperKind::Radial: {
      const double x = taper.bothEnds ? 2 * t - 1 : t;
      return std::sqrt(std::max(0.0, 1 - x * x));
    }
  }
  return 1;
}

int bandCount(const Taper& taper) { return taper.kind == TaperKind::Radial ? taper.slices : 1; }

Vec3 newellNormal(const Ring3& ring) {
  Vec3 n{0};
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec3& p = ring[i];
    const Vec3& q = ring[(i + 1) % ring.size()];
    n += Vec3{(p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)};
  }
  return n;
}

Vec3 mean(const Ring3& ring) {
  Vec3 sum{0};
  for (const Vec3& p : ring) sum += p;
  return sum / static_cast<double>(ring.size());
}

// Orients `ring` counter-clockwise about the outward direction (away from `interior`), or
// about the inward one, and sets the face's normal.
void orientFace(SolidFace& face, const Vec3& interior, bool inward) {
  Vec3 n = newellNormal(face.ring);
  const bool pointsOut = glm::dot(n, mean(face.ring) - interior) > 0;
  if (pointsOut == inward) {
    std::reverse(face.ring.begin(), face.ring.end());
    n = -n;
  }
  face.normal = glm::normalize(n);
}

void projectToFrame(SolidFace& face) {
  face.ring2.clear();
  for (const Vec3& p : face.ring)
    face.ring2.push_back({glm::dot(p - face.origin, face.u), glm::dot(p - face.origin, face.v)});
}

Ring3 withoutRepeats(const Ring3& ring) {
  Ring3 out;
  for (const Vec3& p : ring)
    if (out.empty() || p != out.back()) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

double ringArea(const Ring3& ring) { return 0.5 * glm::length(newellNormal(ring)); }

// Exact sine and cosine for multiples of 90 degrees, so rotated boundaries stay exact.
void sinCosDegrees(double degrees, double& s, double& c) {
  const double quarter = degrees / 90.0;
  if (quarter == std::floor(quarter)) {
    const long turns = static_cast<long>(std::fmod(quarter, 4.0) + 4) % 4;
    static constexpr double sines[] = {0, 1, 0, -1};
    s = sines[turns];
    c = sines[(turns + 1) % 4];
    return;
  }
  const double r = degrees * std::numbers::pi / 180.0;
  s = std::sin(r);
  c = std::cos(r);
}

std::string facePath(const Solid& solid, const std::string& face) {
  return child(child(solid.jsonPath, "faces"), face);
}

// Validates the holes of one face in the face's 2-D frame (spec: FACE).
void checkHoles(const Scene& scene, const Solid& solid, const SolidFace& face,
                const std::vector<Hole>& holes) {
  const double scale = std::max(mesher::extent(face.ring2), 1e-300);
  const double margin = 1e-9 * scale;
  const std::string base = child(facePath(solid, face.name), "holes");
  for (size_t h = 0; h < holes.size(); ++h) {
    const std::string path = child(child(base, h), "polygon");
    const mesher::Ring2& hole = holes[h].polygon;
    if (!mesher::isSimple(hole)) throw SceneError(Diag::SelfIntersecting, scene.file, path);
    if (std::abs(mesher::signedArea(hole)) <= margin * margin)
      throw SceneError(Diag::Degenerate, scene.file, path);
    for (size_t i = 0; i < hole.size(); ++i)
      if (!mesher::strictlyInsideConvex(face.ring2, hole[i], margin))
        throw SceneError(Diag::HoleOutsideFace, scene.file, path,
                         "point " + std::to_string(i) + " is outside or on the edge of " + face.name);
    for (size_t g = 0; g < h; ++g) {
      const mesher::Ring2& other = holes[g].polygon;
      if (mesher::boundaryDistance(hole, other) <= margin ||
          mesher::containsPoint(hole, other.front()) || mesher::containsPoint(other, hole.front()))
        throw SceneError(Diag::HolesTouch, scene.file, path,
                         "with hole " + std::to_string(g) + " of " + face.name);
    }
  }
}

std::string sideName(size_t edge, int band) {
  std::string name = "side ";
  name.append(std::to_string(edge));
  if (band >= 0) name.append(1, '.').append(std::to_string(band));
  return name;
}

}  // namespace

std::vector<SolidFace> sweepSolid(const Solid& solid) {
  const AxisFrame frame = axisFrame(solid.axis);
  const mesher::Vec2 center = mesher::centroid(solid.profile);
  const size_t n = solid.profile.size();
  const int bands = bandCount(solid.taper);

  // Cross-sections at the band boundaries, in object coordinates.
  std::vector<Ring3> rings(static_cast<size_t>(bands) + 1);
  std::vector<double> scales(rings.size());
  for (size_t k = 0; k < rings.size(); ++k) {
    const double t = static_cast<double>(k) / bands;
    const double sweep = k == rings.size() - 1 ? solid.to : solid.from + t * (solid.to - solid.from);
    scales[k] = taperScale(solid.taper, t);
    for (const mesher::Vec2& p : solid.profile) {
      const mesher::Vec2 q = scales[k] == 1 ? p : center + scales[k] * (p - center);
      rings[k].push_back(frame.a * q.x + frame.b * q.y + frame.sweep * sweep);
    }
  }
  Vec3 interior{0};
  for (const Ring3& ring : rings) interior += mean(ring);
  interior /= static_cast<double>(rings.size());

  std::vector<SolidFace> faces;
  auto capFace = [&](const char* name, size_t k) {
    if (scales[k] <= 0) return;  // an apex
    SolidFace face{name, rings[k], {}, frame.sweep * (k == 0 ? solid.from : solid.to), frame.a, frame.b, {}};
    orientFace(face, interior, solid.inward);
    projectToFrame(face);
    faces.push_back(std::move(face));
  };
  capFace("bottom", 0);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    for (int k = 0; k < bands; ++k) {
      const Ring3& lo = rings[static_cast<size_t>(k)];
      const Ring3& hi = rings[static_cast<size_t>(k) + 1];
      SolidFace face;
      face.name = sideName(i, solid.taper.kind == TaperKind::Radial ? k : -1);
      face.ring = withoutRepeats({lo[i], lo[j], hi[j], hi[i]});
      if (face.ring.size() < 3) continue;
      // u runs along the edge at the `from` end of the face (the `to` end when that is a point).
      const bool lowEdgeIsPoint = lo[i] == lo[j];
      face.origin = lo[i];
      face.u = glm::normalize(lowEdgeIsPoint ? hi[j] - hi[i] : lo[j] - lo[i]);
      const Vec3 across = (hi[i] + hi[j]) * 0.5 - (lo[i] + lo[j]) * 0.5;
      face.v = glm::normalize(across - glm::dot(across, face.u) * face.u);
      orientFace(face, interior, solid.inward);
      projectToFrame(face);
      faces.push_back(std::move(face));
    }
  }
  capFace("top", rings.size() - 1);
  return faces;
}

Placement placementOf(const Object& object) {
  double s = 0, c = 1;
  sinCosDegrees(object.rotateYDeg, s, c);
  // Column-major: positive angles turn +x toward -z (right-hand rule about +y).
  Placement placement;
  placement.worldFromObject = glm::dmat3{c, 0, -s, 0, 1, 0, s, 0, c};
  placement.translation = object.position;
  return placement;
}

void appendSolidSurfaces(const Scene& scene, uint32_t objectIndex, const Solid& solid,
                         std::optional<double> objectPatchSize, std::vector<Surface>& out) {
  const std::vector<SolidFace> faces = sweepSolid(solid);
  for (const auto& [name, override] : solid.faces) {
    const bool exists = std::any_of(faces.begin(), faces.end(),
                                    [&face = name](const SolidFace& f) { return f.name == face; });
    if (!exists) throw SceneError(Diag::UnknownFace, scene.file, facePath(solid, name));
  }

  for (const SolidFace& face : faces)
    if (!std::isfinite(face.normal.x + face.normal.y + face.normal.z))
      throw SceneError(Diag::Degenerate, scene.file, solid.jsonPath, face.name + " has no direction");
  const Placement place = placementOf(scene.objects[objectIndex]);
  const double solidPatch = solid.patchSize.value_or(objectPatchSize.value_or(0));
  for (const SolidFace& face : faces) {
    const auto found = solid.faces.find(face.name);
    const FaceOverride none;
    const FaceOverride& over = found == solid.faces.end() ? none : found->second;
    checkHoles(scene, solid, face, over.holes);  // even on an open face: a wrong hole is a mistake
    if (over.open) continue;

    Surface surface;
    surface.normal = glm::normalize(place.direction(face.normal));
    for (const Vec3& p : face.ring) surface.outer.push_back(place.point(p));
    surface.material = over.material.value_or(solid.material);
    surface.object = objectIndex;
    surface.face = face.name;
    surface.jsonPath = found == solid.faces.end() ? solid.jsonPath : facePath(solid, face.name);
    surface.patchSize = over.patchSize.value_or(solidPatch);
    surface.area = ringArea(surface.outer);

    std::vector<Surface> fills;
    for (size_t h = 0; h < over.holes.size(); ++h) {
      Ring3 hole;
      for (const mesher::Vec2& q : over.holes[h].polygon)
        hole.push_back(place.point(face.origin + face.u * q.x + face.v * q.y));
      // Holes run clockwise about the front normal, fills counter-clockwise.
      if (glm::dot(newellNormal(hole), surface.normal) > 0) std::reverse(hole.begin(), hole.end());
      const double holeArea = ringArea(hole);
      surface.area -= holeArea;
      if (over.holes[h].fillMaterial) {
        Surface fill = surface;
        fill.outer.assign(hole.rbegin(), hole.rend());
        fill.holes.clear();
        fill.area = holeArea;
        fill.material = *over.holes[h].fillMaterial;
        fill.face = face.name + " hole " + std::to_string(h) + " fill";
        fills.push_back(std::move(fill));
      }
      surface.holes.push_back(std::move(hole));
    }
    out.push_back(std::move(surface));
    for (Surface& fill : fills) out.push_back(std::move(fill));
  }
}

}  // namespace engine

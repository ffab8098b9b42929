// A surface meshed by the modified quadtree (mesher/mesher.h): the surface laid into its plane,
// meshed there at its patch size, and the mesh's vertices lifted back into the world.
#pragma once

#include "engine/diagnostics.h"
#include "engine/scene.h"
#include "mesher/adaptive_mesh.h"
#include "mesher/mesher.h"

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace engine {

// A 2-D frame in a surface's plane whose counter-clockwise is counter-clockwise about the front
// normal: plane point (x, y) is origin + x u + y v in the world.
struct PlaneFrame {
  Vec3 origin{0}, u{1, 0, 0}, v{0, 1, 0};
  mesher::Vec2 project(const Vec3& p) const;
  // The world point of `p` moved onto the plane of this normal and offset (the frame's own, up to
  // rounding): exactly on it for a frame of world axes at the origin.
  Vec3 lift(mesher::Vec2 p, const Vec3& normal, double offset) const;
};

struct SurfaceMesh {
  mesher::PolygonWithHoles polygon;  // the surface in plane coordinates (outer, then holes), as meshed
  mesher::Mesh mesh;                 // in plane coordinates; elements counter-clockwise from the front
  std::vector<Vec3> positions;       // per mesh vertex, world; the surface's own points exact
  // Per element, its key (radiosity::Surface::keys): its handle in an adaptive mesh of `polygon`
  // (elementKey), which numbers a mesh as meshed as the mesher does, element i {slot i, generation 0}.
  std::vector<uint64_t> keys;
  // Where the plane coordinates lie in the world: the frame they were meshed in, moved along
  // with the surface since.
  PlaneFrame worldFromPlane;
};

// The key of an adaptive mesh's element: its slot and generation, unique while it lives.
uint64_t elementKey(mesher::ElementId id);
std::vector<uint64_t> elementKeys(std::span<const mesher::ElementId> ids);

// The in-plane axes (u, v), counter-clockwise about `normal`, of a plane whose normal is a
// world axis: world axes themselves, so coordinates laid down in it stay exact. Nothing for
// other normals.
std::optional<std::pair<Vec3, Vec3>> axisPlaneAxes(const Vec3& normal);

// Plane coordinates are two world axes when the surface faces along one (exact coordinates,
// axis-aligned edges stay axis-aligned), else axes along its longest outer edge. Meshes with
// `mesher`, whose memory carries over from surface to surface. Throws mesher::MeshRefused for a
// surface the mesher refuses (meshRefusal says where).
SurfaceMesh meshSurface(const Surface& surface, mesher::Mesher& mesher);

// The scene error for a polygon the mesher refused: MeshTooLarge or MeshTooFine, at `place`
// (a surface's JSON path, or a polygon case's "outer") of `file`; `which`, when given, opens the
// detail (the face, when the place is a whole solid's).
SceneError meshRefusal(const mesher::MeshRefused& refused, const std::string& file, const std::string& place,
                       const std::string& which = {});

// World positions for the vertices of `mesh` after those it has positions for (a mesh as meshed
// has none yet; an adaptive mesh of SurfaceMesh::polygon adds vertices after its own), through
// mesh.worldFromPlane onto `surface`'s plane. A mesh with none takes the surface's own points,
// which such meshes list first in the same order, exact.
void addWorldPositions(const Surface& surface, SurfaceMesh& mesh);

// The surface's rings in the plane coordinates `frameOf` is meshed in (a surface in the same
// plane), counter-clockwise about the front normal.
mesher::PolygonWithHoles planePolygon(const Surface& surface, const Surface& frameOf);
// The same in `frame`'s coordinates (a mesh's worldFromPlane, moved along with its surface).
mesher::PolygonWithHoles planePolygon(const Surface& surface, const PlaneFrame& frame);

}  // namespace engine

// A surface meshed by the modified quadtree (mesher/mesher.h): the surface laid into its plane,
// meshed there at its patch size, and the mesh's vertices lifted back into the world.
#pragma once

#include "engine/diagnostics.h"
#include "engine/scene.h"
#include "mesher/mesher.h"

#include <optional>
#include <utility>
#include <vector>

namespace engine {

struct SurfaceMesh {
  mesher::PolygonWithHoles polygon;  // the surface in plane coordinates (outer, then holes)
  mesher::Mesh mesh;                 // in plane coordinates; elements counter-clockwise from the front
  std::vector<Vec3> positions;       // per mesh vertex, world; the surface's own points exact
};

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

// World positions of the vertices of a mesh of `surface` in its plane coordinates (as
// meshSurface meshes it, or an adaptive mesh of SurfaceMesh::polygon): the surface's own points,
// which such meshes list first in the same order, exact.
std::vector<Vec3> worldPositions(const Surface& surface, const std::vector<mesher::Vec2>& vertices);

// The inverse: world points of `surface`'s plane in its plane coordinates (a mesh moved along
// with its surface, whose plane coordinates are those of where it was).
std::vector<mesher::Vec2> planeVertices(const Surface& surface, const std::vector<Vec3>& positions);

// The surface's rings in the plane coordinates `frameOf` is meshed in (a surface in the same
// plane), counter-clockwise about the front normal.
mesher::PolygonWithHoles planePolygon(const Surface& surface, const Surface& frameOf);

}  // namespace engine

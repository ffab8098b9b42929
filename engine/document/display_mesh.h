// What the display draws: triangles with per-vertex linear radiance (Gouraud shading), and the
// element edges for the wireframe. The radiance comes from the radiosity solver (lighting.h);
// before any light is shot it is "emission plus reflectance under the ambient term" of
// radiosity/ambient.h.
#pragma once

#include "engine/geometry/meshed_scene.h"
#include "engine/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace engine {

struct DisplayMesh {
  // Positions are world coordinates less `origin` (the middle of the meshes' bounds): float keeps
  // a room 900 km from the world's origin to 6 cm, and to a micrometre about its own middle.
  glm::dvec3 origin{0};
  std::vector<glm::vec3> positions;  // per vertex, world coordinates less `origin`
  std::vector<glm::vec3> radiance;   // per vertex, linear RGB
  std::vector<float> area;           // per vertex: a third of the area of its triangles
  std::vector<uint32_t> triangles;   // 3 indices per triangle, counter-clockwise from the front
  std::vector<uint32_t> edges;       // 2 indices per element edge
  size_t elements = 0, quads = 0;    // mesh elements (quads are drawn as two triangles)
  // Surface i owns vertices [surfaceVertexStart[i], surfaceVertexStart[i + 1]); each block starts
  // with the surface's own points (outer ring, then holes) at their exact coordinates.
  std::vector<uint32_t> surfaceVertexStart;
  // Surface i's element edges are the index pairs in edges[surfaceEdgeStart[i], surfaceEdgeStart[i + 1]).
  std::vector<uint32_t> surfaceEdgeStart;

  size_t triangleCount() const { return triangles.size() / 3; }
};

// The display's geometry of meshed surfaces (radiance left 0): quads split into two triangles,
// each element edge once. Its origin is the middle of the meshes' bounds unless given (a rebuild
// that carries another mesh's radiance keeps that mesh's origin: carryRadiance).
DisplayMesh displayMesh(const MeshedScene& meshed, std::optional<glm::dvec3> origin = {});

// Radiance for `fresh`, rebuilt from the same surfaces after some were meshed again, until the
// solver has lit it: a surface whose vertex count is unchanged keeps its radiance vertex by
// vertex; a remeshed one gives each vertex the radiance of an old vertex at the same place, or
// the surface's old mean where there is none. Both meshes have the same origin.
void carryRadiance(const DisplayMesh& old, DisplayMesh& fresh);

// Copies the positions of `surfaces` from `meshed` (after they moved; same meshes), less mesh.origin.
void updatePositions(const MeshedScene& meshed, const std::vector<uint32_t>& surfaces, DisplayMesh& mesh);

// The display after an object moved (the window's drag, `render --move`): its surfaces `moved`
// take their new positions, or, when `rebuild` (some surface was meshed again), the display is
// made anew from `meshed` with the light it had carried over (carryRadiance). Returns whether it
// was made anew (all of it to upload) rather than moved (positions only).
bool followMove(const MeshedScene& meshed, const std::vector<uint32_t>& moved, bool rebuild, DisplayMesh& mesh);

// Shades every surface with its emission plus its reflectance times the scene's ambient
// radiance (the picture before any light is shot); returns that ambient radiance.
glm::dvec3 shadeWithAmbient(const Scene& scene, DisplayMesh& mesh);

// An exposure that maps the area-weighted log-average luminance of the mesh to `key` (Reinhard
// et al. 2002), so small bright emitters do not darken the picture. 1 for an empty mesh.
double autoExposure(const DisplayMesh& mesh, double key = 0.25);

}  // namespace engine

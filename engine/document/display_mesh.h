// What the display draws: triangles with per-vertex linear radiance (Gouraud shading), and the
// element edges for the wireframe, held surface by surface so that a surface meshed again is
// replaced on its own. The radiance comes from the radiosity solver (lighting.h); before any
// light is shot it is "emission plus reflectance under the ambient term" of radiosity/ambient.h.
#pragma once

#include "engine/geometry/meshed_scene.h"
#include "engine/scene.h"
#include "radiosity/radiosity.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace engine {

// One surface's display: its mesh's vertices in the mesh's order (the surface's own points first,
// outer ring then holes, at their exact coordinates), and indices local to the surface.
struct SurfaceDisplay {
  uint32_t object = 0;               // the object the surface belongs to (Scene::surfaces[s].object)
  std::vector<glm::vec3> positions;  // per vertex, display coordinates (DisplayMesh::origin)
  std::vector<glm::vec3> radiance;   // per vertex, linear RGB
  std::vector<float> area;           // per vertex: its share of its elements' areas (an n-gon's over n)
  std::vector<uint32_t> triangles;   // 3 indices per triangle, counter-clockwise from the front
  std::vector<uint32_t> edges;       // 2 indices per element edge, each edge once
  // The coarsest level of detail: the surface's polygon alone, 3 indices per triangle into the
  // same vertices (its own points, which come first), tiling exactly what the elements tile, for
  // a surface too small on the screen or too evenly lit for its elements to show. Empty when the
  // polygon's triangles would not tile the elements' area (the surface is then always drawn whole).
  std::vector<uint32_t> outline;
  float extent = 0;                  // the diagonal of its positions' bounds
  size_t elements = 0, quads = 0;    // mesh elements (quads are drawn as two triangles)
};

struct DisplayMesh {
  // Display coordinates are world coordinates less `origin` (the middle of the meshes' bounds):
  // float keeps a room 900 km from the world's origin to 6 cm, and to a micrometre about its own
  // middle.
  glm::dvec3 origin{0};
  std::vector<SurfaceDisplay> surfaces;  // per Scene::surfaces, in order
  // Over all surfaces, kept by displayMesh and replaceSurface (read every frame: not summed).
  size_t elements = 0, quads = 0, vertices = 0;

  size_t triangleCount() const;  // summed over the surfaces
};

// The display's geometry of meshed surfaces of `scene` (radiance left 0): quads split into two
// triangles, each element edge once. Its origin is the middle of the meshes' bounds unless given.
DisplayMesh displayMesh(const Scene& scene, const MeshedScene& meshed, std::optional<glm::dvec3> origin = {});

// Display coordinates from world coordinates for `mesh` as built: less its origin.
glm::dmat4 displayFromWorld(const DisplayMesh& mesh);

// The outline (SurfaceDisplay::outline) of a surface's mesh: its polygon's triangles over its
// own points, or none when they do not tile what the elements tile. Made where the mesh is made
// (the document's thread, SurfaceUpdate::outline), not on the thread that draws.
std::vector<uint32_t> surfaceOutline(const SurfaceMesh& meshed);

// One surface's display from its mesh and outline (surfaceOutline), its vertices put through
// `displayFromWorld` (the mesh's own, or another frame's: an object shown through a transform of
// its own), radiance left 0. O(the surface's mesh).
SurfaceDisplay surfaceDisplay(const SurfaceMesh& meshed, uint32_t object, const glm::dmat4& displayFromWorld,
                              std::vector<uint32_t> outline);

// Puts `display` in the place of surface `surface` (its vertex count may differ), keeping the
// mesh's counts.
void replaceSurface(DisplayMesh& mesh, uint32_t surface, SurfaceDisplay display);

// The radiance of the lighting snapshots (displayRadiance): per display vertex, surface after
// surface, each in its mesh's vertex order. Returns false and changes nothing when its length is
// not the mesh's vertex count (the light of other meshes).
bool setRadiance(DisplayMesh& mesh, std::span<const glm::vec3> perVertex);
// The solver's light (displayRadiance) on the display of the meshes the solver lights.
void setRadiance(DisplayMesh& mesh, const radiosity::Solver& solver);

// Shades every surface with its emission plus its reflectance times the scene's ambient
// radiance (the picture before any light is shot); returns that ambient radiance.
glm::dvec3 shadeWithAmbient(const Scene& scene, DisplayMesh& mesh);

// The luminance of a display radiance (Rec. 709 weights, as radiosity::luminance). Inline: the
// display judges millions of vertices with it at each new snapshot.
inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// An exposure that maps the area-weighted log-average luminance of the mesh to `key` (Reinhard
// et al. 2002), so small bright emitters do not darken the picture. 1 for an empty mesh.
double autoExposure(const DisplayMesh& mesh, double key = 0.25);

}  // namespace engine

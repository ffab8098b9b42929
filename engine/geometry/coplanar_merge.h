// Coplanar merging (thesis 3.2): planar pieces of one owner and material that lie in one plane
// and share edges, whole or in part, become maximal planar polygons with holes, so the quadtree
// meshes whole walls and floors and coplanar neighbours cannot meet with T-vertices. One merge
// serves both inputs: a modeller's triangles (glTF) and a scene file's faces. Built for hundreds
// of thousands of pieces: vertices are welded and planes grouped by hashing, edges matched by
// sorting; nothing is compared pairwise.
//
// The rule both share: pieces of one object, or of objects that are all fixed (movable: false),
// of one material, facing the same way and lying in one plane within `tolerance` (scene units),
// that share an edge or part of one, are merged. A vertex lying on another piece's edge (a
// T-junction) splits that edge, so neighbours in a group meet vertex to vertex. Each group becomes
// one surface: an outer ring and holes, with the input's corners exact. Where a group's boundary
// touches itself (two holes meeting at a corner, say), the pieces at the touching corners are
// split off as surfaces of their own and the rest is tried again, so every surface is a polygon
// the mesher accepts. A group with more than 256 holes stays as its pieces. A piece on its own
// keeps its rings, with the vertices splitting its edges added (only its own corners where
// those would make its ring touch itself).
#pragma once

#include "engine/scene.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace engine {

struct SceneTriangle {
  std::array<Vec3, 3> corners;  // world; counter-clockwise seen from the front
  uint32_t material = 0;        // index into Scene::materials
  uint32_t object = 0;          // index into Scene::objects
};

struct TriangleMergeCounts {
  size_t triangles = 0;    // given
  size_t degenerate = 0;   // skipped: a repeated corner, or a height of at most `tolerance`
  size_t tJunctions = 0;   // edges split at a vertex lying on them
  size_t surfaces = 0;     // made
  size_t singles = 0;      // of those, triangles left on their own (no coplanar neighbour, or
                           // cut out of a group whose boundary touched itself)
};

// The relative tolerance the glTF loader merges with: this fraction of the model's bounding-box
// diagonal decides "in the plane" and "on the edge".
constexpr double kMergeTolerance = 1e-5;

// Merges a model's triangles. Ring corners that are exactly collinear and used by no other
// surface are dropped (the modeller's triangulation leaves them along every wall). Surfaces come
// out in a deterministic order; their `face` says how many triangles they are made of; patch size
// and json path are the caller's to set.
std::vector<Surface> mergeTriangles(const Scene& scene, const std::vector<SceneTriangle>& triangles, double tolerance,
                                    TriangleMergeCounts* counts = nullptr);

// Merges a scene file's faces (surfaces as parseSceneFaces makes them, with their holes). Every
// corner of every face is kept: the file's corners are the thesis' exact input vertices. A
// surface merged from several faces keeps the first one's object, normal, json path and place in
// the order, the smallest patch size, and its `face` lists the faces' names joined by " + ". A
// face merged with nothing comes out as it went in, unless a coplanar neighbour's vertex lies on
// one of its edges: that vertex is added to its ring.
std::vector<Surface> mergeFaces(const Scene& scene, std::vector<Surface> faces, double tolerance);

}  // namespace engine

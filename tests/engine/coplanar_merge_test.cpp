// Coplanar merging of a scene file's faces (thesis 3.2), through the loader: touching faces of
// one material in one plane become one surface, with every corner kept.
#include "engine/geometry/coplanar_merge.h"

#include "engine/geometry/surface_mesh.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <tuple>

namespace engine {
namespace {

Json box(double x0, double z0, double x1, double z1, const char* material = "white") {
  return {{"profile", {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}}, {"from", 0}, {"to", 1}, {"material", material}};
}

Scene sceneOf(std::vector<Json> objects) {
  Json j = test::baseScene();
  j["objects"] = objects;
  return test::parse(j);
}

std::vector<const Surface*> facing(const Scene& scene, Vec3 normal) {
  std::vector<const Surface*> out;
  for (const Surface& s : scene.surfaces)
    if (glm::dot(s.normal, normal) > 0.999) out.push_back(&s);
  return out;
}

bool hasCorner(const Ring3& ring, Vec3 p) { return std::find(ring.begin(), ring.end(), p) != ring.end(); }

// Twice the signed area of a ring lying in a plane y = const, counter-clockwise seen from above
// positive.
double twiceAreaFromAbove(const Ring3& r) {
  double sum = 0;
  for (size_t i = 0; i < r.size(); ++i) sum += glm::cross(r[i], r[(i + 1) % r.size()]).y;
  return sum;
}

// Whether `ring` is `given` with corners added between given ones, starting where it started.
bool addsCornersTo(const Ring3& ring, const Ring3& given) {
  size_t matched = 0;
  for (const Vec3& p : ring)
    if (matched < given.size() && p == given[matched]) ++matched;
  return matched == given.size() && !ring.empty() && ring.front() == given.front();
}

TEST(CoplanarMerge, TwoFlushBoxesShareTheirOuterFaces) {
  Json left = box(0, 0, 1, 1), right = box(1, 0, 2, 1);
  left["patch_size"] = 0.5;
  right["patch_size"] = 0.25;
  const Scene scene = sceneOf({{{"name", "pair"}, {"solids", {left, right}}}});
  // Tops, bottoms, fronts and backs merge; the two faces between the boxes face apart and stay.
  EXPECT_EQ(scene.surfaces.size(), 12u - 4);
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  const Surface& top = *tops[0];
  EXPECT_DOUBLE_EQ(top.area, 2);
  EXPECT_DOUBLE_EQ(twiceAreaFromAbove(top.outer), 4);
  EXPECT_TRUE(top.holes.empty());
  // The first face's name, json path and object; the smaller patch size.
  EXPECT_EQ(top.face, "top + top");
  EXPECT_EQ(top.jsonPath, "objects[0].solids[0]");
  EXPECT_EQ(top.patchSize, 0.25);
  // Every corner kept, also the two where the boxes meet, which the fronts and backs use.
  EXPECT_EQ(top.outer.size(), 6u);
  EXPECT_TRUE(hasCorner(top.outer, {1, 1, 0}));
  EXPECT_TRUE(hasCorner(top.outer, {1, 1, 1}));
}

// A wall of two flush solids of one material in different objects that are both fixed.
TEST(CoplanarMerge, FlushWallsOfFixedObjectsBecomeOneSurface) {
  const Scene scene = sceneOf({{{"name", "west"}, {"movable", false}, {"solids", {box(0, 0, 2, 0.1)}}},
                               {{"name", "east"}, {"movable", false}, {"solids", {box(2, 0, 5, 0.1)}}}});
  const auto fronts = facing(scene, {0, 0, -1});
  ASSERT_EQ(fronts.size(), 1u);
  EXPECT_DOUBLE_EQ(fronts[0]->area, 5);
  EXPECT_EQ(scene.objects[fronts[0]->object].name, "west");
}

// Turned by 30 degrees, the boxes' fronts face no world axis; they still merge, with the first
// face's normal and every corner exactly where the faces had it.
TEST(CoplanarMerge, FlushFacesOfATurnedObjectMerge) {
  Json pair = {{"name", "pair"}, {"rotate_y", 30}, {"solids", {box(0, 0, 1, 1), box(1, 0, 2, 1)}}};
  const Scene scene = sceneOf({pair});
  EXPECT_EQ(scene.surfaces.size(), 12u - 4);
  Json apart = test::baseScene();
  apart["objects"] = {pair};
  const Scene faces = parseSceneFaces(apart.dump(), "faces.json");
  for (const Surface& s : scene.surfaces) {
    if (s.face != "side 0 + side 0") continue;
    EXPECT_DOUBLE_EQ(s.area, 2);
    EXPECT_EQ(s.normal, test::surfaceOf(faces, "pair", "side 0").normal);
    for (const Vec3& p : s.outer) {
      bool found = false;
      for (const Surface& f : faces.surfaces) found = found || hasCorner(f.outer, p);
      EXPECT_TRUE(found);
    }
    return;
  }
  ADD_FAILURE() << "the fronts did not merge";
}

// A 2-wide box beside two 1 x 0.5 boxes: the long box's edge meets the short ones at a
// T-junction; it is split, the tops become one, and the junction vertex stays on the outline
// where the two small boxes' merged side uses it.
TEST(CoplanarMerge, TJunctionsAreResolved) {
  const Scene scene = sceneOf({{{"name", "three"}, {"solids", {box(0, 0, 2, 1), box(2, 0, 3, 0.5), box(2, 0.5, 3, 1)}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  EXPECT_DOUBLE_EQ(tops[0]->area, 3);
  EXPECT_DOUBLE_EQ(twiceAreaFromAbove(tops[0]->outer), 6);
  EXPECT_TRUE(hasCorner(tops[0]->outer, {3, 1, 0.5}));
  EXPECT_FALSE(hasCorner(tops[0]->outer, {2, 1, 0.5}));  // inside now
  const auto east = facing(scene, {1, 0, 0});  // the long box's end (x = 2), the short ones' (x = 3)
  ASSERT_EQ(east.size(), 2u);
  const Surface& end = east[0]->outer[0].x == 3 ? *east[0] : *east[1];
  EXPECT_EQ(end.face, "side 1 + side 1");
  EXPECT_TRUE(hasCorner(end.outer, {3, 1, 0.5}));
}

// A face whose neighbour touches its edge at one point only stays apart, and takes the
// neighbour's corner into its ring so the two meshes meet vertex to vertex.
TEST(CoplanarMerge, AFaceTouchedAtOnePointTakesTheCornerIntoItsRing) {
  const Json apex = {{"profile", {{1, 1}, {2, 2}, {0, 2}}}, {"from", 0}, {"to", 1}, {"material", "white"}};
  const Scene scene = sceneOf({{{"name", "two"}, {"solids", {box(0, 0, 2, 1), apex}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 2u);
  const Surface& boxTop = tops[0]->outer.size() == 5 ? *tops[0] : *tops[1];
  const Surface& apexTop = &boxTop == tops[0] ? *tops[1] : *tops[0];
  EXPECT_EQ(boxTop.outer.size(), 5u);
  EXPECT_TRUE(hasCorner(boxTop.outer, {1, 1, 1}));
  EXPECT_EQ(boxTop.face, "top");
  EXPECT_EQ(apexTop.outer.size(), 3u);
}

TEST(CoplanarMerge, ARingOfBoxesLeavesAHole) {
  const Scene scene = sceneOf({{{"name", "ring"},
                                {"solids", {box(0, 0, 3, 1), box(0, 2, 3, 3), box(0, 1, 1, 2), box(2, 1, 3, 2)}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  ASSERT_EQ(tops[0]->holes.size(), 1u);
  EXPECT_DOUBLE_EQ(tops[0]->area, 8);
  EXPECT_DOUBLE_EQ(twiceAreaFromAbove(tops[0]->holes[0]), -2);  // clockwise from the front
}

// A face's own hole survives the merge with its neighbour.
TEST(CoplanarMerge, AFacesHoleIsKeptInTheMergedSurface) {
  Json holed = box(0, 0, 2, 2);
  holed["faces"] = {{"top", {{"holes", {{{"polygon", {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}}}}}}}}};
  const Scene scene = sceneOf({{{"name", "pair"}, {"solids", {holed, box(2, 0, 3, 2)}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 1u);
  ASSERT_EQ(tops[0]->holes.size(), 1u);
  EXPECT_EQ(tops[0]->holes[0].size(), 4u);
  EXPECT_TRUE(hasCorner(tops[0]->holes[0], {0.5, 1, 0.5}));
  EXPECT_DOUBLE_EQ(tops[0]->area, 6 - 1);
  mesher::Mesher mesher;
  ASSERT_NO_THROW(meshSurface(*tops[0], mesher));
}

TEST(CoplanarMerge, DifferentMaterialsStayApart) {
  const Scene scene = sceneOf({{{"name", "two"}, {"solids", {box(0, 0, 1, 1), box(1, 0, 2, 1, "lamp")}}}});
  EXPECT_EQ(facing(scene, {0, 1, 0}).size(), 2u);
  EXPECT_EQ(scene.surfaces.size(), 12u);
}

// A movable object is dragged on its own: none of its faces merges with another object's, fixed
// or movable.
TEST(CoplanarMerge, MovableObjectsAreNeverMergedWithOthers) {
  const Scene movable = sceneOf({{{"name", "a"}, {"solids", {box(0, 0, 1, 1)}}}, {{"name", "b"}, {"solids", {box(1, 0, 2, 1)}}}});
  EXPECT_EQ(facing(movable, {0, 1, 0}).size(), 2u);
  const Scene mixed = sceneOf({{{"name", "a"}, {"movable", false}, {"solids", {box(0, 0, 1, 1)}}},
                               {{"name", "b"}, {"solids", {box(1, 0, 2, 1)}}}});
  EXPECT_EQ(facing(mixed, {0, 1, 0}).size(), 2u);
  for (const Surface& s : mixed.surfaces) EXPECT_EQ(s.face.find(" + "), std::string::npos) << s.face;
}

TEST(CoplanarMerge, FacesTouchingAtACornerOnlyStayApart) {
  const Scene scene = sceneOf({{{"name", "diagonal"}, {"solids", {box(0, 0, 1, 1), box(1, 1, 2, 2)}}}});
  const auto tops = facing(scene, {0, 1, 0});
  ASSERT_EQ(tops.size(), 2u);
  for (const Surface* top : tops) EXPECT_EQ(top->outer.size(), 4u);
}

// An octagonal column's sides are coplanar with nothing: each stays a surface of its own.
TEST(CoplanarMerge, CurvedPartsStayAsTheirOwnSurfaces) {
  Json column = {{"from", 0}, {"to", 2}, {"material", "white"}};
  for (int i = 0; i < 8; ++i) {
    const double a = std::numbers::pi * i / 4;
    column["profile"].push_back({std::cos(a), std::sin(a)});
  }
  const Scene scene = sceneOf({{{"name", "column"}, {"solids", {column}}}});
  EXPECT_EQ(scene.surfaces.size(), 8u + 2);
}

// The merge on the shipped scenes' faces: a face merged with nothing is the polygon it was (with
// at most a neighbour's corners added on its edges), surfaces keep the faces' order (a merged one
// where its first face was), and every corner of a merged surface is a corner of its faces.
TEST(CoplanarMerge, ShippedScenesKeepTheirFacesAndTheirOrder) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "furnace.json"}) {
    SCOPED_TRACE(name);
    const Scene faces = loadSceneFaces(std::string(WALKRAD_ASSETS) + "/" + name);
    const std::vector<Surface> merged = mergeFaces(faces, faces.surfaces, 1e-9 * sceneExtent(faces));
    std::map<std::tuple<uint32_t, std::string, std::string>, size_t> indexOf;
    for (size_t i = 0; i < faces.surfaces.size(); ++i) {
      const Surface& f = faces.surfaces[i];
      indexOf[{f.object, f.jsonPath, f.face}] = i;
    }
    std::set<std::array<double, 3>> corners;
    for (const Surface& f : faces.surfaces) {
      for (const Vec3& p : f.outer) corners.insert({p.x, p.y, p.z});
      for (const Ring3& hole : f.holes)
        for (const Vec3& p : hole) corners.insert({p.x, p.y, p.z});
    }
    size_t previous = 0, unchanged = 0;
    for (size_t k = 0; k < merged.size(); ++k) {
      const Surface& s = merged[k];
      const std::string first = s.face.substr(0, s.face.find(" + "));
      const auto at = indexOf.find({s.object, s.jsonPath, first});
      ASSERT_NE(at, indexOf.end()) << s.jsonPath << " " << s.face;
      EXPECT_TRUE(k == 0 || at->second > previous) << s.face;
      previous = at->second;
      const Surface& f = faces.surfaces[at->second];
      if (s.face == first) {
        if (s.outer == f.outer && s.holes == f.holes) {
          ++unchanged;
        } else {
          EXPECT_TRUE(addsCornersTo(s.outer, f.outer)) << s.face;
          ASSERT_EQ(s.holes.size(), f.holes.size());
          for (size_t h = 0; h < f.holes.size(); ++h) EXPECT_TRUE(addsCornersTo(s.holes[h], f.holes[h])) << s.face;
        }
        EXPECT_EQ(s.area, f.area);
        EXPECT_EQ(s.normal, f.normal);
      } else {
        for (const Vec3& p : s.outer) EXPECT_TRUE(corners.contains({p.x, p.y, p.z})) << s.face;
        for (const Ring3& hole : s.holes)
          for (const Vec3& p : hole) EXPECT_TRUE(corners.contains({p.x, p.y, p.z})) << s.face;
      }
    }
    EXPECT_GT(unchanged, 0u);
  }
}

// Across the shipped scenes, no mesh vertex of one surface lies inside a boundary edge of
// another coplanar surface of the same material: no T-vertex where surfaces that could merge
// meet. (Surfaces of different movable objects are meant to move apart and are not compared.)
TEST(CoplanarMerge, ShippedScenesHaveNoTVerticesBetweenMergeableSurfaces) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
    const Vec3 size = scene.boundsMax - scene.boundsMin;
    const double tolerance = 1e-9 * std::max({size.x, size.y, size.z});
    // Group by material, owner (fixed objects share one) and plane.
    std::map<std::tuple<uint32_t, int64_t, int64_t, int64_t, int64_t, int64_t>, std::vector<size_t>> groups;
    for (size_t i = 0; i < scene.surfaces.size(); ++i) {
      const Surface& s = scene.surfaces[i];
      const int64_t owner = scene.objects[s.object].movable ? s.object : -1;
      auto q = [&](double v, double unit) { return static_cast<int64_t>(std::llround(v / unit)); };
      groups[{s.material, owner, q(s.normal.x, 1e-6), q(s.normal.y, 1e-6), q(s.normal.z, 1e-6), q(s.planeOffset(), 1e-6 * std::max({size.x, size.y, size.z}))}].push_back(i);
    }
    size_t tVertices = 0, compared = 0;
    for (const auto& [key, members] : groups) {
      if (members.size() < 2) continue;
      std::vector<SurfaceMesh> meshes;
      for (size_t m : members) {
        mesher::Mesher mesher;
        meshes.push_back(meshSurface(scene.surfaces[m], mesher));
      }
      for (size_t a = 0; a < meshes.size(); ++a)
        for (size_t b = 0; b < meshes.size(); ++b) {
          if (a == b) continue;
          ++compared;
          const auto& rb = scene.surfaces[members[b]];
          std::vector<Ring3> rings{rb.outer};
          rings.insert(rings.end(), rb.holes.begin(), rb.holes.end());
          for (const Vec3& p : meshes[a].positions)
            for (const Ring3& ring : rings)
              for (size_t i = 0; i < ring.size(); ++i) {
                const Vec3 u = ring[i], w = ring[(i + 1) % ring.size()];
                const double t = glm::dot(p - u, w - u) / glm::dot(w - u, w - u);
                if (t > 1e-9 && t < 1 - 1e-9 && glm::length(p - (u + t * (w - u))) <= tolerance) ++tVertices;
              }
        }
    }
    EXPECT_EQ(tVertices, 0u) << compared << " pairs compared";
  }
}

}  // namespace
}  // namespace engine

// Model checks: each kind of defect found at its place, and none of the serious kinds in the
// shipped scenes.
#include "engine/diagnostics.h"
#include "engine/geometry/model_check.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace engine {
namespace {

// A scene built face by face, as an importer of triangles or polygons would give it.
class FaceScene {
 public:
  FaceScene() { scene_.file = "faces"; }

  // Adds a face to `object` (made when new); its normal follows the ring's winding.
  FaceScene& face(const std::string& object, Ring3 ring, std::string name = {}) {
    uint32_t o = 0;
    while (o < scene_.objects.size() && scene_.objects[o].name != object) ++o;
    if (o == scene_.objects.size()) {
      scene_.objects.emplace_back();
      scene_.objects.back().name = object;
    }
    Surface s;
    Vec3 n{0};
    for (size_t i = 0; i < ring.size(); ++i) n += glm::cross(ring[i], ring[(i + 1) % ring.size()]);
    s.normal = glm::length(n) > 0 ? glm::normalize(n) : Vec3(0, 1, 0);
    s.area = 0.5 * glm::length(n);
    s.outer = std::move(ring);
    s.object = o;
    s.face = name.empty() ? "face " + std::to_string(scene_.surfaces.size()) : name;
    s.jsonPath = "faces[" + std::to_string(scene_.surfaces.size()) + "]";
    scene_.surfaces.push_back(std::move(s));
    return *this;
  }

  // The six faces of an axis-aligned box, facing out (or in).
  FaceScene& box(const std::string& object, Vec3 lo, Vec3 hi, bool inward = false) {
    const auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d, const char* name) {
      face(object, inward ? Ring3{d, c, b, a} : Ring3{a, b, c, d}, name);
    };
    quad({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}, "-x");
    quad({hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}, "+x");
    quad({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}, "-y");
    quad({lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, "+y");
    quad({lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z}, "-z");
    quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, "+z");
    return *this;
  }

  FaceScene& without(const std::string& face) {
    std::erase_if(scene_.surfaces, [&](const Surface& s) { return s.face == face; });
    return *this;
  }

  FaceScene& flip(const std::string& face) {
    for (Surface& s : scene_.surfaces)
      if (s.face == face) {
        std::reverse(s.outer.begin(), s.outer.end());
        s.normal = -s.normal;
      }
    return *this;
  }

  const Scene& scene() const { return scene_; }

 private:
  Scene scene_;
};

std::vector<Finding> ofKind(const std::vector<Finding>& findings, FindingKind kind) {
  std::vector<Finding> out;
  std::copy_if(findings.begin(), findings.end(), std::back_inserter(out), [&](const Finding& f) { return f.kind == kind; });
  return out;
}

const std::string& faceOf(const Scene& scene, const Finding& f) { return scene.surfaces[f.surface].face; }

TEST(ModelCheck, ClosedBoxesAreClean) {
  FaceScene faces;
  faces.box("room", {0, 0, 0}, {4, 3, 5}, true).box("table", {1, 0, 1}, {2, 1, 2});
  EXPECT_TRUE(checkModel(faces.scene()).empty());
}

TEST(ModelCheck, DegenerateFaceIsFound) {
  FaceScene faces;
  faces.box("box", {0, 0, 0}, {1, 1, 1}).face("sliver", {{0, 2, 0}, {1, 2, 0}, {2, 2, 0}}, "collinear");
  const auto found = checkModel(faces.scene());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, FindingKind::DegenerateFace);
  EXPECT_EQ(faceOf(faces.scene(), found[0]), "collinear");
  EXPECT_EQ(severityOf(found[0].kind), Severity::Error);
}

TEST(ModelCheck, DuplicateFaceIsTheLaterCopy) {
  FaceScene faces;
  faces.box("box", {0, 0, 0}, {1, 1, 1}).face("box", {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}, "top again");
  const auto found = ofKind(checkModel(faces.scene()), FindingKind::DuplicateFace);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(faceOf(faces.scene(), found[0]), "top again");
  EXPECT_EQ(faces.scene().surfaces[static_cast<size_t>(found[0].other)].face, "+y");
  EXPECT_NEAR(found[0].point.y, 1, 1e-12);
}

TEST(ModelCheck, CoincidentFacesFacingTheSameWay) {
  // A rug of no thickness on a floor: z-fighting.
  FaceScene faces;
  faces.face("floor", {{0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0}}).face("rug", {{1, 0, 1}, {1, 0, 2}, {2, 0, 2}, {2, 0, 1}}, "rug");
  const auto found = checkModel(faces.scene());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, FindingKind::CoincidentFaces);
  EXPECT_EQ(faceOf(faces.scene(), found[0]), "rug");
  EXPECT_NE(found[0].message.find("100%"), std::string::npos) << found[0].message;
}

TEST(ModelCheck, BackToBackFacesOfOneObjectButNotBetweenObjects) {
  // Two boxes of one object stacked share a face back to back (thesis figure 3.2 a); a box
  // standing on another object is a contact, which contact cut-outs take care of.
  FaceScene stacked;
  stacked.box("shelf", {0, 0, 0}, {1, 1, 1}).box("shelf", {0, 1, 0}, {1, 2, 1});
  const auto found = checkModel(stacked.scene());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, FindingKind::BackToBackFaces);
  EXPECT_NEAR(found[0].point.y, 1, 1e-12);

  FaceScene resting;
  resting.box("table", {0, 0, 0}, {1, 1, 1}).box("vase", {0.2, 1, 0.2}, {0.4, 1.5, 0.4});
  EXPECT_TRUE(checkModel(resting.scene()).empty());
}

TEST(ModelCheck, InterpenetrationIsFoundWhereTheFacesCross) {
  // A post stuck through a table top (both closed boxes): its four sides cross the top's two
  // faces, at the planes y = 1 and y = 1.1.
  FaceScene faces;
  faces.box("table", {0, 1, 0}, {2, 1.1, 2}).box("post", {0.9, 0, 0.9}, {1.1, 2, 1.1});
  const auto found = ofKind(checkModel(faces.scene()), FindingKind::Interpenetration);
  EXPECT_EQ(found.size(), 8u);
  for (const Finding& f : found) {
    EXPECT_TRUE(std::abs(f.point.y - 1) < 1e-9 || std::abs(f.point.y - 1.1) < 1e-9) << f.point.y;
    EXPECT_NEAR(std::max(std::abs(f.point.x - 1), std::abs(f.point.z - 1)), 0.1, 1e-9);
  }
  // Touching along an edge (a wall standing on a floor, a shelf ending at a wall) is not crossing.
  FaceScene touching;
  touching.face("floor", {{0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0}})
      .face("wall", {{1, 0, 2}, {3, 0, 2}, {3, 2, 2}, {1, 2, 2}})
      .face("shelf", {{1, 1, 2}, {1, 1, 3}, {3, 1, 3}, {3, 1, 2}});
  EXPECT_TRUE(ofKind(checkModel(touching.scene()), FindingKind::Interpenetration).empty());
}

TEST(ModelCheck, InconsistentOrientationNamesTheFlippedFace) {
  FaceScene faces;
  faces.box("box", {0, 0, 0}, {1, 1, 1}).flip("+z");
  const auto found = ofKind(checkModel(faces.scene()), FindingKind::InconsistentOrientation);
  // The flipped face runs its four edges the same way as its four neighbours; each pair once,
  // reported on the later face of the pair (the flipped one comes last).
  ASSERT_EQ(found.size(), 4u);
  for (const Finding& f : found) EXPECT_EQ(faceOf(faces.scene(), f), "+z");
}

TEST(ModelCheck, OpenEdgesOfASolidButNotOfASheet) {
  FaceScene faces;
  faces.box("crate", {0, 0, 0}, {1, 1, 1}).without("+y");
  const auto found = ofKind(checkModel(faces.scene()), FindingKind::OpenEdge);
  ASSERT_EQ(found.size(), 1u);  // one opening of four edges
  EXPECT_NE(found[0].message.find("4 edges"), std::string::npos) << found[0].message;
  EXPECT_NEAR(found[0].point.y, 1, 1e-12);

  FaceScene sheet;
  sheet.face("sign", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  EXPECT_TRUE(checkModel(sheet.scene()).empty());
}

TEST(ModelCheck, TJunctionsAreNotOpenings) {
  // The box's +z face in two halves: the long edges of its -y and +y faces meet the halves'
  // corners at x = 1 (T-junctions), and the box is closed all the same.
  FaceScene faces;
  faces.box("crate", {0, 0, 0}, {2, 1, 1}).without("+z");
  faces.face("crate", {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, "+z left");
  FaceScene halfOpen = faces;
  faces.face("crate", {{1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}}, "+z right");
  EXPECT_TRUE(checkModel(faces.scene()).empty());

  // Without the right half the opening is its outline: the stretches of the long edges beyond
  // the T-junctions and the left half's edge between them.
  const auto found = ofKind(checkModel(halfOpen.scene()), FindingKind::OpenEdge);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].message.find("4 edges (4 long)"), std::string::npos) << found[0].message;
}

TEST(ModelCheck, FacadeIsAOneSidedWallSeenFromBehind) {
  // A room (closed, facing in) split by a one-sided partition facing -x: its back is seen
  // from the room's wall at x = 4.
  FaceScene faces;
  faces.box("room", {0, 0, 0}, {4, 3, 5}, true).face("partition", {{2, 0, 1}, {2, 0, 4}, {2, 2, 4}, {2, 2, 1}}, "partition");
  const auto found = checkModel(faces.scene());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, FindingKind::Facade);
  EXPECT_EQ(faceOf(faces.scene(), found[0]), "partition");
  EXPECT_EQ(faces.scene().surfaces[static_cast<size_t>(found[0].other)].face, "+x");
  EXPECT_NEAR(found[0].point.x, 2, 1e-12);
  EXPECT_NE(found[0].message.find(", 2 away"), std::string::npos) << found[0].message;

  // With a second face behind it (a wall of no thickness) both sides are fronts.
  faces.face("partition", {{2, 2, 1}, {2, 2, 4}, {2, 0, 4}, {2, 0, 1}}, "partition back");
  EXPECT_TRUE(ofKind(checkModel(faces.scene()), FindingKind::Facade).empty());
}

TEST(ModelCheck, FindingsCarryTheirPlaceInTheFile) {
  Scene scene = parseSceneFaces(R"({
    "format": "walkrad-scene/1", "materials": { "white": { "reflectance": [0.5, 0.5, 0.5] } },
    "objects": [
      { "name": "room", "solids": [ { "profile": [[0, 0], [4, 0], [4, 3], [0, 3]], "from": 0, "to": 2.5,
                                      "inward": true, "material": "white" } ] },
      { "name": "crate", "solids": [ { "profile": [[1, 1], [2, 1], [2, 2], [1, 2]], "from": 0, "to": 1,
                                       "material": "white", "faces": { "top": { "open": true } } } ] } ] })",
                                 "crate.json");
  const auto found = checkModel(scene);
  ASSERT_FALSE(found.empty());
  const auto open = ofKind(found, FindingKind::OpenEdge);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_EQ(scene.objects[scene.surfaces[open[0].surface].object].name, "crate");
  EXPECT_EQ(describeLocation(scene, open[0]).rfind("objects[1].solids[0] (crate, ", 0), 0u) << describeLocation(scene, open[0]);
  // Through the open top the crate's inside (the backs of its sides) is seen from the room's
  // walls (its bottom's back is covered by the room's floor, on which it rests).
  const auto seen = ofKind(found, FindingKind::Facade);
  ASSERT_EQ(seen.size(), 4u);
  for (const Finding& f : seen) {
    EXPECT_EQ(scene.surfaces[f.surface].face.rfind("side ", 0), 0u);
    EXPECT_EQ(scene.objects[scene.surfaces[static_cast<size_t>(f.other)].object].name, "room");
  }
}

// What the findings say walkrad does is what the loader does: a duplicate and a coincident
// face stay surfaces of their own after preprocessing (neither merged nor dropped), and a face
// without area is refused by the scene loader.
TEST(ModelCheck, ActionsAreWhatTheLoaderDoes) {
  const std::string scene = R"({
    "format": "walkrad-scene/1", "materials": { "white": { "reflectance": [0.5, 0.5, 0.5] } },
    "objects": [
      { "name": "a", "movable": false, "solids": [ { "profile": [[0, 0], [1, 0], [1, 1], [0, 1]], "from": 0, "to": 1, "material": "white" } ] },
      { "name": "b", "movable": false, "solids": [ { "profile": [[0, 0], [1, 0], [1, 1], [0, 1]], "from": 0, "to": 1, "material": "white" } ] },
      { "name": "c", "movable": false, "solids": [ { "profile": [[0, 0], [0.5, 0], [0.5, 0.5], [0, 0.5]], "from": 0, "to": 1, "material": "white" } ] } ] })";
  Scene faces = parseSceneFaces(scene, "twice.json");
  const auto found = checkModel(faces);
  EXPECT_EQ(ofKind(found, FindingKind::DuplicateFace).size(), 6u);
  EXPECT_FALSE(ofKind(found, FindingKind::CoincidentFaces).empty());
  preprocessSurfaces(faces);
  EXPECT_EQ(faces.surfaces.size(), 18u) << "every face is still there";

  try {
    parseSceneFaces(R"({ "format": "walkrad-scene/1", "materials": { "w": { "reflectance": [0.5, 0.5, 0.5] } },
      "objects": [ { "name": "flat", "solids": [ { "profile": [[0, 0], [1, 0], [2, 0]], "from": 0, "to": 1, "material": "w" } ] } ] })",
                    "flat.json");
    ADD_FAILURE() << "a profile without area was loaded";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::Degenerate);
  }
}

Scene loadAssetFaces(const char* name) { return loadSceneFaces(std::string(WALKRAD_ASSETS) + "/" + name); }

TEST(ModelCheck, ShippedScenesHaveNoErrors) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "furnace.json", "box-on-floor.json"}) {
    const Scene scene = loadAssetFaces(name);
    for (const Finding& f : checkModel(scene))
      EXPECT_NE(severityOf(f.kind), Severity::Error) << name << ": " << describeLocation(scene, f) << ": " << f.message;
  }
}

TEST(ModelCheck, ShippedScenesFindingsAreTheKnownOnes) {
  // The Cornell box is open at the front (z = 0), as measured.
  const Scene cornell = loadAssetFaces("cornell.json");
  const auto c = checkModel(cornell);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].kind, FindingKind::OpenEdge);
  EXPECT_NE(c[0].message.find("4 edges"), std::string::npos);
  EXPECT_EQ(c[0].point.z, 0);
  // The office: only solids of one object stacked (desk tops on legs and so on).
  for (const Finding& f : checkModel(loadAssetFaces("office.json"))) EXPECT_EQ(f.kind, FindingKind::BackToBackFaces);
  // The kitchen: stacked solids, and the sink, a one-sided basin open at the top whose outside
  // is seen from inside its cabinet.
  const Scene kitchen = loadAssetFaces("kitchen.json");
  for (const Finding& f : checkModel(kitchen)) {
    if (f.kind != FindingKind::BackToBackFaces) {
      EXPECT_EQ(kitchen.objects[kitchen.surfaces[f.surface].object].name, "sink") << f.message;
    }
  }
}

// A dense dome (a hemisphere of triangles, open at its rim) and, when `farBox`, a box 1,000 units
// away, so that the dome is a speck of the scene.
Scene domeScene(bool farBox) {
  FaceScene faces;
  constexpr int kRings = 64, kSegments = 128;
  const auto at = [&](int i, int j) {
    const double theta = 0.5 * M_PI * i / kRings, phi = 2 * M_PI * (j % kSegments) / kSegments;
    return 10.0 * Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
  };
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) {
      const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (i > 0) faces.face("dome", {a, d, c});
      faces.face("dome", {a, c, b});
    }
  if (farBox) faces.box("far box", Vec3(1000, 0, 0), Vec3(1001, 1, 1));
  return faces.scene();
}

TEST(ModelCheck, WorkFollowsTheFacesNotHowTheyAreSpread) {
  // A uniform grid over the scene would put the whole dome into a few cells beside the far box
  // and compare its faces pair by pair (16,000 faces: 10^8 pairs). The work per face must stay
  // about what the dome alone costs.
  ModelCheckWork alone, beside;
  const Scene dome = domeScene(false), withBox = domeScene(true);
  const auto found = checkModel(withBox, {}, &beside);
  checkModel(dome, {}, &alone);
  const double faces = static_cast<double>(withBox.surfaces.size());
  ASSERT_GT(faces, 16000);
  // Each face meets its neighbours (sharing an edge or a corner, about 7 here) and what its
  // bounds reach; a query, like a ray, visits a few tens of boxes.
  EXPECT_LT(beside.pairsChecked, 10 * faces);
  EXPECT_LT(beside.pairBoundsTests, 150 * faces);
  EXPECT_LT(beside.edgeBoundsTests, 150 * faces);
  EXPECT_LT(beside.rayBoundsTests, 150 * static_cast<double>(beside.rays));
  // The box adds its own few, not a share of the dome's.
  EXPECT_LT(beside.pairsChecked, 1.1 * static_cast<double>(alone.pairsChecked) + 100);
  EXPECT_LT(beside.rayBoundsTests, 1.5 * static_cast<double>(alone.rayBoundsTests) + 1000);
  // The dome's rim is its one opening; nothing else is wrong with it.
  ASSERT_EQ(found.size(), 1u) << found[0].message;
  EXPECT_EQ(found[0].kind, FindingKind::OpenEdge);
}

TEST(ModelCheck, RandomTrianglesAreCheckedWithoutTrouble) {
  // Hostile input: triangles anywhere on a coarse lattice (so many touch, cross, coincide or
  // collapse), a few of them repeated; every finding names faces that exist.
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(0, 4);
  const auto point = [&] { return Vec3(coordinate(random), coordinate(random), coordinate(random)); };
  FaceScene faces;
  for (int i = 0; i < 600; ++i) {
    faces.face("soup " + std::to_string(i % 7), {point(), point(), point()});
    if (i % 50 == 0) faces.face("soup 0", faces.scene().surfaces.back().outer);
  }
  const auto found = checkModel(faces.scene());
  EXPECT_FALSE(ofKind(found, FindingKind::DegenerateFace).empty());
  EXPECT_FALSE(ofKind(found, FindingKind::DuplicateFace).empty());
  EXPECT_FALSE(ofKind(found, FindingKind::Interpenetration).empty());
  for (const Finding& f : found) {
    EXPECT_LT(f.surface, faces.scene().surfaces.size());
    EXPECT_LT(f.other, static_cast<int64_t>(faces.scene().surfaces.size()));
    EXPECT_TRUE(std::isfinite(f.point.x) && std::isfinite(f.point.y) && std::isfinite(f.point.z)) << f.message;
  }
}

TEST(ModelCheck, TriangleSoupOfClosedSpheresIsClean) {
  // Faces as an importer of triangles gives them: 400 spheres of 800 triangles each (320,000
  // triangles, about Sponza's), closed and consistently oriented, apart from each other.
  FaceScene faces;
  constexpr int kRings = 20, kSegments = 20;
  for (int k = 0; k < 400; ++k) {
    const Vec3 centre{3.0 * (k % 20), 0, 3.0 * (k / 20)};
    const auto at = [&](int i, int j) {
      const double theta = M_PI * i / kRings, phi = 2 * M_PI * (j % kSegments) / kSegments;
      return centre + Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
    };
    const std::string name = "ball " + std::to_string(k);
    for (int i = 0; i < kRings; ++i)
      for (int j = 0; j < kSegments; ++j) {
        const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        // The poles' quads have two points in one: only their real triangle.
        if (i > 0) faces.face(name, {a, d, c});
        if (i < kRings - 1) faces.face(name, {a, c, b});
      }
  }
  ASSERT_EQ(faces.scene().surfaces.size(), 400u * 760);
  const auto found = checkModel(faces.scene());
  EXPECT_TRUE(found.empty()) << found.size() << " findings, the first: " << found[0].message;
}

}  // namespace
}  // namespace engine

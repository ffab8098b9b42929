// Every way a scene can break spec/scene-format.md is refused with its diagnostic and the JSON
// path of the problem, and nothing is returned.
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"
#include "tests/engine/test_scenes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>

namespace engine {
namespace {

struct ErrorCase {
  const char* name;
  std::function<void(Json&)> breakIt;
  Diag diag;
  const char* place;
};

Json& room(Json& j) { return j["objects"][0]["solids"][0]; }
Json& box(Json& j) { return j["objects"][1]["solids"][0]; }
Json& ceilingHoles(Json& j) { return room(j)["faces"]["top"]["holes"]; }
const Json kNull = nullptr;

const ErrorCase kCases[] = {
    {"top level is an array", [](Json& j) { j = Json::array(); }, Diag::WrongType, "(top level)"},
    {"format missing", [](Json& j) { j.erase("format"); }, Diag::MissingField, "format"},
    {"format unknown", [](Json& j) { j["format"] = "walkrad-scene/2"; }, Diag::WrongFormat, "format"},
    {"unknown top-level key", [](Json& j) { j["material"] = Json::object(); }, Diag::UnknownKey, "material"},
    {"units unknown", [](Json& j) { j["units"] = "furlong"; }, Diag::UnknownUnits, "units"},
    {"units wrong type", [](Json& j) { j["units"] = 1; }, Diag::WrongType, "units"},
    {"patch size zero", [](Json& j) { j["settings"]["patch_size"] = 0; }, Diag::OutOfRange, "settings.patch_size"},
    {"adaptive not an object", [](Json& j) { j["settings"]["adaptive"] = true; }, Diag::WrongType, "settings.adaptive"},
    {"adaptive unknown key", [](Json& j) { j["settings"]["adaptive"] = {{"treshold", 0.2}}; }, Diag::UnknownKey,
     "settings.adaptive.treshold"},
    {"adaptive threshold zero", [](Json& j) { j["settings"]["adaptive"] = {{"threshold", 0}}; }, Diag::OutOfRange,
     "settings.adaptive.threshold"},
    {"adaptive threshold absurd", [](Json& j) { j["settings"]["adaptive"] = {{"threshold", 50}}; }, Diag::OutOfRange,
     "settings.adaptive.threshold"},
    {"adaptive minimum size negative", [](Json& j) { j["settings"]["adaptive"] = {{"min_element_size", -0.1}}; },
     Diag::OutOfRange, "settings.adaptive.min_element_size"},
    {"patch size negative", [](Json& j) { j["settings"]["patch_size"] = -1; }, Diag::OutOfRange, "settings.patch_size"},
    {"patch size absurdly small", [](Json& j) { j["settings"]["patch_size"] = 1e-6; }, Diag::PatchTooSmall, "settings.patch_size"},
    {"face patch size absurdly small", [](Json& j) { room(j)["faces"]["top"]["patch_size"] = 1e-7; },
     Diag::PatchTooSmall, "objects[0].solids[0].faces.top.patch_size"},
    {"materials missing", [](Json& j) { j.erase("materials"); }, Diag::MissingField, "materials"},
    {"materials an array", [](Json& j) { j["materials"] = Json::array(); }, Diag::WrongType, "materials"},
    {"reflectance missing", [](Json& j) { j["materials"]["white"].erase("reflectance"); }, Diag::MissingField, "materials.white.reflectance"},
    {"reflectance a string", [](Json& j) { j["materials"]["white"]["reflectance"] = "white"; }, Diag::WrongType, "materials.white.reflectance"},
    {"reflectance two numbers", [](Json& j) { j["materials"]["white"]["reflectance"] = {0.5, 0.5}; }, Diag::WrongType, "materials.white.reflectance"},
    {"reflectance above one", [](Json& j) { j["materials"]["white"]["reflectance"][0] = 1.5; }, Diag::OutOfRange, "materials.white.reflectance[0]"},
    {"reflectance null (NaN written by a tool)", [](Json& j) { j["materials"]["white"]["reflectance"][1] = kNull; }, Diag::NotFinite, "materials.white.reflectance[1]"},
    {"emission negative", [](Json& j) { j["materials"]["lamp"]["emission"][2] = -1; }, Diag::OutOfRange, "materials.lamp.emission[2]"},
    {"emission absurd", [](Json& j) { j["materials"]["lamp"]["emission"][0] = 1e30; }, Diag::OutOfRange, "materials.lamp.emission[0]"},
    {"misspelt material key", [](Json& j) { j["materials"]["white"]["reflectence"] = {1, 1, 1}; }, Diag::UnknownKey, "materials.white.reflectence"},
    {"objects missing", [](Json& j) { j.erase("objects"); }, Diag::MissingField, "objects"},
    {"objects an object", [](Json& j) { j["objects"] = Json::object(); }, Diag::WrongType, "objects"},
    {"object not an object", [](Json& j) { j["objects"][1] = 3; }, Diag::WrongType, "objects[1]"},
    {"object name missing", [](Json& j) { j["objects"][1].erase("name"); }, Diag::MissingField, "objects[1].name"},
    {"object name empty", [](Json& j) { j["objects"][1]["name"] = ""; }, Diag::OutOfRange, "objects[1].name"},
    {"duplicate object names", [](Json& j) { j["objects"][1]["name"] = "room"; }, Diag::DuplicateName, "objects[1].name"},
    {"movable not a boolean", [](Json& j) { j["objects"][1]["movable"] = "yes"; }, Diag::WrongType, "objects[1].movable"},
    {"position with two numbers", [](Json& j) { j["objects"][1]["position"] = {1, 2}; }, Diag::WrongType, "objects[1].position"},
    {"position absurd", [](Json& j) { j["objects"][1]["position"] = {0, 1e12, 0}; }, Diag::OutOfRange, "objects[1].position[1]"},
    {"rotate_y a string", [](Json& j) { j["objects"][1]["rotate_y"] = "90"; }, Diag::WrongType, "objects[1].rotate_y"},
    {"solids missing", [](Json& j) { j["objects"][1].erase("solids"); }, Diag::MissingField, "objects[1].solids"},
    {"solids empty", [](Json& j) { j["objects"][1]["solids"] = Json::array(); }, Diag::OutOfRange, "objects[1].solids"},
    {"profile missing", [](Json& j) { box(j).erase("profile"); }, Diag::MissingField, "objects[1].solids[0].profile"},
    {"profile of two points", [](Json& j) { box(j)["profile"] = {{0, 0}, {1, 0}}; }, Diag::TooFewPoints, "objects[1].solids[0].profile"},
    {"profile point of three numbers", [](Json& j) { box(j)["profile"][2] = {1, 1, 1}; }, Diag::WrongType, "objects[1].solids[0].profile[2]"},
    {"profile coordinate a string", [](Json& j) { box(j)["profile"][1][0] = "2"; }, Diag::WrongType, "objects[1].solids[0].profile[1][0]"},
    {"profile not convex", [](Json& j) { box(j)["profile"] = {{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}; }, Diag::NotConvex, "objects[1].solids[0].profile"},
    {"profile a bowtie", [](Json& j) { box(j)["profile"] = {{0, 0}, {2, 2}, {2, 0}, {0, 2}}; }, Diag::NotConvex, "objects[1].solids[0].profile"},
    {"profile a pentagram", [](Json& j) { box(j)["profile"] = {{1, 0}, {-0.809, 0.588}, {0.309, -0.951}, {0.309, 0.951}, {-0.809, -0.588}}; },
     Diag::NotConvex, "objects[1].solids[0].profile"},
    // The fuzzed profile of tests/fuzz/regressions/scene_text/bottom_face_crosses_itself, moved
    // and scaled: a triangle whose side at x = 1 runs out, back and out again.
    {"profile folding back along a side", [](Json& j) { box(j)["profile"] = {{1, 1.5}, {1, 1}, {2, 2}, {1, 2}, {1, 0.5}}; },
     Diag::NotConvex, "objects[1].solids[0].profile"},
    {"profile repeats a point", [](Json& j) { box(j)["profile"] = {{0, 0}, {1, 0}, {1, 0}, {1, 1}}; }, Diag::Degenerate, "objects[1].solids[0].profile"},
    {"profile without area", [](Json& j) { box(j)["profile"] = {{0, 0}, {1, 0}, {2, 0}}; }, Diag::Degenerate, "objects[1].solids[0].profile"},
    {"axis unknown", [](Json& j) { box(j)["axis"] = "w"; }, Diag::UnknownAxis, "objects[1].solids[0].axis"},
    {"from equals to", [](Json& j) { box(j)["to"] = 0; }, Diag::EmptySweep, "objects[1].solids[0].to"},
    {"from above to", [](Json& j) { box(j)["from"] = 2; }, Diag::EmptySweep, "objects[1].solids[0].to"},
    {"to missing", [](Json& j) { box(j).erase("to"); }, Diag::MissingField, "objects[1].solids[0].to"},
    {"material unknown", [](Json& j) { box(j)["material"] = "oak"; }, Diag::UnknownMaterial, "objects[1].solids[0].material"},
    {"material missing", [](Json& j) { box(j).erase("material"); }, Diag::MissingField, "objects[1].solids[0].material"},
    {"inward not a boolean", [](Json& j) { box(j)["inward"] = 1; }, Diag::WrongType, "objects[1].solids[0].inward"},
    {"taper kind unknown", [](Json& j) { box(j)["taper"] = {{"kind", "twist"}}; }, Diag::UnknownTaper, "objects[1].solids[0].taper.kind"},
    {"linear taper without scale", [](Json& j) { box(j)["taper"] = {{"kind", "linear"}}; }, Diag::MissingField, "objects[1].solids[0].taper.scale"},
    {"linear taper negative", [](Json& j) { box(j)["taper"] = {{"kind", "linear"}, {"scale", -1}}; }, Diag::OutOfRange, "objects[1].solids[0].taper.scale"},
    {"radial taper of no slices", [](Json& j) { box(j)["taper"] = {{"kind", "radial"}, {"slices", 0}}; }, Diag::OutOfRange, "objects[1].solids[0].taper.slices"},
    {"radial taper of half a slice", [](Json& j) { box(j)["taper"] = {{"kind", "radial"}, {"slices", 2.5}}; }, Diag::WrongType, "objects[1].solids[0].taper.slices"},
    {"face that does not exist", [](Json& j) { box(j)["faces"] = {{"side 9", {{"open", true}}}}; }, Diag::UnknownFace, "objects[1].solids[0].faces[\"side 9\"]"},
    {"top of a pyramid", [](Json& j) { box(j)["taper"] = {{"kind", "linear"}, {"scale", 0}}; box(j)["faces"] = {{"top", Json::object()}}; },
     Diag::UnknownFace, "objects[1].solids[0].faces.top"},
    {"unbanded side name on a dome", [](Json& j) { box(j)["taper"] = {{"kind", "radial"}, {"slices", 2}}; box(j)["faces"] = {{"side 0", Json::object()}}; },
     Diag::UnknownFace, "objects[1].solids[0].faces[\"side 0\"]"},
    {"face material unknown", [](Json& j) { room(j)["faces"]["top"]["material"] = "oak"; }, Diag::UnknownMaterial, "objects[0].solids[0].faces.top.material"},
    {"open not a boolean", [](Json& j) { room(j)["faces"]["top"]["open"] = "no"; }, Diag::WrongType, "objects[0].solids[0].faces.top.open"},
    {"fill material unknown", [](Json& j) { ceilingHoles(j)[0]["fill"] = "glass"; }, Diag::UnknownMaterial, "objects[0].solids[0].faces.top.holes[0].fill"},
    {"hole outside its face", [](Json& j) { ceilingHoles(j)[0]["polygon"] = {{3, 1}, {5, 1}, {5, 2}, {3, 2}}; },
     Diag::HoleOutsideFace, "objects[0].solids[0].faces.top.holes[0].polygon"},
    {"hole touching the face edge", [](Json& j) { ceilingHoles(j)[0]["polygon"] = {{0, 1}, {1, 1}, {1, 2}, {0, 2}}; },
     Diag::HoleOutsideFace, "objects[0].solids[0].faces.top.holes[0].polygon"},
    {"hole on a side face beyond its height", [](Json& j) { room(j)["faces"]["side 0"] = {{"holes", {{{"polygon", {{1, 2}, {2, 2}, {2, 3}, {1, 3}}}}}}}; },
     Diag::HoleOutsideFace, "objects[0].solids[0].faces[\"side 0\"].holes[0].polygon"},
    {"holes overlapping", [](Json& j) { ceilingHoles(j).push_back({{"polygon", {{1.5, 1.5}, {2.5, 1.5}, {2.5, 2.5}, {1.5, 2.5}}}}); },
     Diag::HolesTouch, "objects[0].solids[0].faces.top.holes[1].polygon"},
    {"holes touching at a corner", [](Json& j) { ceilingHoles(j).push_back({{"polygon", {{2, 2}, {3, 2}, {3, 2.5}, {2, 2.5}}}}); },
     Diag::HolesTouch, "objects[0].solids[0].faces.top.holes[1].polygon"},
    {"hole inside a hole", [](Json& j) { ceilingHoles(j).push_back({{"polygon", {{1.2, 1.2}, {1.8, 1.2}, {1.8, 1.8}, {1.2, 1.8}}}}); },
     Diag::HolesTouch, "objects[0].solids[0].faces.top.holes[1].polygon"},
    {"hole crossing itself", [](Json& j) { ceilingHoles(j)[0]["polygon"] = {{1, 1}, {2, 2}, {2, 1}, {1, 2}}; },
     Diag::SelfIntersecting, "objects[0].solids[0].faces.top.holes[0].polygon"},
    {"hole of two points", [](Json& j) { ceilingHoles(j)[0]["polygon"] = {{1, 1}, {2, 2}}; },
     Diag::TooFewPoints, "objects[0].solids[0].faces.top.holes[0].polygon"},
    {"camera looking at itself", [](Json& j) { j["cameras"]["default"]["look_at"] = j["cameras"]["default"]["position"]; }, Diag::BadCamera, "cameras.default"},
    {"camera up along the view", [](Json& j) { j["cameras"]["default"]["look_at"] = {0.5, 5, 0.5}; }, Diag::BadCamera, "cameras.default"},
    {"camera field of view zero", [](Json& j) { j["cameras"]["default"]["fov_y"] = 0; }, Diag::OutOfRange, "cameras.default.fov_y"},
    {"camera field of view 180", [](Json& j) { j["cameras"]["default"]["fov_y"] = 180; }, Diag::OutOfRange, "cameras.default.fov_y"},
    {"camera position missing", [](Json& j) { j["cameras"]["default"].erase("position"); }, Diag::MissingField, "cameras.default.position"},
    {"cameras an array", [](Json& j) { j["cameras"] = Json::array(); }, Diag::WrongType, "cameras"},
    {"profile with a shallow notch", [](Json& j) { box(j)["profile"] = {{0, 0}, {0.5, 1e-5}, {1, 0}, {1, 1}, {0, 1}}; },
     Diag::NotConvex, "objects[1].solids[0].profile"},
    {"profile points a hair apart", [](Json& j) { box(j)["profile"] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 1e-12}}; },
     Diag::Degenerate, "objects[1].solids[0].profile"},
    {"profile of too many points", [](Json& j) {
       Json ring = Json::array();
       for (int i = 0; i < 1025; ++i) ring.push_back({std::cos(i * 2 * std::numbers::pi / 1025), std::sin(i * 2 * std::numbers::pi / 1025)});
       box(j)["profile"] = ring; },
     Diag::OutOfRange, "objects[1].solids[0].profile"},
    {"sweep thinner than a nanometre", [](Json& j) { box(j)["to"] = 1e-12; }, Diag::Degenerate, "objects[1].solids[0].to"},
    {"linear taper to a sliver", [](Json& j) { box(j)["taper"] = {{"kind", "linear"}, {"scale", 1e-9}}; }, Diag::OutOfRange, "objects[1].solids[0].taper.scale"},
    {"sphere of one slice", [](Json& j) { box(j)["taper"] = {{"kind", "radial"}, {"slices", 1}, {"both_ends", true}}; },
     Diag::OutOfRange, "objects[1].solids[0].taper.slices"},
    {"slices on a prism", [](Json& j) { box(j)["taper"] = {{"kind", "none"}, {"slices", -5}}; }, Diag::UnknownKey, "objects[1].solids[0].taper.slices"},
    {"both_ends on a linear taper", [](Json& j) { box(j)["taper"] = {{"kind", "linear"}, {"scale", 0.5}, {"both_ends", true}}; },
     Diag::UnknownKey, "objects[1].solids[0].taper.both_ends"},
    {"face name with a quote", [](Json& j) { box(j)["faces"] = {{"a\"b", Json::object()}}; }, Diag::UnknownFace, "objects[1].solids[0].faces[\"a\\\"b\"]"},
    {"bad hole in an open face", [](Json& j) { room(j)["faces"]["side 0"] = {{"open", true}, {"holes", {{{"polygon", {{5, 5}, {6, 5}, {6, 6}}}}}}}; },
     Diag::HoleOutsideFace, "objects[0].solids[0].faces[\"side 0\"].holes[0].polygon"},
    {"hole repeating a point", [](Json& j) { ceilingHoles(j)[0]["polygon"] = {{1, 1}, {2, 1}, {2, 1}, {2, 2}}; },
     Diag::Degenerate, "objects[0].solids[0].faces.top.holes[0].polygon"},
    {"too many holes", [](Json& j) {
       Json holes = Json::array();
       for (int i = 0; i < 257; ++i) holes.push_back({{"polygon", {{0.1 + 0.01 * i, 0.1}, {0.105 + 0.01 * i, 0.1}, {0.105 + 0.01 * i, 0.2}}}});
       ceilingHoles(j) = holes; },
     Diag::OutOfRange, "objects[0].solids[0].faces.top.holes"},
};

void PrintTo(const ErrorCase& c, std::ostream* out) { *out << c.name; }

class SceneErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(SceneErrors, RefusedWithDiagnosticAndPath) {
  Json j = test::baseScene();
  GetParam().breakIt(j);
  try {
    test::parse(j);
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), GetParam().diag) << e.what();
    EXPECT_EQ(e.place(), GetParam().place) << e.what();
    EXPECT_EQ(e.file(), "test.json");
    const std::string line = e.what();
    EXPECT_EQ(line.find('\n'), std::string::npos);
    EXPECT_EQ(line.rfind("test.json: " + std::string(GetParam().place) + ": ", 0), 0u) << line;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryCase, SceneErrors, testing::ValuesIn(kCases), [](const auto& test) {
  std::string name = test.param.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

TEST(SceneErrorsText, SyntaxErrorsNameLineAndColumn) {
  try {
    parseScene("{\n  \"format\": \"walkrad-scene/1\",\n  \"units\": m\n}", "broken.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::NotJson);
    EXPECT_EQ(e.place(), ":3:12");
    EXPECT_EQ(std::string(e.what()).rfind("broken.json:3:12: not valid JSON", 0), 0u) << e.what();
  }
}

// nlohmann keeps the last of two equal keys; a scene naming one twice is refused instead.
TEST(SceneErrorsText, KeysGivenTwiceAreRefusedWithTheirPath) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"format": "walkrad-scene/1", "materials": {"white": {"reflectance": [1, 1, 1]}, "white": {"reflectance": [0, 0, 0]}}, "objects": []})",
       "materials.white"},
      {R"({"format": "walkrad-scene/1", "materials": {}, "objects": [{"name": "a", "solids": []}, {"name": "b", "name": "c", "solids": []}]})",
       "objects[1].name"},
      {R"({"format": "walkrad-scene/1", "format": "walkrad-scene/1"})", "format"},
      {R"({"format": "walkrad-scene/1", "objects": [[0, {"x": 1}], [1, {"y": 2, "y": 3}]]})", "objects[1][1].y"},
  };
  for (const auto& [text, place] : cases) {
    try {
      parseScene(text, "twice.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.diag(), Diag::DuplicateKey) << e.what();
      EXPECT_EQ(e.place(), place) << e.what();
    }
  }
}

// A number too large for a double is placed by line and column, as syntax errors are; numbers
// inside strings before it do not count.
TEST(SceneErrorsText, NumbersBeyondDoubleAreRefusedWhereTheyAre) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"format": "walkrad-scene/1", "settings": {"patch_size": 1e999}})",
       "big.json:1:58: not a finite number: 1e999 is too large for a double"},
      {"{\"format\": \"walkrad-scene/1\",\n \"a\\\" 1e999\": [1e300,\n   -12e308]}",
       "big.json:3:4: not a finite number: -12e308 is too large for a double"},
      {"[" + std::string(400, '9') + "]", "big.json:1:2: not a finite number: " + std::string(400, '9') + " is too large for a double"}};
  for (const auto& [text, message] : cases) {
    try {
      parseScene(text, "big.json");
      ADD_FAILURE() << text;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.diag(), Diag::NotFinite) << e.what();
      EXPECT_EQ(e.what(), message);
    }
  }
}

TEST(SceneErrorsText, EmptyTextIsNotJson) {
  EXPECT_THROW(parseScene("", "empty.json"), SceneError);
}

// Hostile input: every truncation of a valid scene is refused cleanly, never half-loaded.
TEST(SceneErrorsText, EveryTruncationIsRefused) {
  const std::string text = test::baseScene().dump();
  for (size_t length = 0; length < text.size(); ++length) {
    try {
      parseScene(std::string_view(text).substr(0, length), "cut.json");
      ADD_FAILURE() << "a scene cut at " << length << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.diag(), Diag::NotJson) << length;
    }
  }
}

TEST(SceneErrorsText, MissingFileAndDirectoryAreUnreadable) {
  const std::pair<std::string, Diag> cases[] = {{"/nonexistent/scene.json", Diag::FileUnreadable},
                                                {WALKRAD_TEST_OUTPUT, Diag::NotRegularFile}};
  for (const auto& [path, diag] : cases) {
    try {
      loadScene(path);
      FAIL() << path;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.diag(), diag);
      EXPECT_EQ(std::string(e.what()).rfind(path + ": " + describe(diag), 0), 0u) << e.what();
    }
  }
}

// A scene file asking for more faces than walkrad takes is refused at the solid that passes the
// limit, before any is swept: a dome of 1,024 points and 256 slices is 262,146 faces in 20 KB, so
// 16 of them (320 KB) would be 4.2 million.
TEST(SceneErrorsText, TooManyFacesAreRefusedBeforeTheyAreMade) {
  Json dome = {{"axis", "y"}, {"from", 0}, {"to", 1}, {"material", "white"}, {"taper", {{"kind", "radial"}, {"slices", 256}}}};
  for (int i = 0; i < 1024; ++i) {
    const double x = (i - 512) / 64.0;
    dome["profile"].push_back({x, x * x});
  }
  Json j = test::baseScene();
  for (int o = 0; o < 16; ++o) {
    const Json object = {{"name", "dome " + std::to_string(o)}, {"position", {20.0 * o, 0, 0}}, {"solids", Json::array({dome})}};
    j["objects"].push_back(object);
  }
  const std::string text = j.dump();
  const size_t faces = 262146;
  // The room and the box make 13 faces, the filled hole in the ceiling one of them.
  const size_t limit = (kMaxFaces - 13) / faces;  // domes within the limit
  ASSERT_LT(limit, 16u);
  try {
    parseSceneFaces(text, "domes.json");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::TooManyFaces) << e.what();
    EXPECT_EQ(e.place(), "objects[" + std::to_string(2 + limit) + "].solids[0]") << e.what();
  }
}

// A patch size within the scene's limit (100,000 patches along its extent) whose mesh would pass
// the mesher's work limit is refused when the scene is meshed, naming the surface, at once.
TEST(SceneErrorsText, AMeshPastTheMeshersLimitIsRefusedAtItsSurface) {
  Json j = test::baseScene();
  room(j)["faces"]["top"]["patch_size"] = 1e-4;  // 4 x 3 at 1e-4: over a billion elements
  const Scene scene = parseScene(j.dump(), "fine.json");
  try {
    meshScene(scene);
    ADD_FAILURE() << "meshed";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::MeshTooLarge) << e.what();
    EXPECT_EQ(e.place(), "objects[0].solids[0].faces.top") << e.what();
  }
}

// A test per way of breaking a scene: every diagnostic of the table is produced above.
TEST(SceneErrorsText, EveryDiagnosticHasACase) {
  std::set<Diag> covered{Diag::NotJson, Diag::FileUnreadable, Diag::DuplicateKey, Diag::TooManyFaces};  // the tests above
  // Files that are no regular file or too large: input_file_test.cpp.
  covered.insert({Diag::NotRegularFile, Diag::FileTooLarge});
  // glTF models' own: gltf_errors_test.cpp has a case for each.
  covered.insert({Diag::NotGltf, Diag::BadGltfReference, Diag::BadAccessor, Diag::NodeLoop, Diag::NoTriangles,
                  Diag::UnknownNode, Diag::GltfOnly, Diag::UriAbsolute, Diag::UriOutsideFolder, Diag::WrongByteLength});
  // The mesher's refusals: the test above, and cli.mesh_hair_apart_far (a polygon case).
  covered.insert({Diag::MeshTooLarge, Diag::MeshTooFine});
  for (const ErrorCase& c : kCases) covered.insert(c.diag);
#define WALKRAD_EXPECT_COVERED(id, text) EXPECT_TRUE(covered.count(Diag::id)) << #id " has no test";
  WALKRAD_SCENE_DIAGNOSTICS(WALKRAD_EXPECT_COVERED)
#undef WALKRAD_EXPECT_COVERED
}

}  // namespace
}  // namespace engine

// Broken glTF models and sidecars are refused with one located diagnostic, never a crash: bad
// references, accessors past their buffers, loops, and every truncation of a small file.
#include "engine/io/gltf_loader.h"

#include "engine/diagnostics.h"
#include "engine/io/gltf_sidecar.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "tests/engine/gltf_writer.h"
#include "tests/engine/hostile_input.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

namespace engine {
namespace {

using test::GltfModel;

// Two quads (four triangles) under a parent node, one material, a camera.
GltfModel smallModel() {
  GltfModel m;
  test::GltfPrimitive quad;
  quad.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.indexType = test::kUnsignedShort;
  quad.material = 0;
  test::GltfNode parent{"parent", {quad}, {1}, {0, 1, 0}, {}, {}, {}, -1};
  test::GltfNode child{"child", {quad}, {}, {2, 0, 0}, {}, {}, {}, -1};
  test::GltfNode camera{"eye", {}, {}, {0.5, 1, 3}, {}, {}, {}, 0};
  m.nodes = {parent, child, camera};
  m.roots = {0, 2};
  m.materials = {{"white", {0.5, 0.5, 0.5, 1}, Vec3{0}, 0, ""}};
  m.cameras = {{"eye", 0.8}};
  return m;
}

// The .gltf text of smallModel() with one change made to its JSON.
std::string edited(const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json j = nlohmann::json::parse(test::gltfText(smallModel()));
  edit(j);
  return j.dump();
}

struct ErrorCase {
  const char* name;
  std::function<void(nlohmann::json&)> breakIt;
  Diag diag;
  const char* place;
};

const ErrorCase kCases[] = {
    {"no asset", [](nlohmann::json& j) { j.erase("asset"); }, Diag::NotGltf, ""},
    {"material index", [](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["material"] = 7; }, Diag::BadGltfReference,
     "meshes[0].primitives[0].material"},
    {"mesh index", [](nlohmann::json& j) { j["nodes"][1]["mesh"] = 9; }, Diag::BadGltfReference, "nodes[1].mesh"},
    {"child index", [](nlohmann::json& j) { j["nodes"][0]["children"] = {5}; }, Diag::BadGltfReference, "nodes[0].children"},
    {"position accessor index", [](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 40; },
     Diag::BadGltfReference, "meshes[0].primitives[0].attributes.POSITION"},
    {"node loop", [](nlohmann::json& j) { j["nodes"][1]["children"] = {0}; }, Diag::NodeLoop, "nodes[0]"},
    {"node shared by two parents", [](nlohmann::json& j) { j["scenes"][0]["nodes"] = {0, 1}; }, Diag::NodeLoop, "nodes[1]"},
    {"accessor past its view", [](nlohmann::json& j) { j["accessors"][0]["count"] = 400; }, Diag::BadAccessor, "accessors[0]"},
    {"accessor offset past its view", [](nlohmann::json& j) { j["accessors"][1]["byteOffset"] = 1000; }, Diag::BadAccessor, "accessors[1]"},
    {"view past its buffer", [](nlohmann::json& j) { j["bufferViews"][0]["byteLength"] = 100000; }, Diag::BadAccessor, "accessors[0]"},
    {"index beyond the positions", [](nlohmann::json& j) { j["accessors"][0]["count"] = 2; }, Diag::BadAccessor, "accessors[1]"},
    {"accessor of a billion zeros", [](nlohmann::json& j) { j["accessors"][0].erase("bufferView"); j["accessors"][0]["count"] = 1000000000; },
     Diag::BadAccessor, "accessors[0]"},
    {"float indices", [](nlohmann::json& j) { j["accessors"][1]["componentType"] = 5126; j["accessors"][1]["count"] = 3; },
     Diag::BadAccessor, "accessors[1]"},
    {"positions as VEC2", [](nlohmann::json& j) { j["accessors"][0]["type"] = "VEC2"; }, Diag::BadAccessor, "accessors[0]"},
    {"only lines", [](nlohmann::json& j) { for (auto& m : j["meshes"]) m["primitives"][0]["mode"] = 1; }, Diag::NoTriangles, ""},
    {"emission negative", [](nlohmann::json& j) { j["materials"][0]["emissiveFactor"] = {-1, 0, 0}; }, Diag::OutOfRange,
     "materials[0].emissiveFactor"},
    {"matrix of 15 numbers", [](nlohmann::json& j) { j["nodes"][1]["matrix"] = std::vector<double>(15, 1.0); }, Diag::WrongType, "nodes[1].matrix"},
    {"camera looking nowhere", [](nlohmann::json& j) { j["nodes"][2]["scale"] = {0, 0, 0}; }, Diag::BadCamera, "nodes[2].camera"},
};

TEST(GltfErrors, EachBreakageHasItsDiagnosticAndPlace) {
  for (const ErrorCase& c : kCases) {
    std::string what;
    const Diag diag = test::refusalOf([&] { parseGltf(edited(c.breakIt), "broken.gltf"); }, &what);
    EXPECT_EQ(diag, c.diag) << c.name << ": " << what;
    EXPECT_EQ(what.rfind(std::string("broken.gltf") + (*c.place ? ": " : ""), 0), 0u) << c.name << ": " << what;
    if (*c.place) {
      EXPECT_NE(what.find(c.place), std::string::npos) << c.name << ": " << what;
    }
    EXPECT_EQ(what.find('\n'), std::string::npos) << c.name;
  }
}

// Hostile input: every truncation of a small .gltf and .glb is refused cleanly.
TEST(GltfErrors, EveryTruncationIsRefused) {
  const std::string text = test::gltfText(smallModel());
  const std::string glb = test::glbBytes(smallModel());
  ASSERT_EQ(parseGltf(text, "whole.gltf").surfaces.size(), 2u);
  ASSERT_EQ(parseGltf(glb, "whole.glb").surfaces.size(), 2u);
  for (const std::string* bytes : {&text, &glb})
    for (size_t length = 0; length < bytes->size(); ++length) {
      try {
        parseGltf(std::string_view(*bytes).substr(0, length), "cut.glb");
        ADD_FAILURE() << "a model cut at " << length << " of " << bytes->size() << " was accepted";
      } catch (const SceneError& e) {
        EXPECT_TRUE(e.diag() == Diag::NotGltf || e.diag() == Diag::BadAccessor) << length << ": " << e.what();
      }
    }
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = std::string(WALKRAD_TEST_OUTPUT) + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(GltfErrors, ATruncatedExternalBufferIsRefused) {
  // The .glb's binary chunk moved into a .bin beside a .gltf, then cut short.
  nlohmann::json j = nlohmann::json::parse(test::gltfText(smallModel()));
  const std::string glb = test::glbBytes(smallModel());
  const size_t binLength = j["buffers"][0]["byteLength"];
  writeFile("cut-buffer.bin", glb.substr(glb.size() - binLength, binLength / 2));
  j["buffers"][0]["uri"] = "cut-buffer.bin";
  const std::string path = writeFile("cut-buffer.gltf", j.dump());
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { loadGltf(path); }, &what), Diag::WrongByteLength);
  EXPECT_EQ(what.rfind(path + ": buffers[0].uri: ", 0), 0u) << what;
}

// Hostile models the loader survives quickly, in work linear in the file: 40,000 materials of
// one name (named apart in one pass each), a chain of 20,000 nested nodes (walked without
// recursion, its transforms composed all the way down).
TEST(GltfErrors, FortyThousandMaterialsOfOneNameLoad) {
  GltfModel m = smallModel();
  m.materials.assign(40000, {"paint", {0.5, 0.5, 0.5, 1}, Vec3{0}, 0, ""});
  m.materials.push_back({"paint 2", {0.5, 0.5, 0.5, 1}, Vec3{0}, 0, ""});
  const Scene scene = parseGltf(test::gltfText(m), "paint.gltf");
  ASSERT_EQ(scene.materials.size(), 40001u);
  EXPECT_EQ(scene.materials[0].name, "paint");
  EXPECT_EQ(scene.materials[1].name, "paint 2");
  EXPECT_EQ(scene.materials[39999].name, "paint 40000");
  EXPECT_EQ(scene.materials[40000].name, "paint 2 2");
}

TEST(GltfErrors, AChainOfTwentyThousandNodesLoads) {
  constexpr int kDepth = 20000;
  GltfModel m = smallModel();
  m.nodes.resize(kDepth);
  for (int i = 0; i < kDepth; ++i) {
    test::GltfNode& node = m.nodes[static_cast<size_t>(i)];
    node = {"link " + std::to_string(i), {}, {}, {0.001, 0, 0}, {}, {}, {}, -1};
    if (i + 1 < kDepth) node.children = {i + 1};
  }
  m.nodes.back().primitives = smallModel().nodes[0].primitives;
  m.roots = {0};
  m.cameras.clear();
  const Scene scene = parseGltf(test::gltfText(m), "chain.gltf");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].name, "link 0");
  EXPECT_NEAR(scene.boundsMin.x, kDepth * 0.001, 1e-6);
  EXPECT_NEAR(scene.boundsMax.x, kDepth * 0.001 + 1, 1e-6);
  m.nodes.back().children = {kDepth / 2};  // and the chain's end loops back to its middle
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { parseGltf(test::gltfText(m), "loop.gltf"); }, &what), Diag::NodeLoop);
  EXPECT_EQ(what, "loop.gltf: nodes[" + std::to_string(kDepth / 2) + "]: " + describe(Diag::NodeLoop));
}

TEST(GltfErrors, TooManyTrianglesAreRefusedBeforeTheyAreMade) {
  // A strip of one byte an index makes a triangle a byte: 4 MB of them pass the limit.
  test::GltfPrimitive strip;
  strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  strip.indices.resize(kMaxFaces + 3);
  for (size_t i = 0; i < strip.indices.size(); ++i) strip.indices[i] = static_cast<uint32_t>(i % 3);
  strip.indexType = test::kUnsignedByte;
  strip.mode = test::kTriangleStrip;
  GltfModel m = test::floorModel();
  m.nodes[0].primitives.push_back(strip);
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { parseGltf(test::glbBytes(m), "strip.glb"); }, &what), Diag::TooManyFaces);
  EXPECT_EQ(what.rfind("strip.glb: meshes[0].primitives[1]: ", 0), 0u) << what;
}

TEST(GltfErrors, SidecarNamesAreChecked) {
  const std::string model = writeFile("sidecar-names.gltf", test::gltfText(smallModel()));
  std::string what;
  writeFile("sidecar-names.walkrad.json", R"({"objects": {"sofa": {"movable": false}}})");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model); }, &what), Diag::UnknownNode);
  EXPECT_NE(what.find("sidecar-names.walkrad.json: objects.sofa"), std::string::npos) << what;
  writeFile("sidecar-names.walkrad.json", R"({"materials": {"oak": {"omit": true}}})");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model); }, &what), Diag::UnknownMaterial);
  EXPECT_NE(what.find("sidecar-names.walkrad.json: materials.oak"), std::string::npos) << what;
  writeFile("sidecar-names.walkrad.json", R"({"patch_sise": 1})");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model); }, &what), Diag::UnknownKey);
  writeFile("sidecar-names.walkrad.json", R"({"units": "furlong"})");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model); }, &what), Diag::UnknownUnits);
  std::filesystem::remove(std::string(WALKRAD_TEST_OUTPUT) + "/sidecar-names.walkrad.json");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model, {"furlong", ""}); }, &what), Diag::UnknownUnits);
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model, {"", "/nonexistent/x.walkrad.json"}); }, &what), Diag::FileUnreadable);
}

TEST(GltfErrors, ASidecarNumberBeyondDoubleIsPlaced) {
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { parseGltfSidecar("{\n  \"patch_size\": 1e999}", "s.walkrad.json"); }, &what), Diag::NotFinite);
  EXPECT_EQ(what, "s.walkrad.json:2:17: not a finite number: 1e999 is too large for a double");
}

// A sidecar's emission scale that takes a model's light out of range is the sidecar's fault.
TEST(GltfErrors, AnEmissionScaleTooLargeIsTheSidecars) {
  GltfModel m = smallModel();
  m.materials[0].emissive = Vec3{2, 2, 2};
  const std::string model = writeFile("sidecar-scale.gltf", test::gltfText(m));
  writeFile("sidecar-scale.walkrad.json", R"({"emission_scale": 1000000})");
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model); }, &what), Diag::OutOfRange);
  EXPECT_NE(what.find("sidecar-scale.walkrad.json: emission_scale"), std::string::npos) << what;
  writeFile("sidecar-scale.walkrad.json", R"({"emission_scale": 1000})");
  EXPECT_DOUBLE_EQ(loadGltf(model).materials[0].emission.x, 2000);
}

TEST(GltfErrors, ModelOptionsAreRefusedForSceneFiles) {
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { loadScene(std::string(WALKRAD_ASSETS) + "/cornell.json", {"m", ""}); }, &what), Diag::GltfOnly);
  EXPECT_NE(what.find("--units"), std::string::npos) << what;
}

// Every glTF diagnostic of the table is produced above.
TEST(GltfErrors, EveryGltfDiagnosticHasACase) {
  std::set<Diag> covered{Diag::UnknownNode, Diag::GltfOnly, Diag::WrongByteLength, Diag::TooManyFaces};  // the tests above
  for (const ErrorCase& c : kCases) covered.insert(c.diag);
  // The files a model names: gltf_files_test.cpp.
  covered.insert({Diag::UriAbsolute, Diag::UriOutsideFolder});
  for (Diag d : {Diag::NotGltf, Diag::BadGltfReference, Diag::BadAccessor, Diag::NodeLoop, Diag::NoTriangles, Diag::UnknownNode,
                 Diag::GltfOnly, Diag::UriAbsolute, Diag::UriOutsideFolder, Diag::WrongByteLength, Diag::TooManyFaces})
    EXPECT_TRUE(covered.count(d)) << describe(d) << " has no test";
}

}  // namespace
}  // namespace engine

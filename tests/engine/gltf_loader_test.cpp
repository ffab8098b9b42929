// glTF import: component types, primitive modes, the node tree and its transforms, materials,
// cameras and the sidecar, on models written by the test writer.
#include "engine/io/gltf_loader.h"

#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"

#include "tests/engine/gltf_writer.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <glm/ext/vector_uint3_sized.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace engine {
namespace {

using test::GltfModel;
using test::GltfNode;
using test::GltfPrimitive;

// The unit square on the floor, facing up, as two indexed triangles.
GltfPrimitive floorSquare(double size = 1) {
  GltfPrimitive p;
  p.positions = {{0, 0, 0}, {0, 0, size}, {size, 0, size}, {size, 0, 0}};
  p.indices = {0, 1, 2, 0, 2, 3};
  return p;
}

GltfModel oneNode(GltfPrimitive p, std::string name = "thing") {
  GltfModel m;
  GltfNode node;
  node.name = std::move(name);
  node.primitives = {std::move(p)};
  m.nodes = {node};
  m.roots = {0};
  return m;
}

void expectUnitFloor(const Scene& scene, const std::string& what) {
  ASSERT_EQ(scene.surfaces.size(), 1u) << what;
  EXPECT_NEAR(scene.surfaces[0].area, 1, 1e-6) << what;
  EXPECT_EQ(scene.surfaces[0].normal, Vec3(0, 1, 0)) << what;
  EXPECT_EQ(scene.boundsMax, Vec3(1, 0, 1)) << what;
}

TEST(GltfLoader, EveryIndexAndPositionComponentTypeReads) {
  for (int indexType : {test::kUnsignedByte, test::kUnsignedShort, test::kUnsignedInt, 0}) {
    GltfPrimitive p = floorSquare();
    if (indexType == 0) {  // no indices: the corners in triangle order
      p.positions = {p.positions[0], p.positions[1], p.positions[2], p.positions[0], p.positions[2], p.positions[3]};
      p.indices.clear();
    }
    p.indexType = indexType;
    expectUnitFloor(parseGltf(test::gltfText(oneNode(p)), "t.gltf"), "index type " + std::to_string(indexType));
  }
  for (int positionType : {test::kByte, test::kUnsignedByte, test::kShort, test::kUnsignedShort, test::kFloat})
    for (bool normalized : {false, true}) {
      GltfPrimitive p = floorSquare();
      p.positionType = positionType;
      p.normalized = normalized && positionType != test::kFloat;
      expectUnitFloor(parseGltf(test::gltfText(oneNode(p)), "t.gltf"),
                      "position type " + std::to_string(positionType) + (p.normalized ? " normalised" : ""));
    }
}

TEST(GltfLoader, StripsAndFansAreTriangles) {
  GltfPrimitive strip = floorSquare();
  strip.mode = test::kTriangleStrip;
  strip.indices = {1, 2, 0, 3};  // (1, 2, 0) then (2, 0, 3) turned: (0, 2, 3)
  expectUnitFloor(parseGltf(test::gltfText(oneNode(strip)), "t.gltf"), "strip");
  GltfPrimitive fan = floorSquare();
  fan.mode = test::kTriangleFan;
  fan.indices = {0, 1, 2, 3};
  expectUnitFloor(parseGltf(test::gltfText(oneNode(fan)), "t.gltf"), "fan");
  // Lines are no surfaces: beside a square they are left out.
  GltfModel m = oneNode(floorSquare());
  GltfPrimitive lines = floorSquare();
  lines.mode = test::kLines;
  m.nodes[0].primitives.push_back(lines);
  expectUnitFloor(parseGltf(test::gltfText(m), "t.gltf"), "lines beside");
}

TEST(GltfLoader, GltfAndGlbGiveTheSameScene) {
  const GltfModel m = oneNode(floorSquare());
  const Scene a = parseGltf(test::gltfText(m), "t.gltf"), b = parseGltf(test::glbBytes(m), "t.glb");
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  EXPECT_EQ(a.surfaces[0].outer, b.surfaces[0].outer);
}

// Each top-level node is one object with its whole subtree; transforms compose parent first,
// translation * rotation * scale; the object stands at its node's translation; a mirroring scale
// keeps fronts in front.
TEST(GltfLoader, NodeTreesBecomeObjectsWithTheirTransforms) {
  GltfModel m;
  GltfNode parent, child, mirrored, second;
  parent.name = "table";
  parent.translation = {10, 0, 0};
  parent.children = {1};
  parent.primitives = {floorSquare()};
  child.name = "top";
  child.translation = {0, 2, 0};
  child.rotation = {0.7071067811865476, 0, 0, 0.7071067811865476};  // +90 degrees about x: +y to +z
  child.scale = {2, 2, 2};
  child.primitives = {floorSquare()};
  mirrored.name = "mirrored";
  mirrored.scale = {-1, 1, 1};
  mirrored.primitives = {floorSquare()};
  second.primitives = {floorSquare()};  // unnamed
  m.nodes = {parent, child, mirrored, second};
  m.roots = {0, 2, 3};
  const Scene scene = parseGltf(test::gltfText(m), "t.gltf");
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.objects[0].name, "table");
  EXPECT_EQ(scene.objects[0].position, Vec3(10, 0, 0));
  EXPECT_TRUE(scene.objects[0].movable);
  EXPECT_EQ(scene.objects[1].name, "mirrored");
  EXPECT_EQ(scene.objects[2].name, "node[3]");
  ASSERT_TRUE(scene.imported);
  EXPECT_EQ(scene.imported->nodes, 3u);
  EXPECT_EQ(scene.imported->triangles, 8u);
  int seen = 0;
  for (const Surface& s : scene.surfaces) {
    if (s.object != 0 || glm::dot(s.normal, Vec3(0, 0, 1)) < 0.999) continue;
    // The child's square: scaled to 2 x 2, turned up to face +z, at y = 2, z = 0, under x = 10.
    ++seen;
    EXPECT_NEAR(s.area, 4, 1e-9);
    for (const Vec3& p : s.outer) {
      EXPECT_NEAR(p.z, 0, 1e-9);
      EXPECT_TRUE(std::abs(p.x - 10) < 1e-9 || std::abs(p.x - 12) < 1e-9) << p.x;
      EXPECT_TRUE(std::abs(p.y - 2) < 1e-9 || std::abs(p.y + 0) < 1e-9) << p.y;
    }
    EXPECT_EQ(s.jsonPath, "nodes[0]");
  }
  EXPECT_EQ(seen, 1);
  for (const Surface& s : scene.surfaces)
    if (s.object == 1) {
      EXPECT_GT(s.normal.y, 0.999) << "a mirroring scale turned the square's back up";
    }
}

TEST(GltfLoader, MaterialsGiveReflectanceAndEmittedRadiance) {
  GltfModel m = oneNode(floorSquare());
  GltfPrimitive lamp = floorSquare(0.5), plain = floorSquare(), bright = floorSquare();
  for (Vec3& v : lamp.positions) v.y = 1;
  for (Vec3& v : plain.positions) v.y = 2;
  for (Vec3& v : bright.positions) v.y = 3;
  lamp.material = 0;
  bright.material = 1;
  m.nodes[0].primitives = {lamp, plain, bright};
  m.materials = {{"lamp", {0.5, 0.4, 0.3, 1}, {1, 0.5, 0.25}, 8, ""}, {"bright", {1, 1, 1, 1}, Vec3{0}, 0, ""}};
  const Scene scene = parseGltf(test::gltfText(m), "t.gltf");
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[0].name, "lamp");
  EXPECT_EQ(scene.materials[0].reflectance, Vec3(0.5, 0.4, 0.3));
  EXPECT_EQ(scene.materials[0].emission, Vec3(8, 4, 2));  // factor x KHR_materials_emissive_strength
  EXPECT_EQ(scene.materials[1].reflectance, Vec3(0.95));  // albedo 1 clamped
  EXPECT_EQ(scene.materials[2].name, "default");          // for the primitive without one
  EXPECT_EQ(scene.materials[2].reflectance, Vec3(0.95));
  EXPECT_EQ(scene.surfaces.size(), 3u);
}

TEST(GltfLoader, CamerasLookDownTheirNodesMinusZ) {
  GltfModel m = oneNode(floorSquare());
  GltfNode eye;
  eye.name = "eye node";
  eye.translation = {0.5, 1.6, 3};
  eye.rotation = {0, 0.3826834323650898, 0, 0.9238795325112867};  // 45 degrees about +y
  eye.camera = 0;
  m.nodes.push_back(eye);
  m.roots.push_back(1);
  m.cameras = {{"front", 0.5}};
  const Scene scene = parseGltf(test::gltfText(m), "t.gltf");
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& c = scene.cameras[0];
  EXPECT_EQ(c.name, "front");
  EXPECT_EQ(c.position, Vec3(0.5, 1.6, 3));
  const Vec3 view = glm::normalize(c.lookAt - c.position);
  EXPECT_NEAR(view.x, -std::sqrt(0.5), 1e-9);  // -z turned 45 degrees toward -x
  EXPECT_NEAR(view.z, -std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(c.up.y, 1, 1e-9);
  EXPECT_NEAR(c.fovYDeg, glm::degrees(0.5), 1e-9);
  EXPECT_EQ(scene.objects.size(), 1u);  // the camera node holds no triangles: no object
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = std::string(WALKRAD_TEST_OUTPUT) + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// An uncompressed 24-bit BMP (a format tinygltf's image loader reads) of one row of pixels.
std::string bmpRow(const std::vector<glm::u8vec3>& pixels) {
  const auto width = static_cast<uint32_t>(pixels.size());
  const uint32_t row = (3 * width + 3) / 4 * 4;
  std::string out;
  auto put = [&](uint32_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 255);
  };
  out += "BM";
  put(54 + row, 4), put(0, 4), put(54, 4);                      // file header
  put(40, 4), put(width, 4), put(1, 4), put(1, 2), put(24, 2);  // info header: one row, 24 bits
  put(0, 4), put(row, 4), put(2835, 4), put(2835, 4), put(0, 4), put(0, 4);
  for (const glm::u8vec3& p : pixels) out += static_cast<char>(p.b), out += static_cast<char>(p.g), out += static_cast<char>(p.r);
  out.append(row - 3 * width, '\0');
  return out;
}

// A base-colour texture is averaged to one reflectance: the mean of its sRGB-decoded pixels
// times baseColorFactor.
TEST(GltfLoader, ABaseColourTextureIsAveraged) {
  writeFile("texture-two-pixels.bmp", bmpRow({{255, 188, 0}, {0, 188, 255}}));
  GltfModel m = oneNode(floorSquare());
  m.nodes[0].primitives[0].material = 0;
  m.materials = {{"painted", {0.8, 0.8, 0.8, 1}, Vec3{0}, 0, "texture-two-pixels.bmp"}};
  const Scene scene = loadGltf(writeFile("texture.gltf", test::gltfText(m)));
  const double green = std::pow((188 / 255.0 + 0.055) / 1.055, 2.4);  // sRGB 188, about 0.50
  EXPECT_NEAR(scene.materials[0].reflectance.r, 0.8 * 0.5, 1e-9);
  EXPECT_NEAR(scene.materials[0].reflectance.g, 0.8 * green, 1e-9);
  EXPECT_NEAR(scene.materials[0].reflectance.b, 0.8 * 0.5, 1e-9);
}

// The sidecar beside the model: units, patch size, emission, omitted materials, movability, sky.
TEST(GltfLoader, TheSidecarCompletesTheModel) {
  GltfModel m = oneNode(floorSquare(4), "floor");
  GltfPrimitive glass = floorSquare();
  for (Vec3& v : glass.positions) v.y = 1;
  glass.material = 1;
  GltfPrimitive shade = floorSquare();
  for (Vec3& v : shade.positions) v.y = 2;
  shade.material = 0;
  m.nodes[0].primitives[0].material = 0;
  m.nodes[0].primitives.push_back(glass);
  m.nodes[0].primitives.push_back(shade);
  m.materials = {{"paint", {0.5, 0.5, 0.5, 1}, Vec3{0}, 0, ""}, {"glass", {0.9, 0.9, 0.9, 1}, Vec3{0}, 0, ""}};
  const std::string path = writeFile("sidecar-room.gltf", test::gltfText(m));
  const Scene plain = loadGltf(path);
  EXPECT_EQ(plain.units, "m");
  EXPECT_DOUBLE_EQ(plain.patchSize, 0.5);  // an eighth of the 4 m extent
  writeFile("sidecar-room.walkrad.json", R"({"units": "ft", "patch_size": 0.25, "movable": false,
      "materials": {"paint": {"emission": [2, 2, 2], "two_sided": true}, "glass": {"omit": true}},
      "objects": {"floor": {"movable": true}}, "sky": {"emission": [1, 1, 1]}})");
  const Scene scene = loadGltf(path);
  EXPECT_EQ(scene.units, "ft");
  EXPECT_DOUBLE_EQ(scene.metersPerUnit, 0.3048);
  EXPECT_DOUBLE_EQ(scene.patchSize, 0.25);
  for (const Surface& s : scene.surfaces) EXPECT_EQ(s.patchSize, 0.25);
  EXPECT_EQ(scene.materials[0].emission, Vec3(2));
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_TRUE(scene.objects[0].movable);  // its own entry wins over the default
  EXPECT_EQ(scene.objects[1].name, "sky");
  EXPECT_FALSE(scene.objects[1].movable);
  // The floor and the shade, both facing both ways, and the sky: the glass is left out.
  ASSERT_EQ(scene.surfaces.size(), 5u);
  for (size_t i : {0, 1, 2, 3}) {
    const Surface& s = scene.surfaces[i];
    const bool twin = std::any_of(scene.surfaces.begin(), scene.surfaces.end(), [&](const Surface& t) {
      return t.normal == -s.normal && t.planeOffset() == -s.planeOffset() && t.area == s.area;
    });
    EXPECT_TRUE(twin) << i;
  }
  const Surface& sky = scene.surfaces.back();
  EXPECT_EQ(sky.normal, Vec3(0, -1, 0));
  EXPECT_GT(sky.outer[0].y, 2);
  EXPECT_NEAR(sky.area, 16, 1e-9);
  EXPECT_EQ(scene.materials[sky.material].emission, Vec3(1));
  // The command line's units win over the sidecar's.
  EXPECT_EQ(loadGltf(path, {"cm", ""}).units, "cm");
  std::remove((std::string(WALKRAD_TEST_OUTPUT) + "/sidecar-room.walkrad.json").c_str());
}

}  // namespace
}  // namespace engine

namespace engine {
namespace {

// A glTF object is dragged like a scene file's: its surfaces move rigidly with its pose (turns
// about its node's origin) and come back exactly.
TEST(GltfLoader, ObjectsMoveThroughTheEditor) {
  GltfModel m = oneNode(floorSquare(4), "floor");
  GltfNode box;
  box.name = "box";
  box.translation = {1, 0, 1};
  GltfPrimitive top = floorSquare();
  for (Vec3& v : top.positions) v.y = 0.5;
  box.primitives = {top};
  m.nodes.push_back(box);
  m.roots.push_back(1);
  Scene scene = parseGltf(test::gltfText(m), "t.gltf");
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[1].position, Vec3(1, 0, 1));
  MeshedScene meshed = meshScene(scene);
  SceneEditor editor(std::move(scene), std::move(meshed));
  ASSERT_EQ(editor.surfacesOf(1).size(), 1u);
  const uint32_t s = editor.surfacesOf(1).front();
  const Ring3 home = editor.scene().surfaces[s].outer;
  EXPECT_TRUE(editor.setPose(1, {Vec3(2, 0, 1), 90}));
  for (size_t i = 0; i < home.size(); ++i) {
    // Turned 90 degrees about (1, 0, 1) (+x toward -z), then moved 1 along x.
    const Vec3 d = home[i] - Vec3(1, 0, 1);
    const Vec3 expected = Vec3(2, 0, 1) + Vec3(d.z, d.y, -d.x);
    EXPECT_NEAR(glm::length(editor.scene().surfaces[s].outer[i] - expected), 0, 1e-12);
  }
  EXPECT_TRUE(editor.setPose(1, {Vec3(1, 0, 1), 0}));
  EXPECT_EQ(editor.scene().surfaces[s].outer, home);
}

}  // namespace
}  // namespace engine

// The glTF export read back by an independent reader (tinygltf) with every section required:
// the same triangles and areas per object, the baked colours, and what glTF requires of the
// file (accessor bounds, alignment, unlit materials).
#include "engine/document/gltf_export.h"
#include "engine/document/lighting.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/load_scene.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <set>

namespace engine {
namespace {

struct Lit {
  Scene scene;
  DisplayMesh mesh;
};

// The Cornell box meshed and solved (coarsely: the test is about the file, not the light).
const Lit& litCornell() {
  static const Lit lit = [] {
    Lit out{loadScene(std::string(WALKRAD_ASSETS) + "/cornell.json"), {}};
    const MeshedScene meshed = meshScene(out.scene);
    out.mesh = displayMesh(out.scene, meshed);
    radiosity::Solver solver(radiosityInput(out.scene, meshed));
    solveTo(solver, 0.2, 200);
    setRadiance(out.mesh, solver);
    return out;
  }();
  return lit;
}

tinygltf::Model read(const std::string& bytes, bool binary, unsigned sections = tinygltf::REQUIRE_ALL) {
  tinygltf::TinyGLTF reader;
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = binary ? reader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       static_cast<unsigned>(bytes.size()), "", sections)
                         : reader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), static_cast<unsigned>(bytes.size()),
                                                      "", sections);
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(error, "");
  EXPECT_EQ(warning, "");
  return model;
}

// An accessor's floats (VEC3) or indices (SCALAR uint32), checked for alignment on the way.
template <typename T>
std::vector<T> values(const tinygltf::Model& model, int index, int components) {
  const tinygltf::Accessor& accessor = model.accessors.at(static_cast<size_t>(index));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<size_t>(accessor.bufferView));
  const tinygltf::Buffer& buffer = model.buffers.at(static_cast<size_t>(view.buffer));
  const size_t start = view.byteOffset + accessor.byteOffset, length = accessor.count * components * sizeof(T);
  EXPECT_EQ(start % 4, 0u) << "accessor " << index << " is not 4-byte aligned";
  EXPECT_LE(accessor.byteOffset + length, view.byteLength);
  EXPECT_LE(view.byteOffset + view.byteLength, buffer.data.size());
  std::vector<T> out(accessor.count * components);
  std::memcpy(out.data(), buffer.data.data() + start, length);
  return out;
}

using Key = std::array<float, 3>;
Key keyOf(const glm::vec3& p) { return {p.x, p.y, p.z}; }

TEST(GltfExport, RoundTripKeepsObjectsTrianglesAreasAndColours) {
  const Lit& lit = litCornell();
  const Scene& scene = lit.scene;
  const double exposure = autoExposure(lit.mesh);
  const tinygltf::Model model = read(exportGltf(scene, lit.mesh, {.exposure = exposure, .binary = true}), true);
  const auto scale = static_cast<float>(scene.metersPerUnit);

  // What each object should come back as: its triangles (corners in metres) and area, and the
  // colours its vertices may have at each place.
  std::map<std::string, double> expectedArea;
  std::map<std::string, std::multiset<std::array<Key, 3>>> expectedTriangles;
  std::map<std::string, std::multimap<Key, glm::vec3>> expectedColour;
  for (uint32_t s = 0; s < scene.surfaces.size(); ++s) {
    const std::string& object = scene.objects[scene.surfaces[s].object].name;
    expectedArea[object] += scene.surfaces[s].area * scene.metersPerUnit * scene.metersPerUnit;
    const SurfaceDisplay& display = lit.mesh.surfaces[s];
    for (size_t v = 0; v < display.positions.size(); ++v)
      expectedColour[object].insert(
          {keyOf(display.positions[v] * scale), glm::clamp(display.radiance[v] * static_cast<float>(exposure), 0.0f, 1.0f)});
    for (size_t t = 0; t < display.triangles.size(); t += 3) {
      std::array<Key, 3> corners;
      for (int k = 0; k < 3; ++k) corners[k] = keyOf(display.positions[display.triangles[t + k]] * scale);
      expectedTriangles[object].insert(corners);
    }
  }

  ASSERT_EQ(model.nodes.size(), scene.objects.size());
  ASSERT_EQ(model.scenes.size(), 1u);
  EXPECT_EQ(model.scenes[0].nodes.size(), scene.objects.size());
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"KHR_materials_unlit"});
  EXPECT_NEAR(model.asset.extras.Get("exposure").GetNumberAsDouble(), exposure, 1e-12);
  EXPECT_EQ(model.asset.extras.Get("units").Get<std::string>(), "mm");
  ASSERT_EQ(model.materials.size(), scene.materials.size());
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    EXPECT_EQ(model.materials[m].name, scene.materials[m].name);
    EXPECT_EQ(model.materials[m].extensions.count("KHR_materials_unlit"), 1u);
    EXPECT_EQ(model.materials[m].pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1, 1, 1, 1}));
    EXPECT_FALSE(model.materials[m].doubleSided);
  }

  size_t clamped = 0;
  for (const tinygltf::Node& node : model.nodes) {
    SCOPED_TRACE(node.name);
    ASSERT_GE(node.mesh, 0);
    const tinygltf::Mesh& mesh = model.meshes[static_cast<size_t>(node.mesh)];
    EXPECT_EQ(mesh.name, node.name);
    double area = 0;
    std::multiset<std::array<Key, 3>> triangles;
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
      const tinygltf::Accessor& positionAccessor = model.accessors.at(static_cast<size_t>(primitive.attributes.at("POSITION")));
      ASSERT_EQ(positionAccessor.minValues.size(), 3u);
      ASSERT_EQ(positionAccessor.maxValues.size(), 3u);
      EXPECT_EQ(model.accessors.at(static_cast<size_t>(primitive.indices)).componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
      const auto positions = values<float>(model, primitive.attributes.at("POSITION"), 3);
      const auto colours = values<float>(model, primitive.attributes.at("COLOR_0"), 3);
      const auto radiance = values<float>(model, primitive.attributes.at("_RADIANCE"), 3);
      const auto indices = values<uint32_t>(model, primitive.indices, 1);
      const auto at = [&](const std::vector<float>& v, size_t i) { return glm::vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]); };
      glm::vec3 lo(INFINITY), hi(-INFINITY);
      for (size_t i = 0; i < positions.size() / 3; ++i) {
        lo = glm::min(lo, at(positions, i));
        hi = glm::max(hi, at(positions, i));
        // The colour of a display vertex at this place, within an 8-bit step.
        const glm::vec3 colour = at(colours, i);
        bool found = false;
        const auto [first, last] = expectedColour[node.name].equal_range(keyOf(at(positions, i)));
        for (auto e = first; e != last && !found; ++e) found = glm::length(e->second - colour) < 1.0f / 255;
        EXPECT_TRUE(found) << "vertex " << i;
        EXPECT_LE(std::max({colour.r, colour.g, colour.b}), 1.0f);
        EXPECT_NEAR(glm::length(glm::clamp(at(radiance, i) * static_cast<float>(exposure), 0.0f, 1.0f) - colour), 0, 1e-6);
        clamped += std::max({at(radiance, i).r, at(radiance, i).g, at(radiance, i).b}) * exposure > 1;
      }
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(positionAccessor.minValues[k], lo[k]);
        EXPECT_EQ(positionAccessor.maxValues[k], hi[k]);
      }
      for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3 a = at(positions, indices[t]), b = at(positions, indices[t + 1]), c = at(positions, indices[t + 2]);
        area += 0.5 * glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a)));
        triangles.insert({keyOf(a), keyOf(b), keyOf(c)});
      }
    }
    EXPECT_NEAR(area, expectedArea[node.name], 1e-5 * expectedArea[node.name]);
    EXPECT_TRUE(triangles == expectedTriangles[node.name]) << triangles.size() << " triangles, expected "
                                                           << expectedTriangles[node.name].size();
  }
  // The lamp is brighter than white at this exposure: clamped in COLOR_0, kept in _RADIANCE.
  EXPECT_GT(clamped, 0u);
}

TEST(GltfExport, TextAndBinaryHoldTheSameModel) {
  const Lit& lit = litCornell();
  const tinygltf::Model binary = read(exportGltf(lit.scene, lit.mesh, {.exposure = 2, .binary = true}), true);
  const tinygltf::Model text = read(exportGltf(lit.scene, lit.mesh, {.exposure = 2, .binary = false}), false);
  ASSERT_EQ(binary.buffers.size(), 1u);
  ASSERT_EQ(text.buffers.size(), 1u);
  EXPECT_EQ(binary.buffers[0].data, text.buffers[0].data);
  EXPECT_EQ(binary.accessors.size(), text.accessors.size());
  EXPECT_EQ(binary.nodes.size(), text.nodes.size());
}

TEST(GltfExport, GlbContainerIsWellFormed) {
  const Lit& lit = litCornell();
  const std::string bytes = exportGltf(lit.scene, lit.mesh);
  ASSERT_GE(bytes.size(), 28u);
  const auto word = [&](size_t at) {
    uint32_t w;
    std::memcpy(&w, bytes.data() + at, 4);
    return w;
  };
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(word(4), 2u);
  EXPECT_EQ(word(8), bytes.size());
  const uint32_t jsonLength = word(12);
  EXPECT_EQ(jsonLength % 4, 0u);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  const size_t bin = 20 + jsonLength;
  EXPECT_EQ(word(bin) % 4, 0u);
  EXPECT_EQ(bytes.substr(bin + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(bin + 8 + word(bin), bytes.size());
}

TEST(GltfExport, EmptySceneIsStillValid) {
  Scene scene;
  scene.materials.push_back({});
  const DisplayMesh mesh = displayMesh(scene, MeshedScene{});
  // Nothing to require but the version: glTF forbids empty arrays, so there are no nodes.
  const tinygltf::Model model = read(exportGltf(scene, mesh), true, tinygltf::REQUIRE_VERSION);
  EXPECT_TRUE(model.nodes.empty());
  EXPECT_EQ(model.materials.size(), 1u);
}

// Export, then import through walkrad's own glTF loader: the objects by name, each material's
// reflectance and emission (kept in extras), and per object and material the same area, in the
// same planes, now in metres. The exported elements merge back into planar surfaces.
TEST(GltfExport, ImportBringsBackObjectsMaterialsAndGeometry) {
  const Lit& lit = litCornell();
  const Scene back = parseGltf(exportGltf(lit.scene, lit.mesh, {.exposure = 1, .binary = true}), "cornell-export.glb");

  ASSERT_EQ(back.objects.size(), lit.scene.objects.size());
  for (size_t i = 0; i < back.objects.size(); ++i) EXPECT_EQ(back.objects[i].name, lit.scene.objects[i].name);
  ASSERT_EQ(back.materials.size(), lit.scene.materials.size());
  for (size_t i = 0; i < back.materials.size(); ++i) {
    EXPECT_EQ(back.materials[i].name, lit.scene.materials[i].name);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(back.materials[i].reflectance[c], lit.scene.materials[i].reflectance[c], 1e-12);
      EXPECT_NEAR(back.materials[i].emission[c], lit.scene.materials[i].emission[c], 1e-9 * (1 + lit.scene.materials[i].emission[c]));
    }
  }

  // Areas in square metres per object and material, and the planes they lie in.
  const double m = lit.scene.metersPerUnit;
  std::map<std::pair<uint32_t, uint32_t>, double> before, after;
  for (const Surface& s : lit.scene.surfaces) before[{s.object, s.material}] += s.area * m * m;
  for (const Surface& s : back.surfaces) {
    after[{s.object, s.material}] += s.area;
    const bool inAPlaneOfBefore = std::any_of(lit.scene.surfaces.begin(), lit.scene.surfaces.end(), [&](const Surface& o) {
      return o.object == s.object && glm::dot(o.normal, s.normal) > 1 - 1e-6 && std::abs(o.planeOffset() * m - s.planeOffset()) < 1e-6;
    });
    EXPECT_TRUE(inAPlaneOfBefore) << s.face;
  }
  ASSERT_EQ(after.size(), before.size());
  for (const auto& [key, area] : before) EXPECT_NEAR(after[key], area, 1e-5 * area);
  // Whole walls again, not the exported elements.
  EXPECT_LE(back.surfaces.size(), 2 * lit.scene.surfaces.size());
}

}  // namespace
}  // namespace engine

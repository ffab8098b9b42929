#include "engine/document/gltf_export.h"

#include <nlohmann/json.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

namespace engine {

namespace {

using Json = nlohmann::ordered_json;

// glTF's numbers for component types, accessor targets and primitive modes.
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

// The one binary buffer: views appended one after the other, each starting 4-byte aligned (all
// our components are 4 bytes wide, so every accessor is aligned as glTF requires).
class BinaryBuilder {
 public:
  // Appends a view of `values` and an accessor on it; returns the accessor's index.
  template <typename T>
  size_t accessor(const std::vector<T>& values, int componentType, const char* type, size_t count, int target, Json& doc,
                  const Json& min = nullptr, const Json& max = nullptr) {
    while (bytes_.size() % 4 != 0) bytes_.push_back('\0');
    const size_t offset = bytes_.size(), length = values.size() * sizeof(T);
    bytes_.resize(offset + length);
    std::memcpy(bytes_.data() + offset, values.data(), length);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"target", target}});
    Json accessor = {{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (!min.is_null()) accessor["min"] = min;
    if (!max.is_null()) accessor["max"] = max;
    doc["accessors"].push_back(accessor);
    return doc["accessors"].size() - 1;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t group = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) group |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) group |= static_cast<uint8_t>(bytes[i + 2]);
    out.push_back(kDigits[(group >> 18) & 63]);
    out.push_back(kDigits[(group >> 12) & 63]);
    out.push_back(i + 1 < bytes.size() ? kDigits[(group >> 6) & 63] : '=');
    out.push_back(i + 2 < bytes.size() ? kDigits[group & 63] : '=');
  }
  return out;
}

void appendWord(std::string& out, uint32_t word) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((word >> (8 * k)) & 0xff));  // little-endian
}

// The binary container (glTF 2.0, section 4.4): a 12-byte header, then the JSON chunk padded
// with spaces and the BIN chunk padded with zeros, each to a multiple of 4 bytes.
std::string glb(std::string json, std::string bin) {
  while (json.size() % 4 != 0) json.push_back(' ');
  while (bin.size() % 4 != 0) bin.push_back('\0');
  std::string out;
  appendWord(out, 0x46546C67);  // "glTF"
  appendWord(out, 2);
  appendWord(out, static_cast<uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  appendWord(out, static_cast<uint32_t>(json.size()));
  appendWord(out, 0x4E4F534A);  // "JSON"
  out += json;
  if (!bin.empty()) {
    appendWord(out, static_cast<uint32_t>(bin.size()));
    appendWord(out, 0x004E4942);  // "BIN\0"
    out += bin;
  }
  return out;
}

Json vec3(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

}  // namespace

std::string exportGltf(const Scene& scene, const DisplayMesh& mesh, const GltfExportSettings& settings) {
  Json doc;
  doc["asset"] = {{"version", "2.0"},
                  {"generator", "walkrad"},
                  {"extras", {{"exposure", settings.exposure}, {"units", scene.units}, {"meters_per_unit", scene.metersPerUnit}}}};
  doc["extensionsUsed"] = {"KHR_materials_unlit"};
  doc["scene"] = 0;
  doc["scenes"] = Json::array({{{"nodes", Json::array()}}});
  doc["nodes"] = doc["meshes"] = doc["accessors"] = doc["bufferViews"] = Json::array();
  doc["materials"] = Json::array();
  for (const Material& m : scene.materials)
    doc["materials"].push_back(
        {{"name", m.name},
         {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 1}}},
         {"extensions", {{"KHR_materials_unlit", Json::object()}}},
         {"extras", {{"reflectance", vec3(m.reflectance)}, {"emission", vec3(m.emission)}}}});

  // Surfaces by object, then by material.
  std::map<uint32_t, std::map<uint32_t, std::vector<uint32_t>>> groups;
  for (uint32_t s = 0; s < scene.surfaces.size(); ++s) groups[scene.surfaces[s].object][scene.surfaces[s].material].push_back(s);

  BinaryBuilder bin;
  const float scale = static_cast<float>(scene.metersPerUnit);
  for (const auto& [object, byMaterial] : groups) {
    Json primitives = Json::array();
    for (const auto& [material, surfaces] : byMaterial) {
      std::vector<float> positions, normals, colors, radiance;
      std::vector<uint32_t> indices;
      glm::vec3 lo(INFINITY), hi(-INFINITY);
      for (uint32_t s : surfaces) {
        const SurfaceDisplay& display = mesh.surfaces[s];
        const auto base = static_cast<uint32_t>(positions.size() / 3);
        const glm::vec3 normal(scene.surfaces[s].normal);
        for (size_t v = 0; v < display.positions.size(); ++v) {
          const glm::vec3 p = display.positions[v] * scale, r = display.radiance[v];
          const glm::vec3 c = glm::clamp(r * static_cast<float>(settings.exposure), 0.0f, 1.0f);
          lo = glm::min(lo, p);
          hi = glm::max(hi, p);
          positions.insert(positions.end(), {p.x, p.y, p.z});
          normals.insert(normals.end(), {normal.x, normal.y, normal.z});
          colors.insert(colors.end(), {c.r, c.g, c.b});
          radiance.insert(radiance.end(), {r.r, r.g, r.b});
        }
        for (uint32_t corner : display.triangles) indices.push_back(corner + base);
      }
      if (indices.empty()) continue;
      const size_t count = positions.size() / 3;
      const size_t position = bin.accessor(positions, kFloat, "VEC3", count, kArrayBuffer, doc, {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
      const size_t normal = bin.accessor(normals, kFloat, "VEC3", count, kArrayBuffer, doc);
      const size_t color = bin.accessor(colors, kFloat, "VEC3", count, kArrayBuffer, doc);
      const size_t light = bin.accessor(radiance, kFloat, "VEC3", count, kArrayBuffer, doc);
      const size_t index = bin.accessor(indices, kUnsignedInt, "SCALAR", indices.size(), kElementArrayBuffer, doc);
      primitives.push_back({{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"COLOR_0", color}, {"_RADIANCE", light}}},
                            {"indices", index},
                            {"material", material},
                            {"mode", kTriangles}});
    }
    if (primitives.empty()) continue;
    doc["meshes"].push_back({{"name", scene.objects[object].name}, {"primitives", primitives}});
    Json node = {{"name", scene.objects[object].name}, {"mesh", doc["meshes"].size() - 1}};
    // The positions are about the display mesh's origin, in float; the node puts them in place
    // in double (a model far from the world's origin keeps its detail).
    if (mesh.origin != glm::dvec3{0}) {
      const glm::dvec3 at = mesh.origin * scene.metersPerUnit;
      node["translation"] = {at.x, at.y, at.z};
    }
    doc["nodes"].push_back(std::move(node));
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
  }

  if (!bin.bytes().empty()) {
    Json buffer = {{"byteLength", bin.bytes().size()}};
    if (!settings.binary) buffer["uri"] = "data:application/octet-stream;base64," + base64(bin.bytes());
    doc["buffers"] = Json::array({buffer});
  }
  // glTF allows no empty arrays: an empty scene keeps only what it must.
  if (doc["scenes"][0]["nodes"].empty()) doc["scenes"][0].erase("nodes");
  for (const char* key : {"accessors", "bufferViews", "meshes", "nodes", "materials"})
    if (doc[key].empty()) doc.erase(key);
  return settings.binary ? glb(doc.dump(), bin.bytes()) : doc.dump(1) + "\n";
}

}  // namespace engine

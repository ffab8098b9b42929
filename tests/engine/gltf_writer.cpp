#include "tests/engine/gltf_writer.h"

#include "engine/geometry/surface_mesh.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace engine::test {

namespace {

using Json = nlohmann::ordered_json;

std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

template <class T>
void append(std::string& buffer, T value) {
  char bytes[sizeof value];
  std::memcpy(bytes, &value, sizeof value);
  buffer.append(bytes, sizeof value);
}

void appendComponent(std::string& buffer, int type, double value, bool normalized) {
  switch (type) {
    case kByte: return append(buffer, static_cast<int8_t>(std::lround(normalized ? value * 127 : value)));
    case kUnsignedByte: return append(buffer, static_cast<uint8_t>(std::lround(normalized ? value * 255 : value)));
    case kShort: return append(buffer, static_cast<int16_t>(std::lround(normalized ? value * 32767 : value)));
    case kUnsignedShort: return append(buffer, static_cast<uint16_t>(std::lround(normalized ? value * 65535 : value)));
    case kUnsignedInt: return append(buffer, static_cast<uint32_t>(value));
    default: return append(buffer, static_cast<float>(value));
  }
}

// Buffer views start on 4-byte boundaries, as the spec asks.
void pad(std::string& buffer, char with = '\0') {
  while (buffer.size() % 4) buffer += with;
}

// The document and its one buffer.
Json document(const GltfModel& model, std::string& buffer) {
  Json j;
  j["asset"] = {{"version", "2.0"}, {"generator", "walkrad tests"}};
  j["scene"] = 0;
  j["scenes"] = Json::array({Json{{"nodes", model.roots}}});
  Json nodes = Json::array(), meshes = Json::array(), accessors = Json::array(), views = Json::array();
  auto addView = [&](size_t offset) {
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", buffer.size() - offset}});
    return views.size() - 1;
  };
  for (const GltfNode& n : model.nodes) {
    Json node = Json::object();
    if (!n.name.empty()) node["name"] = n.name;
    if (!n.children.empty()) node["children"] = n.children;
    if (!n.translation.empty()) node["translation"] = n.translation;
    if (!n.rotation.empty()) node["rotation"] = n.rotation;
    if (!n.scale.empty()) node["scale"] = n.scale;
    if (!n.matrix.empty()) node["matrix"] = n.matrix;
    if (n.camera >= 0) node["camera"] = n.camera;
    if (!n.primitives.empty()) {
      Json primitives = Json::array();
      for (const GltfPrimitive& p : n.primitives) {
        Json primitive = {{"attributes", Json::object()}, {"mode", p.mode}};
        // Positions, with their bounds (required by the spec).
        size_t offset = buffer.size();
        Vec3 lo{1e300}, hi{-1e300};
        for (const Vec3& v : p.positions) {
          for (int c = 0; c < 3; ++c) appendComponent(buffer, p.positionType, v[c], p.normalized);
          lo = glm::min(lo, v), hi = glm::max(hi, v);
        }
        pad(buffer);
        Json positions = {{"bufferView", addView(offset)}, {"componentType", p.positionType}, {"count", p.positions.size()},
                          {"type", "VEC3"}, {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}};
        if (p.normalized) positions["normalized"] = true;
        accessors.push_back(positions);
        primitive["attributes"]["POSITION"] = accessors.size() - 1;
        if (!p.indices.empty()) {
          offset = buffer.size();
          for (uint32_t i : p.indices) appendComponent(buffer, p.indexType, i, false);
          pad(buffer);
          accessors.push_back({{"bufferView", addView(offset)}, {"componentType", p.indexType}, {"count", p.indices.size()}, {"type", "SCALAR"}});
          primitive["indices"] = accessors.size() - 1;
        }
        if (p.material >= 0) primitive["material"] = p.material;
        primitives.push_back(primitive);
      }
      meshes.push_back({{"primitives", primitives}});
      node["mesh"] = meshes.size() - 1;
    }
    nodes.push_back(node);
  }
  j["nodes"] = nodes;
  if (!meshes.empty()) j["meshes"] = meshes;
  Json materials = Json::array(), textures = Json::array(), images = Json::array();
  bool strength = false;
  for (const GltfMaterial& m : model.materials) {
    Json material = {{"name", m.name},
                     {"pbrMetallicRoughness", {{"baseColorFactor", {m.baseColor.r, m.baseColor.g, m.baseColor.b, m.baseColor.a}},
                                               {"metallicFactor", 0}}},
                     {"emissiveFactor", {m.emissive.x, m.emissive.y, m.emissive.z}}};
    if (!m.baseColorImage.empty()) {
      material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", textures.size()}};
      textures.push_back({{"source", images.size()}});
      images.push_back({{"uri", m.baseColorImage}});
    }
    if (m.emissiveStrength > 0) {
      material["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", m.emissiveStrength}}}};
      strength = true;
    }
    materials.push_back(material);
  }
  if (!materials.empty()) j["materials"] = materials;
  if (!textures.empty()) j["textures"] = textures, j["images"] = images;
  if (strength) j["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  Json cameras = Json::array();
  for (const GltfCamera& c : model.cameras)
    cameras.push_back({{"name", c.name}, {"type", "perspective"}, {"perspective", {{"yfov", c.yfovRad}, {"znear", 0.01}}}});
  if (!cameras.empty()) j["cameras"] = cameras;
  if (!accessors.empty()) j["accessors"] = accessors;
  if (!views.empty()) j["bufferViews"] = views;
  return j;
}

}  // namespace

std::string gltfText(const GltfModel& model) {
  std::string buffer;
  Json j = document(model, buffer);
  j["buffers"] = Json::array({Json{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}});
  return j.dump(1);
}

std::string glbBytes(const GltfModel& model) {
  std::string buffer;
  Json j = document(model, buffer);
  j["buffers"] = Json::array({Json{{"byteLength", buffer.size()}}});
  std::string json = j.dump();
  pad(json, ' ');
  pad(buffer);
  std::string out = "glTF";
  append(out, uint32_t{2});
  append(out, static_cast<uint32_t>(12 + 8 + json.size() + 8 + buffer.size()));
  append(out, static_cast<uint32_t>(json.size()));
  out += "JSON";
  out += json;
  append(out, static_cast<uint32_t>(buffer.size()));
  out += std::string("BIN\0", 4);
  out += buffer;
  return out;
}

GltfModel modelOfScene(const Scene& scene, double scale) {
  GltfModel model;
  for (const Material& m : scene.materials) {
    GltfMaterial material{m.name, glm::dvec4(m.reflectance, 1), Vec3{0}, 0, ""};
    const double peak = std::max({m.emission.x, m.emission.y, m.emission.z});
    if (peak > 0) material.emissive = m.emission / peak, material.emissiveStrength = peak;
    model.materials.push_back(material);
  }
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    GltfNode node;
    node.name = scene.objects[o].name;
    for (const Surface& s : scene.surfaces) {
      if (s.object != o) continue;
      GltfPrimitive p;
      p.material = static_cast<int>(s.material);
      for (const Vec3& v : s.outer) p.positions.push_back(v * scale);
      for (const Ring3& hole : s.holes)
        for (const Vec3& v : hole) p.positions.push_back(v * scale);
      for (const auto& t : mesher::triangulate(planePolygon(s, s))) p.indices.insert(p.indices.end(), t.begin(), t.end());
      node.primitives.push_back(std::move(p));
    }
    model.roots.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(std::move(node));
  }
  for (const Camera& c : scene.cameras) {
    // Looking down the node's -z with its +y up.
    const Vec3 back = glm::normalize(c.position - c.lookAt);
    const Vec3 right = glm::normalize(glm::cross(c.up, back));
    const Vec3 up = glm::cross(back, right);
    GltfNode node;
    node.name = c.name;
    node.camera = static_cast<int>(model.cameras.size());
    node.matrix = {right.x, right.y, right.z, 0, up.x, up.y, up.z, 0, back.x, back.y, back.z, 0,
                   c.position.x * scale, c.position.y * scale, c.position.z * scale, 1};
    model.cameras.push_back({c.name, glm::radians(c.fovYDeg)});
    model.roots.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(std::move(node));
  }
  return model;
}

}  // namespace engine::test

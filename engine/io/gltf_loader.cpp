// Sections: accessors | materials | the node tree | loadGltf.
#include "engine/io/gltf_loader.h"

#include "engine/diagnostics.h"
#include "engine/geometry/contact_cutouts.h"
#include "engine/geometry/coplanar_merge.h"
#include "engine/io/gltf_files.h"
#include "engine/io/gltf_sidecar.h"
#include "engine/io/input_file.h"
#include "engine/io/json_reader.h"
#include "engine/io/load_limits.h"
#include "engine/io/unique_names.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>

namespace engine {

namespace {

constexpr double kMaxReflectance = 0.95;  // albedo 1 in a closed room never converges
constexpr double kSkyLift = 0.01;         // the sky floats this fraction of the extent above the model

// extras.KEY when it is three numbers, as walkrad's exporter writes a material's reflectance and
// emission (document/gltf_export.h).
std::optional<Vec3> extrasVec3(const tinygltf::Value& extras, const char* key) {
  if (!extras.IsObject() || !extras.Has(key)) return std::nullopt;
  const tinygltf::Value& value = extras.Get(key);
  if (!value.IsArray() || value.ArrayLen() != 3) return std::nullopt;
  Vec3 v;
  for (int c = 0; c < 3; ++c) {
    if (!value.Get(c).IsNumber()) return std::nullopt;
    v[c] = value.Get(c).GetNumberAsDouble();
  }
  return v;
}

// ---- accessors ----

// Checked reading of one accessor: every element lies inside its buffer view and buffer.
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int index, const std::string& file, const std::string& user) {
    place_ = child("accessors", static_cast<size_t>(index));
    auto fail = [&](Diag diag, const std::string& detail) { throw SceneError(diag, file, place_, detail + " (" + user + ")"); };
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
      throw SceneError(Diag::BadGltfReference, file, user, "accessor " + std::to_string(index));
    const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
    if (a.sparse.isSparse) fail(Diag::BadAccessor, "sparse accessors are not read");
    componentType_ = a.componentType;
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    components_ = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    if (componentSize <= 0 || components_ <= 0) fail(Diag::BadAccessor, "unknown component or element type");
    componentSize_ = static_cast<size_t>(componentSize);
    normalized_ = a.normalized;
    count_ = a.count;
    // Without a view the spec makes every element zero: no geometry, and an unchecked count
    // (any number) would size what is read from it.
    if (a.bufferView < 0) {
      if (count_ > 0) fail(Diag::BadAccessor, std::to_string(count_) + " elements and no bufferView");
      return;
    }
    if (static_cast<size_t>(a.bufferView) >= model.bufferViews.size()) fail(Diag::BadGltfReference, "bufferView " + std::to_string(a.bufferView));
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
      fail(Diag::BadGltfReference, "buffer " + std::to_string(view.buffer));
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(view.buffer)].data;
    const size_t elementSize = componentSize_ * static_cast<size_t>(components_);
    stride_ = view.byteStride ? view.byteStride : elementSize;
    if (stride_ < elementSize) fail(Diag::BadAccessor, "byteStride " + std::to_string(stride_) + " below the element size");
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      fail(Diag::BadAccessor, "bufferView " + std::to_string(a.bufferView) + " runs past its buffer of " + std::to_string(buffer.size()) + " bytes");
    // The last element ends inside the view (divisions first: counts may be absurd).
    if (count_ > 0 && (a.byteOffset > view.byteLength || (count_ - 1) > (view.byteLength - a.byteOffset) / stride_ ||
                       a.byteOffset + (count_ - 1) * stride_ + elementSize > view.byteLength))
      fail(Diag::BadAccessor, std::to_string(count_) + " elements do not fit bufferView " + std::to_string(a.bufferView));
    data_ = buffer.data() + view.byteOffset + a.byteOffset;
  }

  size_t count() const { return count_; }
  int components() const { return components_; }
  int componentType() const { return componentType_; }
  const std::string& place() const { return place_; }

  // Component c of element i; normalised integers map to [0, 1] or [-1, 1] as the spec says.
  double get(size_t i, int c) const {
    if (!data_) return 0;
    const unsigned char* p = data_ + i * stride_ + static_cast<size_t>(c) * componentSize_;
    switch (componentType_) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: return scaled(load<int8_t>(p), 127.0, true);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return scaled(load<uint8_t>(p), 255.0, false);
      case TINYGLTF_COMPONENT_TYPE_SHORT: return scaled(load<int16_t>(p), 32767.0, true);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return scaled(load<uint16_t>(p), 65535.0, false);
      case TINYGLTF_COMPONENT_TYPE_INT: return scaled(load<int32_t>(p), 2147483647.0, true);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return scaled(load<uint32_t>(p), 4294967295.0, false);
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
      default: return load<double>(p);  // TINYGLTF_COMPONENT_TYPE_DOUBLE (not glTF 2.0, but tinygltf knows it)
    }
  }

 private:
  template <class T>
  static T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return value;
  }
  double scaled(double value, double max, bool isSigned) const {
    if (!normalized_) return value;
    return isSigned ? std::max(value / max, -1.0) : value / max;
  }

  const unsigned char* data_ = nullptr;
  size_t count_ = 0, stride_ = 0, componentSize_ = 0;
  int components_ = 0, componentType_ = 0;
  bool normalized_ = false;
  std::string place_;
};

// ---- materials ----

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The mean linear colour of a decoded base-colour texture (sRGB), or white when it is not there
// (an image file missing beside the model is a warning to tinygltf, not an error).
Vec3 textureMean(const tinygltf::Model& model, int textureIndex) {
  if (textureIndex < 0 || static_cast<size_t>(textureIndex) >= model.textures.size()) return Vec3{1};
  const int source = model.textures[static_cast<size_t>(textureIndex)].source;
  if (source < 0 || static_cast<size_t>(source) >= model.images.size()) return Vec3{1};
  const tinygltf::Image& image = model.images[static_cast<size_t>(source)];
  const size_t pixels = static_cast<size_t>(std::max(image.width, 0)) * static_cast<size_t>(std::max(image.height, 0));
  const size_t bytes = (image.bits == 16 ? 2 : 1);
  if (pixels == 0 || image.component < 3 || (image.bits != 8 && image.bits != 16) ||
      image.image.size() < pixels * static_cast<size_t>(image.component) * bytes)
    return Vec3{1};
  Vec3 sum{0};
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) {
      const size_t at = (i * static_cast<size_t>(image.component) + static_cast<size_t>(c)) * bytes;
      const double value = bytes == 2 ? (image.image[at] | (image.image[at + 1] << 8)) / 65535.0 : image.image[at] / 255.0;
      sum[c] += srgbToLinear(value);
    }
  return sum / static_cast<double>(pixels);
}

// ---- the node tree ----

glm::dmat4 localMatrix(const tinygltf::Node& node, const std::string& file, const std::string& place) {
  auto check = [&](const std::vector<double>& values, size_t size, const char* what) {
    if (!values.empty() && values.size() != size)
      throw SceneError(Diag::WrongType, file, place + "." + what, std::to_string(values.size()) + " numbers, expected " + std::to_string(size));
    for (double v : values)
      if (!std::isfinite(v) || std::abs(v) > kMaxLength) throw SceneError(Diag::NotFinite, file, place + "." + what);
  };
  check(node.matrix, 16, "matrix");
  check(node.translation, 3, "translation");
  check(node.rotation, 4, "rotation");
  check(node.scale, 3, "scale");
  if (!node.matrix.empty()) {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<size_t>(4 * c + r)];  // column-major, as glTF
    return m;
  }
  glm::dmat4 m{1.0};
  if (!node.translation.empty()) m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1);
  if (!node.rotation.empty()) {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // glTF: x, y, z, w
    if (glm::length(q) == 0) throw SceneError(Diag::Degenerate, file, place + ".rotation", "a zero quaternion");
    m = m * glm::dmat4(glm::mat3_cast(glm::normalize(q)));
  }
  if (!node.scale.empty()) m = m * glm::scale(glm::dmat4{1.0}, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

class GltfImporter {
 public:
  GltfImporter(const tinygltf::Model& model, const std::string& file, const GltfSidecar& sidecar, Scene& scene)
      : model_(model), file_(file), sidecar_(sidecar), scene_(scene) {}

  std::vector<SceneTriangle> run() {
    readMaterials();
    const std::vector<int> roots = rootNodes();
    visited_.assign(model_.nodes.size(), 0);
    UniqueNames objectNames;
    std::set<std::string> rootNames;
    for (int root : roots) rootNames.insert(model_.nodes[static_cast<size_t>(root)].name);
    for (const auto& [name, movable] : sidecar_.movableObjects)
      if (!rootNames.count(name)) throw SceneError(Diag::UnknownNode, sidecarFile_, child("objects", name));
    for (int root : roots) {
      const tinygltf::Node& node = model_.nodes[static_cast<size_t>(root)];
      const size_t before = triangles_.size();
      const glm::dmat4 world = localMatrix(node, file_, child("nodes", static_cast<size_t>(root)));
      const auto object = static_cast<uint32_t>(scene_.objects.size());
      readSubtree(static_cast<size_t>(root), world, object);
      if (triangles_.size() == before) continue;  // a camera or an empty group: nothing to drag
      Object o;
      o.name = objectNames.add(node.name.empty() ? child("node", static_cast<size_t>(root)) : node.name);
      o.position = Vec3(world[3]);
      const auto own = sidecar_.movableObjects.find(node.name);
      o.movable = own != sidecar_.movableObjects.end() ? own->second : sidecar_.movable.value_or(true);
      scene_.objects.push_back(std::move(o));
      objectNode_.push_back(static_cast<size_t>(root));
    }
    counts_.nodes = roots.size();
    return std::move(triangles_);
  }

  const ImportCounts& counts() const { return counts_; }
  size_t nodeOf(uint32_t object) const { return objectNode_[object]; }
  void setSidecarFile(std::string file) { sidecarFile_ = std::move(file); }

 private:
  [[noreturn]] void fail(Diag diag, const std::string& place, const std::string& detail = {}) const {
    throw SceneError(diag, file_, place, detail);
  }

  void readMaterials() {
    std::set<std::string> overridden;
    for (size_t i = 0; i < model_.materials.size(); ++i) {
      const tinygltf::Material& m = model_.materials[i];
      const std::string place = child("materials", i);
      Material material;
      material.name = materialNames_.add(m.name.empty() ? child("material", i) : m.name);
      const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
      if (base.size() != 4) fail(Diag::WrongType, place + ".pbrMetallicRoughness.baseColorFactor", "expected 4 numbers");
      const Vec3 texture = textureMean(model_, m.pbrMetallicRoughness.baseColorTexture.index);
      material.reflectance = glm::clamp(Vec3(base[0], base[1], base[2]) * texture, 0.0, kMaxReflectance);
      if (m.emissiveFactor.size() != 3) fail(Diag::WrongType, place + ".emissiveFactor", "expected 3 numbers");
      double strength = 1;
      if (const auto ext = m.extensions.find("KHR_materials_emissive_strength"); ext != m.extensions.end()) {
        const tinygltf::Value& value = ext->second.Get("emissiveStrength");
        if (value.IsNumber()) strength = value.GetNumberAsDouble();
      }
      material.emission = Vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]) * strength;
      // A model walkrad exported keeps its materials' light in extras (its own are unlit).
      if (const auto reflectance = extrasVec3(m.extras, "reflectance")) material.reflectance = glm::clamp(*reflectance, 0.0, 1.0);
      if (const auto emission = extrasVec3(m.extras, "emission")) material.emission = *emission;
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(material.reflectance[c])) fail(Diag::NotFinite, place + ".pbrMetallicRoughness.baseColorFactor");
        if (!(material.emission[c] >= 0 && material.emission[c] <= kMaxEmission))
          fail(Diag::OutOfRange, place + ".emissiveFactor", "emission must lie in 0..1e6");
      }
      // The model's light is in range; scaled out of it, the sidecar's scale is what is wrong.
      material.emission *= sidecar_.emissionScale;
      if (glm::any(glm::greaterThan(material.emission, Vec3(kMaxEmission))))
        throw SceneError(Diag::OutOfRange, sidecarFile_, "emission_scale",
                         "takes " + place + "'s emission beyond 1e6 (" + material.name + ")");
      bool omit = false, twoSided = false;
      if (const auto o = sidecar_.materials.find(m.name); o != sidecar_.materials.end()) {
        if (o->second.reflectance) material.reflectance = *o->second.reflectance;
        if (o->second.emission) material.emission = *o->second.emission;
        omit = o->second.omit;
        twoSided = o->second.twoSided;
        overridden.insert(m.name);
      }
      omitted_.push_back(omit);
      twoSided_.push_back(twoSided);
      scene_.materials.push_back(std::move(material));
    }
    for (const auto& [name, o] : sidecar_.materials)
      if (!overridden.count(name)) throw SceneError(Diag::UnknownMaterial, sidecarFile_, child("materials", name));
  }

  // glTF's default material, added when a primitive has none.
  uint32_t defaultMaterial() {
    if (!defaultMaterial_) {
      Material material;
      material.name = materialNames_.add("default");
      material.reflectance = Vec3{kMaxReflectance};
      defaultMaterial_ = static_cast<uint32_t>(scene_.materials.size());
      scene_.materials.push_back(std::move(material));
      omitted_.push_back(false);
      twoSided_.push_back(false);
    }
    return *defaultMaterial_;
  }

  // The scene's top-level nodes: those of the default scene (else the first), else every node
  // no other node holds.
  std::vector<int> rootNodes() const {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (static_cast<size_t>(scene) >= model_.scenes.size()) fail(Diag::BadGltfReference, "scene", std::to_string(scene));
      roots = model_.scenes[static_cast<size_t>(scene)].nodes;
    } else {
      std::vector<uint8_t> held(model_.nodes.size(), 0);
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && static_cast<size_t>(c) < held.size()) held[static_cast<size_t>(c)] = 1;
      for (size_t i = 0; i < held.size(); ++i)
        if (!held[i]) roots.push_back(static_cast<int>(i));
    }
    for (int r : roots)
      if (r < 0 || static_cast<size_t>(r) >= model_.nodes.size()) fail(Diag::BadGltfReference, "scenes", "node " + std::to_string(r));
    return roots;
  }

  // A top-level node and its subtree, depth first in the file's order, on a stack of its own (a
  // chain of nodes is as deep as the file is long). A node met twice (a loop, or shared by two
  // parents) is refused, so the walk ends.
  void readSubtree(size_t root, const glm::dmat4& rootWorld, uint32_t object) {
    std::vector<std::pair<size_t, glm::dmat4>> pending{{root, rootWorld}};  // nodes and their world transforms
    while (!pending.empty()) {
      const auto [i, world] = pending.back();
      pending.pop_back();
      const std::string place = child("nodes", i);
      if (visited_[i]) fail(Diag::NodeLoop, place);
      visited_[i] = 1;
      const tinygltf::Node& node = model_.nodes[i];
      if (node.mesh >= 0) {
        if (static_cast<size_t>(node.mesh) >= model_.meshes.size()) fail(Diag::BadGltfReference, place + ".mesh", std::to_string(node.mesh));
        readMesh(static_cast<size_t>(node.mesh), world, object);
      }
      if (node.camera >= 0) readCamera(node, i, world);
      const size_t firstChild = pending.size();
      for (int c : node.children) {
        if (c < 0 || static_cast<size_t>(c) >= model_.nodes.size()) fail(Diag::BadGltfReference, place + ".children", std::to_string(c));
        const auto ci = static_cast<size_t>(c);
        pending.emplace_back(ci, world * localMatrix(model_.nodes[ci], file_, child("nodes", ci)));
      }
      std::reverse(pending.begin() + static_cast<std::ptrdiff_t>(firstChild), pending.end());  // the first child on top
    }
  }

  void readMesh(size_t meshIndex, const glm::dmat4& world, uint32_t object) {
    const tinygltf::Mesh& mesh = model_.meshes[meshIndex];
    const glm::dmat3 linear(world);
    const bool mirrored = glm::determinant(linear) < 0;  // a mirroring transform turns fronts to backs
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      const std::string place = child(child(child("meshes", meshIndex), "primitives"), p);
      const int mode = primitive.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) continue;
      uint32_t material = 0;
      if (primitive.material < 0) {
        material = defaultMaterial();
      } else {
        if (static_cast<size_t>(primitive.material) >= model_.materials.size())
          fail(Diag::BadGltfReference, place + ".material", std::to_string(primitive.material));
        material = static_cast<uint32_t>(primitive.material);
      }
      if (omitted_[material]) continue;
      const auto position = primitive.attributes.find("POSITION");
      if (position == primitive.attributes.end()) fail(Diag::MissingField, place + ".attributes", "POSITION");
      const AccessorReader positions(model_, position->second, file_, place + ".attributes.POSITION");
      if (positions.components() != 3) fail(Diag::BadAccessor, positions.place(), "POSITION must be VEC3");
      std::vector<Vec3> points(positions.count());
      for (size_t i = 0; i < points.size(); ++i) {
        const glm::dvec4 p4 = world * glm::dvec4(positions.get(i, 0), positions.get(i, 1), positions.get(i, 2), 1);
        points[i] = Vec3(p4);
        for (int c = 0; c < 3; ++c)
          if (!std::isfinite(points[i][c]) || std::abs(points[i][c]) > kMaxLength)
            fail(Diag::OutOfRange, positions.place(), "position " + std::to_string(i) + " is not finite or beyond 1e6");
      }
      std::vector<uint32_t> indices;
      if (primitive.indices >= 0) {
        const AccessorReader reader(model_, primitive.indices, file_, place + ".indices");
        const int type = reader.componentType();
        if (reader.components() != 1 || (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                          type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
          fail(Diag::BadAccessor, reader.place(), "indices must be unsigned integer scalars");
        indices.reserve(reader.count());
        for (size_t i = 0; i < reader.count(); ++i) {
          const double value = reader.get(i, 0);
          if (value >= static_cast<double>(points.size()))
            fail(Diag::BadAccessor, reader.place(), "index " + std::to_string(static_cast<uint64_t>(value)) + " beyond the " +
                                                        std::to_string(points.size()) + " positions");
          indices.push_back(static_cast<uint32_t>(value));
        }
      } else {
        indices.reserve(points.size());
        for (size_t i = 0; i < points.size(); ++i) indices.push_back(static_cast<uint32_t>(i));
      }
      // A mesh may be placed by any number of nodes and list one accessor in any number of
      // primitives: the count is checked before the triangles are made.
      const size_t made = mode == TINYGLTF_MODE_TRIANGLES ? indices.size() / 3 : (indices.size() < 3 ? 0 : indices.size() - 2);
      checkFaceCount(triangles_.size() + made * (twoSided_[material] ? 2 : 1), file_, place);
      auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (mirrored) std::swap(b, c);
        triangles_.push_back({{points[a], points[b], points[c]}, material, object});
        if (twoSided_[material]) triangles_.push_back({{points[a], points[c], points[b]}, material, object});
      };
      if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (size_t i = 0; i + 2 < indices.size(); i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
      } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // Every second triangle of a strip runs the other way round.
        for (size_t i = 0; i + 2 < indices.size(); ++i)
          i % 2 ? add(indices[i + 1], indices[i], indices[i + 2]) : add(indices[i], indices[i + 1], indices[i + 2]);
      } else {
        for (size_t i = 1; i + 1 < indices.size(); ++i) add(indices[0], indices[i], indices[i + 1]);
      }
    }
  }

  void readCamera(const tinygltf::Node& node, size_t nodeIndex, const glm::dmat4& world) {
    const std::string place = child(child("nodes", nodeIndex), "camera");
    if (static_cast<size_t>(node.camera) >= model_.cameras.size()) fail(Diag::BadGltfReference, place, std::to_string(node.camera));
    const tinygltf::Camera& c = model_.cameras[static_cast<size_t>(node.camera)];
    if (c.type != "perspective") return;  // orthographic views are not walked through
    Camera camera;
    camera.name = cameraNames_.add(!c.name.empty() ? c.name : !node.name.empty() ? node.name : child("camera", static_cast<size_t>(node.camera)));
    camera.position = Vec3(world[3]);
    const glm::dmat3 linear(world);
    const Vec3 forward = linear * Vec3(0, 0, -1), up = linear * Vec3(0, 1, 0);
    camera.fovYDeg = glm::degrees(c.perspective.yfov);
    if (!(camera.fovYDeg > 0 && camera.fovYDeg <= 179) || glm::length(forward) == 0 || glm::length(glm::cross(forward, up)) == 0)
      fail(Diag::BadCamera, place);
    camera.lookAt = camera.position + glm::normalize(forward);
    camera.up = glm::normalize(up);
    scene_.cameras.push_back(std::move(camera));
  }

  const tinygltf::Model& model_;
  const std::string& file_;
  const GltfSidecar& sidecar_;
  std::string sidecarFile_;
  Scene& scene_;
  std::vector<uint8_t> omitted_;   // per material
  std::vector<uint8_t> twoSided_;  // per material
  std::optional<uint32_t> defaultMaterial_;
  std::vector<uint8_t> visited_;  // per node
  UniqueNames materialNames_, cameraNames_;
  std::vector<SceneTriangle> triangles_;
  std::vector<size_t> objectNode_;  // per object
  ImportCounts counts_;
};

// A sky over the model: a fixed emitter facing down, over the model's footprint, a little above
// it, for open models (an atrium, a courtyard) whose light is the sky.
void addSky(Scene& scene, const Vec3& emission, const Vec3& lo, const Vec3& hi) {
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  Material material;
  material.name = "sky";
  material.reflectance = Vec3{0};
  material.emission = emission;
  scene.materials.push_back(material);
  Object object;
  object.name = "sky";
  object.movable = false;
  scene.objects.push_back(object);
  Surface s;
  const double y = hi.y + kSkyLift * extent;
  // Counter-clockwise seen from below, the front.
  s.outer = {{lo.x, y, lo.z}, {hi.x, y, lo.z}, {hi.x, y, hi.z}, {lo.x, y, hi.z}};
  s.normal = {0, -1, 0};
  s.area = (hi.x - lo.x) * (hi.z - lo.z);
  s.material = static_cast<uint32_t>(scene.materials.size() - 1);
  s.object = static_cast<uint32_t>(scene.objects.size() - 1);
  s.face = "sky";
  s.jsonPath = "sky";
  scene.surfaces.push_back(std::move(s));
}

// The first line of tinygltf's message, cut short (it may quote a whole data: URI).
std::string firstLine(const std::string& text) {
  constexpr size_t kLongest = 200;
  const std::string line = text.substr(0, text.find('\n'));
  return line.size() <= kLongest ? line : line.substr(0, kLongest) + "...";
}


// Each triangle a surface of its own, as the file describes it (for walkrad check): degenerate
// ones included, with no area and the default normal.
std::vector<Surface> triangleFaces(const std::vector<SceneTriangle>& triangles, const GltfImporter& importer) {
  std::vector<Surface> faces;
  faces.reserve(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    const SceneTriangle& t = triangles[i];
    Surface face;
    face.outer.assign(t.corners.begin(), t.corners.end());
    const Vec3 cross = glm::cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]);
    const double twiceArea = glm::length(cross);
    if (twiceArea > 0) face.normal = cross / twiceArea;
    face.area = twiceArea / 2;
    face.material = t.material;
    face.object = t.object;
    face.face = "triangle " + std::to_string(i);
    face.jsonPath = child("nodes", importer.nodeOf(t.object));
    faces.push_back(std::move(face));
  }
  return faces;
}

enum class GltfStage { Faces, Surfaces };

Scene importGltf(std::string_view bytes, const std::string& file, const LoadOptions& options, GltfStage stage) {
  // The sidecar first: its errors are the user's to fix whatever the model holds.
  GltfSidecar sidecar;
  std::string sidecarFile = options.sidecar;
  if (sidecarFile.empty() && std::filesystem::exists(sidecarPathFor(file))) sidecarFile = sidecarPathFor(file);
  if (!sidecarFile.empty()) sidecar = parseGltfSidecar(readInputFile(sidecarFile), sidecarFile);

  // The files the model names, confined to its folder (gltf_files.h); tinygltf reads no other.
  GltfFiles files(bytes, file);
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(files.callbacks());
  tinygltf::Model model;
  std::string error, warning;
  const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
  const bool read = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                         static_cast<unsigned int>(bytes.size()), "")
                           : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                                        static_cast<unsigned int>(bytes.size()), "");
  if (!read) throw SceneError(Diag::NotGltf, file, "", error.empty() ? "tinygltf gave no reason" : firstLine(error));

  Scene scene;
  scene.file = file;
  scene.units = !options.units.empty() ? options.units : !sidecar.units.empty() ? sidecar.units : "m";
  scene.metersPerUnit = metersPerUnit(scene.units);
  if (scene.metersPerUnit == 0) throw SceneError(Diag::UnknownUnits, file, "--units", "\"" + scene.units + "\"");

  // The model's triangles, by object and material.
  GltfImporter importer(model, file, sidecar, scene);
  importer.setSidecarFile(sidecarFile);
  std::vector<SceneTriangle> triangles = importer.run();
  if (triangles.empty()) throw SceneError(Diag::NoTriangles, file, "");
  Vec3 lo = triangles.front().corners[0], hi = lo;
  for (const SceneTriangle& t : triangles)
    for (const Vec3& p : t.corners) lo = glm::min(lo, p), hi = glm::max(hi, p);

  if (stage == GltfStage::Faces) {
    scene.surfaces = triangleFaces(triangles, importer);
  } else {
    // Coplanar triangles into polygons, within a tolerance relative to the model's size.
    TriangleMergeCounts merged;
    scene.surfaces = mergeTriangles(scene, triangles, kMergeTolerance * glm::length(hi - lo), &merged);
    for (Surface& s : scene.surfaces) s.jsonPath = child("nodes", importer.nodeOf(s.object));
    if (sidecar.sky) addSky(scene, *sidecar.sky, lo, hi);
    ImportCounts counts = importer.counts();
    counts.triangles = merged.triangles;
    counts.degenerate = merged.degenerate;
    counts.tJunctions = merged.tJunctions;
    counts.singles = merged.singles;
    scene.imported = counts;
  }

  // Patch size: the sidecar's, else an eighth of the largest extent (as scene files).
  scene.computeBounds();
  const double extent = sceneExtent(scene);
  scene.patchSize = sidecar.patchSize.value_or(extent / 8);
  checkPatchSize(scene.patchSize, extent, sidecarFile, "patch_size");
  for (Surface& s : scene.surfaces) s.patchSize = scene.patchSize;
  if (stage == GltfStage::Surfaces) cutOutContacts(scene.surfaces, contactTolerance(scene));
  return scene;
}

}  // namespace

bool isGltfPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".gltf" || extension == ".glb";
}

Scene parseGltf(std::string_view bytes, const std::string& file, const LoadOptions& options) {
  return importGltf(bytes, file, options, GltfStage::Surfaces);
}

Scene loadGltf(const std::string& path, const LoadOptions& options) {
  return parseGltf(readInputFile(path), path, options);
}

Scene loadGltfFaces(const std::string& path, const LoadOptions& options) {
  return importGltf(readInputFile(path), path, options, GltfStage::Faces);
}

}  // namespace engine

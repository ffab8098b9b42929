// A small glTF 2.0 writer for tests: models described in code (nodes, primitives, materials,
// cameras) written as .gltf text with one embedded base64 buffer, or as .glb bytes, in every
// index and position component type the loader must read.
#pragma once

#include "engine/scene.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace engine::test {

// glTF component types.
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6, kLines = 1;

struct GltfPrimitive {
  std::vector<Vec3> positions;
  std::vector<uint32_t> indices;  // empty: none (positions in order)
  int indexType = kUnsignedInt;
  int positionType = kFloat;      // integer types store the positions rounded (or scaled when normalised)
  bool normalized = false;
  int mode = kTriangles;
  int material = -1;
};

struct GltfNode {
  std::string name;
  std::vector<GltfPrimitive> primitives;  // a mesh of its own when not empty
  std::vector<int> children;
  std::vector<double> translation, rotation, scale, matrix;  // as glTF: empty when absent
  int camera = -1;
};

struct GltfMaterial {
  std::string name;
  glm::dvec4 baseColor{1};
  Vec3 emissive{0};
  double emissiveStrength = 0;  // > 0: written as KHR_materials_emissive_strength
  std::string baseColorImage;   // a base-colour texture's image file (uri), or none
};

struct GltfCamera {
  std::string name;
  double yfovRad = 1;
};

struct GltfModel {
  std::vector<GltfNode> nodes;
  std::vector<int> roots;  // the scene's nodes
  std::vector<GltfMaterial> materials;
  std::vector<GltfCamera> cameras;
};

// The model as .gltf text, its buffer embedded as a data: URI.
std::string gltfText(const GltfModel& model);
// The model as .glb bytes (JSON chunk, then the binary chunk).
std::string glbBytes(const GltfModel& model);

// A scene's surfaces as a model: one node per object (named as it), one primitive per surface
// (ear-clipped, holes and all), one material per scene material; coordinates scaled by `scale`
// (a scene in mm written in glTF's metres: 0.001). Emission is written as a factor of at most 1
// times KHR_materials_emissive_strength. Cameras go along as camera nodes.
GltfModel modelOfScene(const Scene& scene, double scale);

}  // namespace engine::test

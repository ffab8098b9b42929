// The model check on scene text (input starting with '{'), or on a soup of triangles decoded from
// bytes and written as a .glb model, checked as `walkrad check model.glb` does and imported whole
// (coplanar triangles merged, contact cut-outs) as every other subcommand does. Soup layout
// (bytes; past the end all zeros):
//   mode       bit 0: coordinates as int8 in quarters (a coarse grid, so faces often coincide,
//              touch and cross), else float32
//   then per triangle: a tag (object tag % 4, material tag / 4 % 4) and its three corners;
//   at most 64 triangles (a random soup of 256 takes 70 ms in the release build, most of it
//   formatting its findings' messages).
#include "tests/fuzz/fuzz_targets.h"

#include "engine/diagnostics.h"
#include "engine/geometry/model_check.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/scene_loader.h"
#include "tests/engine/gltf_writer.h"
#include "tests/fuzz/byte_reader.h"
#include "tests/fuzz/meshable.h"
#include "tests/fuzz/temp_folder.h"

#include <fstream>
#include <string_view>

namespace fuzz::model_check {

namespace {

constexpr int kObjects = 4, kMaterials = 4;
constexpr size_t kMostTriangles = 64;

engine::test::GltfModel soupModel(const uint8_t* data, size_t size) {
  ByteReader in(data, size);
  const bool grid = in.next<uint8_t>() & 1;
  engine::test::GltfModel model;
  for (int m = 0; m < kMaterials; ++m) {
    // The last material emits, as a lamp would.
    model.materials.push_back({"material " + std::to_string(m), glm::dvec4(0.2 * (m + 1)), engine::Vec3(m == 3 ? 1.0 : 0.0), 0, ""});
  }
  model.nodes.resize(kObjects);
  for (int o = 0; o < kObjects; ++o) {
    model.nodes[o].name = "object " + std::to_string(o);
    model.nodes[o].primitives.resize(kMaterials);
    for (int m = 0; m < kMaterials; ++m) model.nodes[o].primitives[m].material = m;
  }
  for (size_t t = 0; t < kMostTriangles && !in.atEnd(); ++t) {
    const auto tag = in.next<uint8_t>();
    auto& positions = model.nodes[tag % kObjects].primitives[tag / kObjects % kMaterials].positions;
    for (int corner = 0; corner < 3; ++corner) {
      engine::Vec3 p;
      for (int c = 0; c < 3; ++c) p[c] = grid ? in.next<int8_t>() / 4.0 : in.next<float>();
      positions.push_back(p);
    }
  }
  // Objects and primitives without triangles are left out, as an exporter would.
  engine::test::GltfModel kept;
  kept.materials = model.materials;
  for (engine::test::GltfNode& node : model.nodes) {
    std::erase_if(node.primitives, [](const engine::test::GltfPrimitive& p) { return p.positions.empty(); });
    if (node.primitives.empty()) continue;
    kept.roots.push_back(static_cast<int>(kept.nodes.size()));
    kept.nodes.push_back(std::move(node));
  }
  return kept;
}

void checkSceneText(std::string_view text) {
  const engine::Scene scene = engine::parseSceneFaces(text, "fuzz.json");
  for (const engine::Finding& f : engine::checkModel(scene)) engine::describeLocation(scene, f);
}

void checkSoup(const uint8_t* data, size_t size) {
  const std::string bytes = engine::test::glbBytes(soupModel(data, size));
  static const std::string file = (tempFolder() / "soup.glb").string();
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  const engine::Scene faces = engine::loadGltfFaces(file);
  for (const engine::Finding& f : engine::checkModel(faces)) engine::describeLocation(faces, f);
  expectMeshableSurfaces(engine::parseGltf(bytes, file));
}

}  // namespace

void fuzzOne(const uint8_t* data, size_t size) {
  try {
    if (size > 0 && data[0] == '{')
      checkSceneText(std::string_view(reinterpret_cast<const char*>(data), size));
    else
      checkSoup(data, size);
  } catch (const engine::SceneError&) {
    // Refused with its place: what bad input must get.
  }
}

}  // namespace fuzz::model_check

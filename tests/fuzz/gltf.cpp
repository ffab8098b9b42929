#include "tests/fuzz/fuzz_targets.h"

#include "engine/diagnostics.h"
#include "engine/io/gltf_loader.h"
#include "tests/fuzz/meshable.h"
#include "tests/fuzz/temp_folder.h"

#include <string_view>

namespace fuzz::gltf {

void fuzzOne(const uint8_t* data, size_t size) {
  // .gltf or .glb alike: the loader tells them by the bytes.
  static const std::string file = (tempFolder() / "model.gltf").string();
  try {
    expectMeshableSurfaces(engine::parseGltf(std::string_view(reinterpret_cast<const char*>(data), size), file));
  } catch (const engine::SceneError&) {
    // Refused with its place: what bad input must get.
  }
}

}  // namespace fuzz::gltf

#include "tests/fuzz/fuzz_targets.h"

#include "engine/diagnostics.h"
#include "engine/scene_loader.h"

#include <string_view>

namespace fuzz::scene_text {

void fuzzOne(const uint8_t* data, size_t size) {
  try {
    engine::parseScene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const engine::SceneError&) {
    // Refused with its place: what bad input must get.
  }
}

}  // namespace fuzz::scene_text

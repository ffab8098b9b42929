#include "tests/fuzz/fuzz_targets.h"

#include "engine/diagnostics.h"
#include "engine/io/polygon_case.h"

#include <string_view>

namespace fuzz::polygon_case {

void fuzzOne(const uint8_t* data, size_t size) {
  // Whatever the text holds: `walkrad mesh` reads a polygon case only when it has "outer" and no
  // "format", but the validation must refuse anything else as cleanly.
  const engine::JsonReader in("fuzz.json");
  try {
    engine::parsePolygonCase(in.parse(std::string_view(reinterpret_cast<const char*>(data), size)), in);
  } catch (const engine::SceneError&) {
    // Refused with its place: what bad input must get.
  }
}

}  // namespace fuzz::polygon_case

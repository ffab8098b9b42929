// The fuzz targets: one entry per loader or algorithm that takes what a stranger could send.
// Each fuzzOne() takes any bytes and returns normally when walkrad does what it promises:
// an input it accepts is processed (into what the next stage accepts), one it refuses is refused
// by the documented exception (engine::SceneError, and for the mesher std::invalid_argument),
// which fuzzOne catches.
// Anything else (a crash, a sanitizer report, another exception, a hang, memory without
// bound) is a finding. libfuzzer_main.cpp drives one of them under libFuzzer (the fuzz
// preset); regression_test.cpp replays every saved input through the same function with gtest.
#pragma once

#include <cstddef>
#include <cstdint>

namespace fuzz {

// Scene text (spec/scene-format.md) from bytes: parsed, validated and preprocessed (coplanar
// merging, contact cut-outs) as `walkrad render` does before meshing; every surface made must be
// a polygon the mesher accepts (meshable.h), as for the glTF and model-check targets.
namespace scene_text { void fuzzOne(const uint8_t* data, size_t size); }

// A glTF model, .gltf text or .glb bytes, imported as `walkrad render model.gltf` does. It is
// named as a file in an empty folder of its own, so a relative URI finds nothing beside it (and
// the loader refuses URIs that leave the model's folder once file access is confined).
namespace gltf { void fuzzOne(const uint8_t* data, size_t size); }

// A polygon case (`walkrad mesh case.json`): parsed and validated.
namespace polygon_case { void fuzzOne(const uint8_t* data, size_t size); }

// The mesher on a polygon with holes decoded from bytes (the layout is in mesh_polygon.cpp):
// most inputs are valid polygons; some are left unchecked, which the mesher must mesh or refuse.
namespace mesh_polygon { void fuzzOne(const uint8_t* data, size_t size); }

// The model check (`walkrad check`) on scene text (input starting with '{') or on a soup of
// triangles decoded from bytes and imported as a .glb model, which is also imported whole
// (coplanar triangles merged).
namespace model_check { void fuzzOne(const uint8_t* data, size_t size); }

// Every target by the name of its folders (corpus/NAME, regressions/NAME, known/NAME) and of its
// libFuzzer program (fuzz_NAME).
struct Target {
  const char* name;
  void (*fuzzOne)(const uint8_t* data, size_t size);
};
inline constexpr Target kTargets[] = {{"scene_text", scene_text::fuzzOne},
                                      {"gltf", gltf::fuzzOne},
                                      {"polygon_case", polygon_case::fuzzOne},
                                      {"mesh_polygon", mesh_polygon::fuzzOne},
                                      {"model_check", model_check::fuzzOne}};

}  // namespace fuzz

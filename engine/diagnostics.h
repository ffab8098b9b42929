// Every way a scene file (or a glTF model, the files it names, or its sidecar) can be refused, in one table, so tests check ids rather than wording.
#pragma once

#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace engine {

// X(id, what the user is told)
#define WALKRAD_SCENE_DIAGNOSTICS(X)                                                  \
  X(FileUnreadable, "cannot read the file")                                           \
  X(NotRegularFile, "not a regular file")                                             \
  X(FileTooLarge, "file larger than walkrad reads (1 GiB)")                           \
  X(NotJson, "not valid JSON")                                                        \
  X(WrongFormat, "unsupported format (expected \"walkrad-scene/1\")")               \
  X(MissingField, "missing required field")                                           \
  X(WrongType, "wrong type")                                                          \
  X(UnknownKey, "unknown key")                                                        \
  X(DuplicateKey, "key given twice in one object")                                    \
  X(NotFinite, "not a finite number")                                                 \
  X(OutOfRange, "value out of range")                                                 \
  X(UnknownUnits, "unknown units (use m, cm, mm, in or ft)")                          \
  X(UnknownAxis, "unknown axis (use x, y or z)")                                      \
  X(UnknownTaper, "unknown taper kind (use none, linear or radial)")                  \
  X(TooFewPoints, "fewer than 3 points")                                              \
  X(Degenerate, "degenerate polygon (repeated points or no area)")                    \
  X(NotConvex, "profile is not convex")                                               \
  X(SelfIntersecting, "polygon crosses itself")                                       \
  X(EmptySweep, "`from` must be less than `to`")                                      \
  X(UnknownMaterial, "unknown material")                                              \
  X(DuplicateName, "duplicate object name")                                           \
  X(UnknownFace, "no such face on this solid")                                        \
  X(HoleOutsideFace, "hole is not strictly inside its face")                          \
  X(HolesTouch, "holes touch or overlap")                                             \
  X(PatchTooSmall, "patch size too small for the scene (over 100000 patches per edge)") \
  X(MeshTooLarge, "mesh too large (over the mesher's limit: a patch size too small, or a polygon too thin)") \
  X(MeshTooFine, "detail finer than the coordinates resolve (points or edges a hair apart far from the origin)") \
  X(BadCamera, "camera looks nowhere (position equals look_at, or up is parallel to the view)") \
  X(NotGltf, "not a readable glTF 2.0 model")                                         \
  X(BadGltfReference, "glTF index refers to nothing")                                 \
  X(BadAccessor, "glTF accessor does not fit its buffer")                             \
  X(NodeLoop, "glTF node hierarchy loops or shares a node")                           \
  X(UriAbsolute, "glTF URI is an absolute path (only files in the model's folder are read)") \
  X(UriOutsideFolder, "glTF URI leads outside the model's folder")                    \
  X(WrongByteLength, "glTF buffer's data is not byteLength bytes long")               \
  X(NoTriangles, "the model has no triangles")                                        \
  X(UnknownNode, "no top-level node of that name in the model")                       \
  X(GltfOnly, "this option applies to glTF models only")                              \
  X(TooManyFaces, "the model makes more faces than walkrad takes (4,000,000)")

enum class Diag {
#define WALKRAD_DIAG_ID(id, text) id,
  WALKRAD_SCENE_DIAGNOSTICS(WALKRAD_DIAG_ID)
#undef WALKRAD_DIAG_ID
};

// The user-facing text of a diagnostic.
const char* describe(Diag diag);

// Test frameworks print a diagnostic by its text.
inline void PrintTo(Diag diag, std::ostream* out) { *out << describe(diag); }

// A scene refused: where (file and JSON path, or file:line:column for syntax) and why.
// what() is the one line to print: "FILE: PATH: problem: detail".
class SceneError : public std::runtime_error {
 public:
  SceneError(Diag diag, std::string file, std::string place, std::string detail = {});

  Diag diag() const { return diag_; }
  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }

 private:
  Diag diag_;
  std::string file_, place_;
};

// The place of a value in a JSON file, as a SceneError names it: child(path, "key") -> path.key
// (or path["key"] when key is not an identifier), child(path, 3) -> path[3].
std::string child(const std::string& path, std::string_view key);
std::string child(const std::string& path, size_t index);

}  // namespace engine

// Reading glTF 2.0 models (.gltf with its buffers, or .glb) with tinygltf into the same Scene a
// scene file gives, so meshing, lighting, the window and every subcommand take them unchanged.
//
// - Each top-level node of the model's scene is an object a user can select and drag (movable
//   unless the sidecar says otherwise), placed at the node's translation; its whole subtree's
//   triangles (node transforms applied; TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN primitives;
//   every index and vertex component type, normalised or not) belong to it. Points and lines are
//   left out.
// - Materials: baseColorFactor (times the mean of a base-colour texture, sRGB decoded) is the
//   reflectance, clamped to 0.95 so that closed rooms still converge; emissiveFactor times
//   KHR_materials_emissive_strength (times the sidecar's emission_scale) is the emitted
//   radiance. Triangles without a material get glTF's default (white, so 0.95). Faces are
//   one-sided, their front the counter-clockwise side: glTF's doubleSided is not honoured
//   (exporters set it on whole models, which would double every wall); the sidecar's
//   two_sided makes one material's triangles face both ways.
// - Perspective cameras become scene cameras (looking down the node's -z, up its +y).
// - Coplanar triangles of one object and material are merged into planar polygons with holes
//   (geometry/coplanar_merge.h), with the tolerance kMergeTolerance of the model's diagonal.
// - The sidecar (gltf_sidecar.h) sets units, patch size, emission and movability; without a
//   patch size the patch size is an eighth of the model's largest extent, as in scene files.
// Coordinates are the file's (glTF says metres; `units` says otherwise when an exporter wrote
// centimetres or inches).
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// What the command line may add to a model file.
struct LoadOptions {
  std::string units;    // the units of the model's coordinates (else the sidecar's, else m)
  std::string sidecar;  // this sidecar instead of MODEL.walkrad.json beside the model
};

// Whether a path names a glTF model (.gltf or .glb, any case).
bool isGltfPath(const std::string& path);

// Reads and imports a model and its sidecar (options.sidecar, else MODEL.walkrad.json when it
// exists). Throws SceneError naming the file (model or sidecar) and what is wrong: unreadable,
// not glTF, an index or accessor out of range, a node hierarchy that loops, no triangles.
Scene loadGltf(const std::string& path, const LoadOptions& options = {});

// The same for a model's bytes already in memory (.gltf text or .glb); external buffers are
// looked for beside `file`.
Scene parseGltf(std::string_view bytes, const std::string& file, const LoadOptions& options = {});

// The model as the file describes it, for checks (walkrad check): one surface per triangle, in
// the file's order ("triangle N" of its node), degenerate ones included; no merging, no sky,
// no contact cut-outs.
Scene loadGltfFaces(const std::string& path, const LoadOptions& options = {});

}  // namespace engine

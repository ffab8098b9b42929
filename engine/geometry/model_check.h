// Checks of a model as it was described (thesis 3.1 and 3.3: what goes wrong in models built
// for display rather than for lighting): faces without area, faces given twice, coincident
// faces, faces crossing each other, solids with inconsistent orientation or holes in their
// skin, and one-sided walls whose backs can be seen. Each finding says where it is and what
// walkrad does about it, so a modeller knows what to fix.
#pragma once

#include "engine/scene.h"

#include <ostream>
#include <string>
#include <vector>

namespace engine {

// X(id, severity, name printed, what walkrad does about it). Errors make the lighting wrong,
// warnings may, notes are worth a look.
#define WALKRAD_MODEL_FINDINGS(X)                                                                          \
  X(DegenerateFace, Error, "degenerate face",                                                           \
    "refuses a scene file that has one (exit 2 when loading); leaves a glTF model's out; delete it in the modeller")               \
  X(DuplicateFace, Error, "duplicate face",                                                             \
    "nothing: both are meshed, both are lit and they z-fight on screen; delete one in the modeller")     \
  X(CoincidentFaces, Warning, "coincident faces",                                                       \
    "nothing: both are meshed, lit as if the other were not there, and z-fight on screen")              \
  X(BackToBackFaces, Note, "back-to-back faces",                                                        \
    "nothing: both are meshed and take part in the solve; fine where they are hidden (solids stacked)")  \
  X(Interpenetration, Warning, "interpenetrating faces",                                                \
    "nothing: each is meshed across the other, so light leaks along the crossing; split them in the modeller") \
  X(InconsistentOrientation, Error, "inconsistent orientation",                                         \
    "nothing: one of the two faces points into its solid, so from outside its back shows (not drawn, absorbing all light); flip it in the modeller") \
  X(OpenEdge, Warning, "open edges",                                                                     \
    "nothing: light passes through the opening; close it unless it is meant (an open window)")           \
  X(Facade, Warning, "back seen",                                                                        \
    "nothing: the back absorbs all light and is not drawn (see-through); give the wall thickness or a second face")

enum class FindingKind {
#define WALKRAD_FINDING_ID(id, severity, name, action) id,
  WALKRAD_MODEL_FINDINGS(WALKRAD_FINDING_ID)
#undef WALKRAD_FINDING_ID
};
enum class Severity { Error, Warning, Note };

constexpr size_t kFindingKinds = static_cast<size_t>(FindingKind::Facade) + 1;

const char* idOf(FindingKind kind);       // "DuplicateFace": stable, for scripts
const char* nameOf(FindingKind kind);     // "duplicate face"
const char* actionOf(FindingKind kind);   // what walkrad does about it
const char* nameOf(Severity severity);    // "error", "warning", "note"
Severity severityOf(FindingKind kind);

// Test frameworks print a finding kind by its name.
inline void PrintTo(FindingKind kind, std::ostream* out) { *out << nameOf(kind); }

struct Finding {
  FindingKind kind;
  uint32_t surface = 0;        // index into the checked Scene::surfaces
  int64_t other = -1;          // the other face involved, when there is one
  Vec3 point{0};               // a point of the problem, world coordinates
  std::string message;         // the specifics: which faces, how much
};

struct ModelCheckSettings {
  // Distances below this are zero (scene units); 0: 1e-6 of the scene's extent.
  double tolerance = 0;
  // An object counts as a solid (so its open edges are reported) when at least this share of its
  // edge length is closed: used by an even number of its faces, T-junctions resolved.
  double closedShare = 0.5;
};

// What a check did, counted where it is done, so tests can hold its cost to the model's size
// without a clock. A bounds test compares two boxes (of a tree node, face, triangle or point).
struct ModelCheckWork {
  uint64_t pairBoundsTests = 0;  // looking for the pairs of faces whose bounds overlap
  uint64_t pairsChecked = 0;     // those pairs, each checked for overlap or crossing
  uint64_t edgeBoundsTests = 0;  // looking for vertices on open edges (T-junctions)
  uint64_t rays = 0;             // cast from the faces' backs
  uint64_t rayBoundsTests = 0;   // by those rays (a triangle reached counts one)
};

// Checks `scene`'s surfaces as loadSceneFaces gives them (one per face: before coplanar merging,
// which would hide duplicates and join faces) and returns the findings, errors first, then
// warnings, then notes, each by surface, kind and the other face involved. Bounding volume
// hierarchies over the faces, their triangles and their open edges' vertices keep the work
// near-linear in the number of faces however they are spread; `work`, when given, receives the
// counts.
std::vector<Finding> checkModel(const Scene& scene, const ModelCheckSettings& settings = {}, ModelCheckWork* work = nullptr);

// "objects[2].solids[0] (desk, top) at (1.5, 0.75, 2)": where a finding is, for messages.
std::string describeLocation(const Scene& scene, const Finding& finding);

}  // namespace engine

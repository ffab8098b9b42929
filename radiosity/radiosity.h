// walkrad's radiosity solver: progressive-refinement shooting (Cohen, Chen, Wallace, Greenberg
// 1988; thesis chapter 2) over meshed planar surfaces, with point-to-polygon form factors from
// the emulated Pixel-Planes 5 (pxpl5/hemisphere.h). Plain data in, plain data out; no GL.
//
// Units. Everything is radiance (W sr^-1 m^-2 in the scene's units), in and out: emission is the
// outgoing radiance of a Lambertian emitter, results are outgoing radiance. For Lambertian
// surfaces exitance (radiosity in the thesis' sense) is pi x radiance, and the radiosity
// equation B_i = E_i + rho_i sum_j F_ij B_j is linear, so it holds for radiance unchanged. Power
// is where the pi appears: a patch of area A and radiance L emits pi L A. Energy figures below
// (Stats) are powers in those units, per colour channel.
//
// Elements and patches (substructuring, Cohen et al. 1986). Elements receive light and carry
// the displayed radiance; shooting patches are groups of elements of one surface that shoot
// their unshot light together from one hemisphere frame. Which elements form a patch is decided
// outside (groupIntoPatches below, or the quadtree's parents); by default every element is its
// own patch. The solver splits a patch whose centre turns out to be inside a solid (see
// solver.cpp), so the patch count can grow while solving.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace radiosity {

constexpr uint32_t kNone = 0xffffffffu;

// One planar surface, meshed. Vertices are shared by the elements of this surface only.
struct Surface {
  std::vector<glm::dvec3> vertices;                // world coordinates
  std::vector<std::array<uint32_t, 4>> elements;   // convex, corner indices into `vertices`,
                                                   // counter-clockwise seen from the front;
                                                   // triangles have [3] == kNone
  glm::dvec3 normal{0, 0, 1};                      // unit, toward the front (reflects and emits)
  glm::dvec3 reflectance{0.5};                     // diffuse albedo per channel, 0..1
  glm::dvec3 emission{0};                          // emitted radiance per channel, >= 0
  // Optional substructuring: per element, its shooting patch (0-based, local to this surface,
  // every index below the largest used). Empty: each element shoots on its own.
  std::vector<uint32_t> patchOfElement;
  // Per element, its key: unique within the surface and the same for as long as the element
  // lives, so that an edit (Solver::edit) knows which elements go on. Empty: each element's index.
  std::vector<uint64_t> keys;
};

// A surface of an edit (Solver::edit): `now` replaces surface `surface`. An element before
// whose key is among now's goes on as that element (it keeps its light; it moved when its own
// corners differ); keys that went are elements removed, new keys elements added.
struct SurfaceChange {
  uint32_t surface = 0;
  Surface now;
  // Meshed anew rather than changed element by element: none of its elements goes on, whatever
  // the keys say (a new mesh numbers its elements afresh).
  bool meshedAnew = false;
};

// Groups a surface's elements into shooting patches of about `patchEdge` across: the element
// centroids are binned into squares of that size in the surface's plane, in order of first
// appearance, so the result is deterministic. Returns Surface::patchOfElement.
std::vector<uint32_t> groupIntoPatches(const Surface& surface, double patchEdge);

struct SolverSettings {
  int resolution = 256;        // hemisphere pixels across (pxpl5; even, >= 8)
  int graphicsProcessors = 1;  // pxpl5 worker threads; results do not depend on it
  // Receivers whose bounding sphere comes closer to the shooter's centre than this many shooter
  // radii are near-field: their form factor is integrated over the shooter's area instead of
  // taken from its centre. The point approximation's error falls as (radius / distance)^2: about
  // 20% for two unit squares a unit apart (1.4 radii), about 1% at 6 radii.
  double nearFieldRatio = 8;
  // In that integral clusters of the shooter's elements farther from the receiver than
  // `pieceRatio` times their radius count by four points; closer ones by their parts, down to
  // the elements, which are split in four while a piece's radius exceeds its distance to the
  // receiver over `pieceRatio`, at most `maxShooterSplits` times, and each piece is integrated
  // by a Gauss rule (error falling as the fourth power of its size).
  double pieceRatio = 3;
  int maxShooterSplits = 3;
  // Receivers whose form factor is below this many hemisphere pixels are too small for the item
  // buffer (a pixel is either theirs or not): their factor is computed analytically.
  double smallReceiverPixels = 128;
  // Overshooting (radiosity/overshoot.h): a patch also shoots, ahead of time, the light it will
  // reflect of the unshot light it sees, and is left with as much negative unshot light. About
  // 40% fewer shots to 1% on the shipped scenes. Off by default because the negative light makes
  // unshotFraction() (a sum of magnitudes) larger than the ledgers' signed unshot term
  // (unshotPower()) until it is filled; the application turns it on.
  bool overshoot = false;
  // After an edit, a patch that did not change corrects its light in the window of its
  // hemisphere where the changed elements are seen (Solver::edit): about the cost of what
  // changed. Off: every correction takes back and sends again all of the patch's light.
  bool windowedCorrections = true;
  // A patch shoots from the same point over the same geometry every time, so its first shot's
  // frame (pixel factors) and the judgement of its near and small receivers (visibilities,
  // analytic factors, the plans of the near receivers' integrals with their elements' factors)
  // are kept and reused when it shoots again; only the weighing of the near receivers' integrals
  // by its elements' unshot light, and the factors from the points that stand for clusters of
  // them, are done again. Results are the same bit for bit. Kept for the patches that shoot first
  // until this many bytes are held; 0 keeps none.
  size_t shotCacheBytes = size_t{256} << 20;
  // Of those, only a shot of at most this many bytes is kept. On a room the largest take under
  // 2 MB (the kitchen's 1.6 MB, the office's 0.7 MB), and thousands fit in the budget; on a
  // building every shot sees most of the elements (the White Room's take about 9.5 MB), so the
  // budget held a few dozen patches' shots, worth little to an edit that corrects hundreds.
  size_t shotCacheRecordBytes = size_t{4} << 20;
  // A shot's receivers are judged in chunks whose storage is kept for the next shot; beyond this
  // many bytes in all, a chunk's storage that a shot left more than half spare is freed instead.
  // Different shots fill different chunks, so without a bound they come to hold the sum of each
  // chunk's largest (three times a shot's on a building after 34 shots, and growing).
  size_t scratchBytes = size_t{64} << 20;
};

// Counters since construction. Powers are per channel (see the units above).
struct Stats {
  uint64_t shots = 0;
  uint64_t frames = 0;             // hemisphere frames rendered
  uint64_t reusedShots = 0;        // shots that reused their patch's kept frame and judgement
  uint64_t nearReceivers = 0;      // receiver factors integrated over the shooter's area
  uint64_t smallReceivers = 0;     // receiver factors computed analytically for their size
  uint64_t splitPatches = 0;       // patches of several elements whose centre was inside a solid,
                                   // split in parts (see solver.cpp)
  uint64_t movedShooters = 0;      // one-element patches whose centre was inside a solid
  uint64_t renormalisedShots = 0;  // shots whose corrections were too big for the rest to absorb
  uint64_t corrections = 0;        // patches whose light was taken back after an edit (Solver::edit)
  uint64_t windowedCorrections = 0;  // of those, corrected in a window of their hemisphere only
  uint64_t editedSurfaces = 0;     // surfaces that edits replaced (Solver::edit)
  uint64_t patchTrees = 0;         // patches' element trees built (near field): as patches are set
                                   // up, by edits for the surfaces they replace, and as patches
                                   // first shoot
  uint64_t scratchBytes = 0;       // not a count: what the receivers' scratch holds after the
                                   // last shot for the next (SolverSettings::scratchBytes)
  double seconds = 0;              // wall time spent in step()
  glm::dvec3 emittedPower{0};      // pi x sum of emission x area
  glm::dvec3 absorbedPower{0};     // absorbed by the front of elements, (1 - rho) of what arrives
  glm::dvec3 backPower{0};         // arrived at the back of an element: one-sided, lost
  glm::dvec3 escapedPower{0};      // left the scene (hemisphere pixels that saw nothing)
  // The light edits took out with the elements they removed (their unshot light and what the
  // corrections took back from them, less the emission their successors start with), so that
  // emitted = absorbed + back + escaped + unshot + removed at every step.
  glm::dvec3 removedPower{0};
};

struct Shooter {
  uint32_t patch = 0;              // global patch index
  uint32_t surface = 0;
  glm::dvec3 unshotPower{0};       // pi x unshot radiance x patch area
};

class Solver {
 public:
  // Copies the surfaces' geometry and materials; each element starts at its emission, each
  // patch's unshot radiance is its emission. Throws std::invalid_argument for an element with
  // a corner index outside its surface's vertices, fewer than 3 corners, zero area, a patch
  // grouping or keys of the wrong size, or a key given twice in a surface; and what
  // pxpl5::HemisphereRenderer throws for the settings.
  Solver(std::span<const Surface> surfaces, const SolverSettings& settings = {});
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  // The patch with the largest unshot power (sum of channels; ties go to the lowest index), or
  // nothing when no patch has any.
  std::optional<Shooter> nextShooter() const;

  // Shoots nextShooter()'s unshot light (when that patch is split on its first shot, the next
  // shooter after the split's): a hemisphere frame at the patch's centre over every element,
  // near and small receivers corrected (see solver.cpp), and the reflected part deposited as
  // radiance on each receiver and as unshot light on its patch. Returns false and does nothing
  // when there is nothing left to shoot. Throws only what runs out (memory,
  // threads); the solver is then half-way through a shot and must be thrown away.
  bool step();

  // Unshot power over emitted power, each patch's channels counted by magnitude (some light is
  // negative after an edit or with overshooting); 0 for a scene that emits nothing. Take-backs
  // still pending after an edit are not light yet: only a bound of what they will move is known
  // before they are done (several times the emitted power after a desk moves in the office).
  double unshotFraction() const;
  // Nothing left to take back, and the unshot fraction at most `fraction`.
  bool converged(double fraction) const { return pendingCorrections() == 0 && unshotFraction() <= fraction; }
  // The unshot power per channel, signed (after an edit some light is negative), without the
  // corrections still pending: the term of the power ledgers (Stats).
  glm::dvec3 unshotPower() const;
  // How far the power ledgers (Stats) are from closing: |emitted - absorbed - back - escaped -
  // removed - unshotPower()| over emitted, channels summed. Rounding only (below 1e-9) after
  // every step; 0 for a scene that emits nothing.
  double ledgerResidual() const;

  // Steps until converged(fraction) or `maxShots` shots in this call. Returns the shots taken.
  uint64_t solve(double fraction, uint64_t maxShots = UINT64_MAX);

  // Per element of `surface`, its radiance so far (light shot to it plus its emission), without
  // the ambient term.
  std::span<const glm::dvec3> elementRadiance(uint32_t surface) const;

  // The ambient term (radiosity/ambient.h) of the light not yet shot.
  glm::dvec3 ambient() const;

  // Per vertex of `surface`: the area-weighted mean radiance of the elements of that surface
  // around it (thesis 2.4), so Gouraud shading is continuous within a surface, plus reflectance x
  // `ambient` (ambient() for the display's estimate before convergence, computed once for many
  // surfaces: it looks at every patch; 0 for the radiance alone). Vertices used by no element
  // get 0.
  std::vector<glm::dvec3> vertexRadiance(uint32_t surface, const glm::dvec3& ambient) const;

  // An edit of the scene (objects moved, surfaces meshed again or refined): each change replaces
  // its surface; the surfaces it names none of keep everything. Elements that go on (by their
  // keys, SurfaceChange) keep their light; new ones start from their emission. Nothing is
  // restarted (after Chen 1990, "Incremental radiosity"): every patch
  // that has shot and may see what changed has its light taken back along the old geometry's
  // factors exactly as its shots sent it (negative light where it fell), and sent again at once
  // along the new geometry's, so the difference is what moves and a move and the move back leave
  // nothing behind. A patch that did not change makes its new frame from its kept one and the
  // part of its hemisphere where the changed elements are seen
  // (SolverSettings::windowedCorrections). Take-backs
  // come first in step(), the most powerful first; until done, the solver has not converged.
  // Take-backs left from an earlier edit
  // are done first (here). Throws std::invalid_argument (and changes nothing) for a surface that
  // does not exist or is named twice, or as the constructor does.
  void edit(std::span<const SurfaceChange> changes);
  // Take-backs still pending after the last edit.
  size_t pendingCorrections() const;
  // The power of the take-backs still pending over that of all the last edit's (0 when none):
  // the most powerful come first, so the light is about right again long before it reaches 0.
  double pendingCorrectionShare() const;

  const Stats& stats() const;
  size_t surfaceCount() const;
  size_t elementCount() const;
  size_t patchCount() const;
  size_t vertexCount() const;  // of all surfaces: their vertexRadiance's lengths summed

 private:
  struct State;
  struct Edit;
  // One correction (edit()): the next pending patch's light taken back and sent again; false
  // when none is pending.
  bool correct();
  // For patch p (of the geometry before the edit) when it did not change: its frame now, made
  // from its kept frame before and what a window of its hemisphere sees, kept for its patch now,
  // so that sending its light again renders no frame; false (and nothing done) otherwise. It
  // finds the next pending patch's window beside p's (solver.cpp).
  bool frameInWindow(uint32_t p);
  // Patch p's light taken back along the geometry before, as its shots sent it.
  void takeBack(uint32_t p);
  // Patch p's light sent again from its elements along the geometry now.
  void sendAgain(uint32_t p);
  std::unique_ptr<State> state_;
  std::unique_ptr<Edit> edit_;
};

}  // namespace radiosity

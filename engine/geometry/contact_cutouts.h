// Contact cut-outs, beyond the thesis (3.2, figure 3.5: light leaking from under a box on a
// floor): where a face of one object rests on a surface of another (in its plane, facing it,
// inside it), the covered part of the supporting surface is cut out as a hole. No light is then
// computed under furniture, and no element of the floor straddles a box's footprint, half lit
// and half dark.
#pragma once

#include "engine/scene.h"

#include <cstdint>
#include <functional>
#include <map>
#include <tuple>
#include <vector>

namespace engine {

// Cuts every face that rests on another object's surface out of that surface as a hole, when it
// lies strictly inside the surface's outline and apart from its holes (`tolerance`, scene
// units, decides coplanar and apart). A footprint that reaches the surface's edge or another
// hole is left as it is: the light under it is computed as before. The footprints follow a
// surface's own holes and are counted in Surface::contactHoles. Returns the holes cut.
size_t cutOutContacts(std::vector<Surface>& surfaces, double tolerance);

// The scene's surfaces filed by their planes and bounds, so that the cut-outs of one surface are
// found from the few faces that may rest on it, and a move re-cuts only the surfaces it concerns:
// those the moved faces rest on before and after, and the moved surfaces themselves.
class ContactIndex {
 public:
  // The unit normal to 1e-6 and the plane offset to a grid of 1e3 tolerances.
  using Key = std::tuple<int64_t, int64_t, int64_t, int64_t>;

  // Files `surfaces` (without cut-outs) by their planes.
  ContactIndex(const std::vector<Surface>& surfaces, double tolerance);
  // Surface `surface` moved from `before` to `after` (its outlines without cut-outs).
  void move(uint32_t surface, const Surface& before, const Surface& after);
  // Appends the surfaces in whose planes (to a grid cell) `face` may rest.
  void supportsUnder(const Surface& face, std::vector<uint32_t>& out) const;
  // Surface `support` with its cut-outs, as cutOutContacts makes them: a hole for each face of
  // another object that rests on it and fits, in the order of the surfaces. `uncut(i)` gives
  // surface i without cut-outs where it stands.
  Surface cut(uint32_t support, const std::function<const Surface&(uint32_t)>& uncut) const;

 private:
  struct Bounds {
    Vec3 lo, hi;
  };
  static Bounds boundsOf(const Surface& surface);
  bool near(const Bounds& a, const Bounds& b) const;  // within the tolerance of meeting
  Key asSupport(const Surface& surface, int64_t shift = 0) const;
  Key asFace(const Surface& surface) const;
  void file(uint32_t surface, const Surface& where);
  void unfile(uint32_t surface, const Surface& where);

  double tolerance_, cell_;
  std::vector<Bounds> bounds_;  // per surface, of its outline
  std::map<Key, std::vector<uint32_t>> supports_;  // by the surface's own plane
  std::map<Key, std::vector<uint32_t>> faces_;     // by the plane it would rest on
};

// Takes every footprint cutOutContacts cut back out of the surfaces (before cutting anew when
// objects moved).
void removeContacts(std::vector<Surface>& surfaces);

// The tolerance the loader cuts with: 1e-6 of the scene's extent.
double contactTolerance(const Scene& scene);

}  // namespace engine

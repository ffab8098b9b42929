// Contact cut-outs, beyond the thesis (3.2, figure 3.5: light leaking from under a box on a
// floor): where a face of one object rests on a surface of another (in its plane, facing it,
// inside it), the covered part of the supporting surface is cut out as a hole. No light is then
// computed under furniture, and no element of the floor straddles a box's footprint, half lit
// and half dark.
#pragma once

#include "engine/scene.h"

#include <vector>

namespace engine {

// Cuts every face that rests on another object's surface out of that surface as a hole, when it
// lies strictly inside the surface's outline and apart from its holes (`tolerance`, scene
// units, decides coplanar and apart). A footprint that reaches the surface's edge or another
// hole is left as it is: the light under it is computed as before. The footprints follow a
// surface's own holes and are counted in Surface::contactHoles. Returns the holes cut.
size_t cutOutContacts(std::vector<Surface>& surfaces, double tolerance);

// Takes every footprint cutOutContacts cut back out of the surfaces (before cutting anew when
// objects moved).
void removeContacts(std::vector<Surface>& surfaces);

// The tolerance the loader cuts with: 1e-6 of the scene's extent.
double contactTolerance(const Scene& scene);

}  // namespace engine

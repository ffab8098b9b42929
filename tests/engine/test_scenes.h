// Small scenes and measurements shared by the engine tests.
#pragma once

#include "engine/io/json_reader.h"
#include "engine/scene.h"

#include <string>

namespace engine::test {

// A valid scene: a 4 x 2.5 x 3 m inward room ("room") with a filled hole in its ceiling, and a
// 1 x 1 x 1 m box ("box") on the floor. Tests break one thing at a time.
Json baseScene();

// A scene with one object "thing" holding one solid; `solid` is that solid's JSON.
Json sceneWithSolid(const Json& solid);

Scene parse(const Json& scene);

// The surface of `object` whose face name is `face`; fails the test when there is none.
const Surface& surfaceOf(const Scene& scene, const std::string& object, const std::string& face);

Vec3 centroidOf(const Surface& surface);

// Signed volume enclosed by an object's surfaces (divergence theorem): positive when every
// normal points out of a closed solid, negative when every normal points in.
double enclosedVolume(const Scene& scene, const std::string& object);

// Sum of normal x area over an object's surfaces: zero for a closed surface.
Vec3 netArea(const Scene& scene, const std::string& object);

}  // namespace engine::test

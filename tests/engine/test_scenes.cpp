#include "tests/engine/test_scenes.h"

#include "engine/io/scene_loader.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace engine::test {

Json baseScene() {
  return Json::parse(R"({
    "format": "walkrad-scene/1",
    "units": "m",
    "settings": { "patch_size": 0.5 },
    "materials": {
      "white": { "reflectance": [0.5, 0.5, 0.5] },
      "lamp": { "reflectance": [0.5, 0.5, 0.5], "emission": [4, 4, 4] }
    },
    "objects": [
      { "name": "room", "movable": false,
        "solids": [ { "profile": [[0, 0], [4, 0], [4, 3], [0, 3]], "axis": "y", "from": 0, "to": 2.5,
                      "inward": true, "material": "white",
                      "faces": { "top": { "holes": [ { "polygon": [[1, 1], [2, 1], [2, 2], [1, 2]], "fill": "lamp" } ] } } } ] },
      { "name": "box",
        "solids": [ { "profile": [[1, 1], [2, 1], [2, 2], [1, 2]], "from": 0, "to": 1, "material": "white" } ] }
    ],
    "cameras": { "default": { "position": [0.5, 1.6, 0.5], "look_at": [3, 1, 2.5] } }
  })");
}

Json sceneWithSolid(const Json& solid) {
  Json scene = baseScene();
  scene["objects"] = Json::array();
  scene["objects"].push_back({{"name", "thing"}, {"solids", Json::array({solid})}});
  return scene;
}

Scene parse(const Json& scene) { return parseScene(scene.dump(), "test.json"); }

const Surface& surfaceOf(const Scene& scene, const std::string& object, const std::string& face) {
  for (const Surface& s : scene.surfaces)
    if (scene.objects[s.object].name == object && s.face == face) return s;
  ADD_FAILURE() << "no surface " << face << " on " << object;
  static const Surface none;
  return none;
}

Vec3 centroidOf(const Surface& surface) {
  Vec3 sum{0};
  for (const Vec3& p : surface.outer) sum += p;
  return sum / static_cast<double>(surface.outer.size());
}

double enclosedVolume(const Scene& scene, const std::string& object) {
  double volume = 0;
  for (const Surface& s : scene.surfaces)
    if (scene.objects[s.object].name == object) volume += glm::dot(s.outer.front(), s.normal) * s.area / 3;
  return volume;
}

Vec3 netArea(const Scene& scene, const std::string& object) {
  Vec3 sum{0};
  for (const Surface& s : scene.surfaces)
    if (scene.objects[s.object].name == object) sum += s.normal * s.area;
  return sum;
}

}  // namespace engine::test

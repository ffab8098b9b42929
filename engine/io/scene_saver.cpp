#include "engine/io/scene_saver.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace engine {

std::string sceneTextWithPoses(std::string_view text, const Scene& scene) {
  nlohmann::ordered_json root = nlohmann::ordered_json::parse(text);
  nlohmann::ordered_json& objects = root.at("objects");
  if (objects.size() != scene.objects.size())
    throw std::invalid_argument(scene.file + ": the text has " + std::to_string(objects.size()) + " objects, the scene " +
                                std::to_string(scene.objects.size()));
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    nlohmann::ordered_json& out = objects[i];
    // Poses the file already states are left in its own spelling (0, not 0.0).
    const nlohmann::ordered_json position = {o.position.x, o.position.y, o.position.z};
    const nlohmann::ordered_json filePosition = out.value("position", nlohmann::ordered_json::array({0, 0, 0}));
    if (filePosition != position) out["position"] = position;
    if (out.value("rotate_y", 0.0) != o.rotateYDeg) out["rotate_y"] = o.rotateYDeg;
  }
  return root.dump(2) + "\n";
}

}  // namespace engine

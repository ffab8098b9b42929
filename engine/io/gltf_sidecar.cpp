#include "engine/io/gltf_sidecar.h"

#include "engine/io/json_reader.h"
#include "engine/io/load_limits.h"

#include <filesystem>

namespace engine {

std::string sidecarPathFor(const std::string& model) {
  std::filesystem::path path(model);
  path.replace_extension(".walkrad.json");
  return path.string();
}

GltfSidecar parseGltfSidecar(std::string_view text, const std::string& file) {
  const JsonReader in(file);
  const Json root = in.parse(text);
  in.expectObject(root, "");
  in.allowOnly(root, "", {"units", "patch_size", "emission_scale", "movable", "materials", "objects", "sky"});
  GltfSidecar sidecar;
  if (const auto v = root.find("units"); v != root.end()) {
    sidecar.units = in.string(*v, "units");
    if (metersPerUnit(sidecar.units) == 0) in.fail(Diag::UnknownUnits, "units", "\"" + sidecar.units + "\"");
  }
  if (const auto v = root.find("patch_size"); v != root.end()) {
    sidecar.patchSize = in.number(*v, "patch_size", 0, kMaxLength);
    if (*sidecar.patchSize <= 0) in.fail(Diag::OutOfRange, "patch_size", "must be greater than 0");
  }
  if (const auto v = root.find("emission_scale"); v != root.end())
    sidecar.emissionScale = in.number(*v, "emission_scale", 0, kMaxEmission);
  if (const auto v = root.find("movable"); v != root.end()) sidecar.movable = in.boolean(*v, "movable");
  if (const auto v = root.find("materials"); v != root.end()) {
    in.expectObject(*v, "materials");
    for (const auto& item : v->items()) {
      const std::string path = child("materials", item.key());
      in.expectObject(item.value(), path);
      in.allowOnly(item.value(), path, {"reflectance", "emission", "omit", "two_sided"});
      MaterialOverride& m = sidecar.materials[item.key()];
      if (const auto r = item.value().find("reflectance"); r != item.value().end())
        m.reflectance = in.vec3(*r, child(path, "reflectance"), 0, 1);
      if (const auto e = item.value().find("emission"); e != item.value().end())
        m.emission = in.vec3(*e, child(path, "emission"), 0, kMaxEmission);
      if (const auto o = item.value().find("omit"); o != item.value().end()) m.omit = in.boolean(*o, child(path, "omit"));
      if (const auto t = item.value().find("two_sided"); t != item.value().end())
        m.twoSided = in.boolean(*t, child(path, "two_sided"));
    }
  }
  if (const auto v = root.find("objects"); v != root.end()) {
    in.expectObject(*v, "objects");
    for (const auto& item : v->items()) {
      const std::string path = child("objects", item.key());
      in.expectObject(item.value(), path);
      in.allowOnly(item.value(), path, {"movable"});
      sidecar.movableObjects[item.key()] = in.boolean(in.required(item.value(), path, "movable"), child(path, "movable"));
    }
  }
  if (const auto v = root.find("sky"); v != root.end()) {
    in.expectObject(*v, "sky");
    in.allowOnly(*v, "sky", {"emission"});
    sidecar.sky = in.vec3(in.required(*v, "sky", "emission"), "sky.emission", 0, kMaxEmission);
  }
  return sidecar;
}

}  // namespace engine

#include "engine/io/scene_loader.h"

#include "engine/diagnostics.h"
#include "engine/geometry/contact_cutouts.h"
#include "engine/geometry/coplanar_merge.h"
#include "engine/geometry/solid_surfaces.h"
#include "engine/io/json_reader.h"
#include "engine/io/load_limits.h"
#include "mesher/polygon.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace engine {

namespace {

// Further limits that make a value absurd rather than merely unusual (see load_limits.h).
constexpr double kMinLength = 1e-9;   // shorter edges and sweeps are degenerate, in scene units
constexpr int kMaxSlices = 256;
constexpr size_t kMaxPolygonPoints = 1024;  // per profile or hole
constexpr size_t kMaxHolesPerFace = 256;    // the display's hole bridging is quadratic in points

// The triangles fanned from the first point, each counted positive: a convex ring's area, and
// zero only when every point lies on one line (a bowtie's signed area is zero too).
double fanArea(const mesher::Ring2& ring) {
  double twice = 0;
  for (size_t i = 1; i + 1 < ring.size(); ++i) twice += std::abs(mesher::orient2(ring[0], ring[i], ring[i + 1]));
  return twice / 2;
}

class SceneParser {
 public:
  SceneParser(const JsonReader& in, Scene& scene) : in_(in), scene_(scene) {}

  void parse(const Json& root) {
    in_.expectObject(root, "");
    in_.allowOnly(root, "", {"format", "units", "settings", "materials", "objects", "cameras"});
    const std::string format = in_.string(in_.required(root, "", "format"), "format");
    if (format != "walkrad-scene/1") in_.fail(Diag::WrongFormat, "format", "\"" + format + "\"");

    if (const auto units = root.find("units"); units != root.end()) {
      scene_.units = in_.string(*units, "units");
      scene_.metersPerUnit = metersPerUnit(scene_.units);
      if (scene_.metersPerUnit == 0) in_.fail(Diag::UnknownUnits, "units", "\"" + scene_.units + "\"");
    }
    if (const auto settings = root.find("settings"); settings != root.end()) {
      in_.expectObject(*settings, "settings");
      in_.allowOnly(*settings, "settings", {"patch_size", "adaptive"});
      if (const auto size = settings->find("patch_size"); size != settings->end())
        scene_.patchSize = patchSize(*size, "settings.patch_size");
      if (const auto adaptive = settings->find("adaptive"); adaptive != settings->end()) parseAdaptive(*adaptive);
    }
    parseMaterials(in_.required(root, "", "materials"));
    parseObjects(in_.required(root, "", "objects"));
    if (const auto cameras = root.find("cameras"); cameras != root.end()) parseCameras(*cameras);
  }

 private:
  // settings.adaptive: {"threshold": relative jump that refines, (0, 10]; "min_element_size":
  // the narrowest refined element in scene units, 0 for a quarter of each surface's patch size}.
  void parseAdaptive(const Json& value) {
    in_.expectObject(value, "settings.adaptive");
    in_.allowOnly(value, "settings.adaptive", {"threshold", "min_element_size"});
    AdaptiveSettings& adaptive = scene_.adaptive.emplace();
    if (const auto threshold = value.find("threshold"); threshold != value.end()) {
      adaptive.threshold = in_.number(*threshold, "settings.adaptive.threshold", 0, 10);
      if (adaptive.threshold <= 0) in_.fail(Diag::OutOfRange, "settings.adaptive.threshold", "must be greater than 0");
    }
    if (const auto size = value.find("min_element_size"); size != value.end())
      adaptive.minElementSize = in_.number(*size, "settings.adaptive.min_element_size", 0, kMaxLength);
  }

  double patchSize(const Json& value, const std::string& path) const {
    const double size = in_.number(value, path, 0, kMaxLength);
    if (size <= 0) in_.fail(Diag::OutOfRange, path, "must be greater than 0");
    return size;
  }

  uint32_t materialRef(const Json& value, const std::string& path) const {
    const std::string name = in_.string(value, path);
    const auto& m = scene_.materials;
    const auto found = std::find_if(m.begin(), m.end(), [&](const Material& x) { return x.name == name; });
    if (found == m.end()) in_.fail(Diag::UnknownMaterial, path, "\"" + name + "\"");
    return static_cast<uint32_t>(found - m.begin());
  }

  void parseMaterials(const Json& materials) {
    in_.expectObject(materials, "materials");
    for (const auto& item : materials.items()) {
      const std::string path = child("materials", item.key());
      const Json& m = item.value();
      in_.expectObject(m, path);
      in_.allowOnly(m, path, {"reflectance", "emission"});
      Material material;
      material.name = item.key();
      material.reflectance = in_.vec3(in_.required(m, path, "reflectance"), child(path, "reflectance"), 0, 1);
      if (const auto e = m.find("emission"); e != m.end())
        material.emission = in_.vec3(*e, child(path, "emission"), 0, kMaxEmission);
      scene_.materials.push_back(std::move(material));
    }
  }

  void parseObjects(const Json& objects) {
    in_.expectArray(objects, "objects");
    std::set<std::string> names;
    for (size_t i = 0; i < objects.size(); ++i) {
      const std::string path = child("objects", i);
      const Json& o = objects[i];
      in_.expectObject(o, path);
      in_.allowOnly(o, path, {"name", "movable", "position", "rotate_y", "patch_size", "solids"});
      Object object;
      object.name = in_.string(in_.required(o, path, "name"), child(path, "name"));
      if (object.name.empty()) in_.fail(Diag::OutOfRange, child(path, "name"), "must not be empty");
      if (!names.insert(object.name).second)
        in_.fail(Diag::DuplicateName, child(path, "name"), "\"" + object.name + "\"");
      if (const auto v = o.find("movable"); v != o.end()) object.movable = in_.boolean(*v, child(path, "movable"));
      if (const auto v = o.find("position"); v != o.end())
        object.position = in_.vec3(*v, child(path, "position"), -kMaxLength, kMaxLength);
      if (const auto v = o.find("rotate_y"); v != o.end())
        object.rotateYDeg = in_.number(*v, child(path, "rotate_y"), -kMaxLength, kMaxLength);
      if (const auto v = o.find("patch_size"); v != o.end())
        object.patchSize = patchSize(*v, child(path, "patch_size"));
      const std::string solidsPath = child(path, "solids");
      const Json& solids = in_.required(o, path, "solids");
      in_.expectArray(solids, solidsPath);
      if (solids.empty()) in_.fail(Diag::OutOfRange, solidsPath, "an object needs at least one solid");
      for (size_t s = 0; s < solids.size(); ++s) object.solids.push_back(parseSolid(solids[s], child(solidsPath, s)));
      scene_.objects.push_back(std::move(object));
    }
  }

  Solid parseSolid(const Json& s, const std::string& path) const {
    in_.expectObject(s, path);
    in_.allowOnly(s, path, {"profile", "axis", "from", "to", "taper", "inward", "material", "patch_size", "faces"});
    Solid solid;
    solid.jsonPath = path;
    const std::string profilePath = child(path, "profile");
    solid.profile = in_.ring2(in_.required(s, path, "profile"), profilePath, -kMaxLength, kMaxLength);
    checkConvexProfile(solid.profile, profilePath);
    if (const auto v = s.find("axis"); v != s.end()) {
      const std::string axis = in_.string(*v, child(path, "axis"));
      if (axis == "x") solid.axis = Axis::X;
      else if (axis == "y") solid.axis = Axis::Y;
      else if (axis == "z") solid.axis = Axis::Z;
      else in_.fail(Diag::UnknownAxis, child(path, "axis"), "\"" + axis + "\"");
    }
    solid.from = in_.number(in_.required(s, path, "from"), child(path, "from"), -kMaxLength, kMaxLength);
    solid.to = in_.number(in_.required(s, path, "to"), child(path, "to"), -kMaxLength, kMaxLength);
    if (!(solid.from < solid.to)) in_.fail(Diag::EmptySweep, child(path, "to"));
    if (solid.to - solid.from < kMinLength) in_.fail(Diag::Degenerate, child(path, "to"), "the sweep is shorter than 1e-9");
    if (const auto v = s.find("taper"); v != s.end()) solid.taper = parseTaper(*v, child(path, "taper"));
    if (const auto v = s.find("inward"); v != s.end()) solid.inward = in_.boolean(*v, child(path, "inward"));
    solid.material = materialRef(in_.required(s, path, "material"), child(path, "material"));
    if (const auto v = s.find("patch_size"); v != s.end()) solid.patchSize = patchSize(*v, child(path, "patch_size"));
    if (const auto v = s.find("faces"); v != s.end()) {
      const std::string facesPath = child(path, "faces");
      in_.expectObject(*v, facesPath);
      for (const auto& item : v->items())
        solid.faces[item.key()] = parseFace(item.value(), child(facesPath, item.key()));
    }
    return solid;
  }

  void checkConvexProfile(const mesher::Ring2& profile, const std::string& path) const {
    const double size = mesher::extent(profile);
    checkPolygonPoints(profile, path);
    // Area first: points on one line fold back too, where "no area" says more than "not convex".
    if (fanArea(profile) <= 1e-12 * size * size) in_.fail(Diag::Degenerate, path, "no area");
    if (!mesher::isConvex(profile)) in_.fail(Diag::NotConvex, path);
  }

  // Shared by profiles and holes: not too many points, none repeating its neighbour.
  void checkPolygonPoints(const mesher::Ring2& polygon, const std::string& path) const {
    if (polygon.size() > kMaxPolygonPoints)
      in_.fail(Diag::OutOfRange, path, std::to_string(polygon.size()) + " points, at most " + std::to_string(kMaxPolygonPoints));
    for (size_t i = 0; i < polygon.size(); ++i)
      if (glm::length(polygon[(i + 1) % polygon.size()] - polygon[i]) < kMinLength)
        in_.fail(Diag::Degenerate, path, "point " + std::to_string(i) + " repeats the next (closer than 1e-9)");
  }

  Taper parseTaper(const Json& t, const std::string& path) const {
    in_.expectObject(t, path);
    Taper taper;
    const std::string kind = in_.string(in_.required(t, path, "kind"), child(path, "kind"));
    if (kind == "none") {
      in_.allowOnly(t, path, {"kind"});
      taper.kind = TaperKind::None;
    } else if (kind == "linear") {
      in_.allowOnly(t, path, {"kind", "scale"});
      taper.kind = TaperKind::Linear;
      taper.scale = in_.number(in_.required(t, path, "scale"), child(path, "scale"), 0, 1e3);
      if (taper.scale > 0 && taper.scale < 1e-6)
        in_.fail(Diag::OutOfRange, child(path, "scale"), "a scale below 1e-6 leaves a sliver; use 0 for an apex");
    } else if (kind == "radial") {
      in_.allowOnly(t, path, {"kind", "slices", "both_ends"});
      taper.kind = TaperKind::Radial;
      if (const auto v = t.find("both_ends"); v != t.end()) taper.bothEnds = in_.boolean(*v, child(path, "both_ends"));
      const int fewest = taper.bothEnds ? 2 : 1;  // one band shrunk to a point at both ends is nothing
      taper.slices = in_.integer(in_.required(t, path, "slices"), child(path, "slices"), fewest, kMaxSlices);
    } else {
      in_.fail(Diag::UnknownTaper, child(path, "kind"), "\"" + kind + "\"");
    }
    return taper;
  }

  FaceOverride parseFace(const Json& f, const std::string& path) const {
    in_.expectObject(f, path);
    in_.allowOnly(f, path, {"material", "open", "patch_size", "holes"});
    FaceOverride face;
    if (const auto v = f.find("material"); v != f.end()) face.material = materialRef(*v, child(path, "material"));
    if (const auto v = f.find("open"); v != f.end()) face.open = in_.boolean(*v, child(path, "open"));
    if (const auto v = f.find("patch_size"); v != f.end()) face.patchSize = patchSize(*v, child(path, "patch_size"));
    if (const auto v = f.find("holes"); v != f.end()) {
      const std::string holesPath = child(path, "holes");
      in_.expectArray(*v, holesPath);
      if (v->size() > kMaxHolesPerFace)
        in_.fail(Diag::OutOfRange, holesPath, std::to_string(v->size()) + " holes, at most " + std::to_string(kMaxHolesPerFace));
      for (size_t h = 0; h < v->size(); ++h) {
        const std::string holePath = child(holesPath, h);
        const Json& hole = (*v)[h];
        in_.expectObject(hole, holePath);
        in_.allowOnly(hole, holePath, {"polygon", "fill"});
        Hole parsed;
        const std::string polygonPath = child(holePath, "polygon");
        parsed.polygon = in_.ring2(in_.required(hole, holePath, "polygon"), polygonPath, -kMaxLength, kMaxLength);
        checkPolygonPoints(parsed.polygon, polygonPath);
        if (const auto fill = hole.find("fill"); fill != hole.end())
          parsed.fillMaterial = materialRef(*fill, child(holePath, "fill"));
        face.holes.push_back(std::move(parsed));
      }
    }
    return face;
  }

  void parseCameras(const Json& cameras) {
    in_.expectObject(cameras, "cameras");
    for (const auto& item : cameras.items()) {
      const std::string path = child("cameras", item.key());
      const Json& c = item.value();
      in_.expectObject(c, path);
      in_.allowOnly(c, path, {"position", "look_at", "up", "fov_y"});
      Camera camera;
      camera.name = item.key();
      camera.position = in_.vec3(in_.required(c, path, "position"), child(path, "position"), -kMaxLength, kMaxLength);
      camera.lookAt = in_.vec3(in_.required(c, path, "look_at"), child(path, "look_at"), -kMaxLength, kMaxLength);
      if (const auto v = c.find("up"); v != c.end()) camera.up = in_.vec3(*v, child(path, "up"), -kMaxLength, kMaxLength);
      if (const auto v = c.find("fov_y"); v != c.end()) {
        camera.fovYDeg = in_.number(*v, child(path, "fov_y"), 0, 179);
        if (camera.fovYDeg <= 0) in_.fail(Diag::OutOfRange, child(path, "fov_y"), "must be greater than 0");
      }
      const glm::dvec3 view = camera.lookAt - camera.position;
      const double viewLength = glm::length(view), upLength = glm::length(camera.up);
      if (viewLength == 0 || upLength == 0 ||
          glm::length(glm::cross(view, camera.up)) <= 1e-9 * viewLength * upLength)
        in_.fail(Diag::BadCamera, path);
      scene_.cameras.push_back(std::move(camera));
    }
  }

  const JsonReader& in_;
  Scene& scene_;
};

// The faces a solid makes at most: a side per profile point and band, the two ends, a surface per
// filled hole (open faces and apexes make fewer).
size_t mostFaces(const Solid& solid) {
  const size_t bands = solid.taper.kind == TaperKind::Radial ? static_cast<size_t>(solid.taper.slices) : 1;
  size_t fills = 0;
  for (const auto& [name, face] : solid.faces)
    fills += static_cast<size_t>(std::count_if(face.holes.begin(), face.holes.end(), [](const Hole& h) { return h.fillMaterial.has_value(); }));
  return solid.profile.size() * bands + 2 + fills;
}

// Every patch size the file gives, against the scene's extent.
void checkPatchSizes(const Scene& scene) {
  const double extent = sceneExtent(scene);
  auto check = [&](const std::optional<double>& patch, const std::string& path) {
    if (patch) checkPatchSize(*patch, extent, scene.file, path);
  };
  check(scene.patchSize > 0 ? std::optional(scene.patchSize) : std::nullopt, "settings.patch_size");
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    check(object.patchSize, child(child("objects", i), "patch_size"));
    for (const Solid& solid : object.solids) {
      check(solid.patchSize, child(solid.jsonPath, "patch_size"));
      for (const auto& [name, face] : solid.faces)
        check(face.patchSize, child(child(child(solid.jsonPath, "faces"), name), "patch_size"));
    }
  }
}

}  // namespace

Scene parseSceneFaces(std::string_view text, const std::string& file) {
  const JsonReader in(file);
  const Json root = in.parse(text);
  Scene scene;
  scene.file = file;
  SceneParser(in, scene).parse(root);

  // Counted before anything is swept, so that a file asking too much is refused at once.
  size_t faces = 0;
  for (const Object& object : scene.objects)
    for (const Solid& solid : object.solids) {
      faces += mostFaces(solid);
      checkFaceCount(faces, file, solid.jsonPath);
    }
  for (uint32_t i = 0; i < scene.objects.size(); ++i)
    for (const Solid& solid : scene.objects[i].solids)
      appendSolidSurfaces(scene, i, solid, scene.objects[i].patchSize, scene.surfaces);
  scene.computeBounds();
  // Without settings.patch_size, an eighth of the scene's extent.
  if (scene.patchSize <= 0) scene.patchSize = sceneExtent(scene) / 8;
  for (Surface& s : scene.surfaces)
    if (s.patchSize <= 0) s.patchSize = scene.patchSize;
  checkPatchSizes(scene);
  return scene;
}

void preprocessSurfaces(Scene& scene) {
  // Coplanar faces of one material that touch become one surface (3.2).
  scene.surfaces = mergeFaces(scene, std::move(scene.surfaces), 1e-9 * sceneExtent(scene));
  // Faces resting on other objects' surfaces are cut out of them.
  cutOutContacts(scene.surfaces, contactTolerance(scene));
}

Scene parseScene(std::string_view text, const std::string& file) {
  Scene scene = parseSceneFaces(text, file);
  preprocessSurfaces(scene);
  return scene;
}

}  // namespace engine

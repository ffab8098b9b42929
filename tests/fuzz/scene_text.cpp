// Scene text from bytes. An input starting with '{' is taken as the text of a scene file; any
// other is decoded into one (below), so that most inputs get past the parser into solid
// sweeping, holes, coplanar merging and contact cut-outs, where mutated text rarely arrives.
// Coordinates are on a grid of quarters, so faces often lie in one plane, touch and rest on each
// other. Layout (bytes; past the end all zeros):
//   settings   patch_size = (1 + settings % 16) / 4, or none (bit 7)
//   then objects (at most 8) while bytes remain:
//   object     bit 0 movable; 1 + bit 1 solids; bits 2-3 rotate_y 0, 90, 45 or 180 degrees;
//              then the position (three int8, in quarters)
//   solid      kind: bits 0-1 axis (x, y, z, x), bit 2 inward, bits 3-4 taper (none, none, linear, radial),
//              bits 5-7 material; from (int8) and length (1 + a byte), in quarters; the profile
//              (shape % 3: a rectangle x, y, width, height; a regular polygon of 3 + n % 6 sides,
//              centre and radius; or 3 + n % 5 listed points, not always convex); the taper's
//              scale (a byte, in 64ths) or slices (1 + a byte % 8, bit 3 both ends); then
//              faces % 4 face overrides: a face (top, bottom, side N) and what it gets (open, a
//              material, an open hole or a hole filled with a material: x, y, width, height).
#include "tests/fuzz/fuzz_targets.h"

#include "engine/diagnostics.h"
#include "engine/io/json_reader.h"
#include "engine/io/scene_loader.h"
#include "tests/fuzz/byte_reader.h"
#include "tests/fuzz/meshable.h"

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

namespace fuzz::scene_text {

namespace {

using engine::Json;

const char* const kMaterials[] = {"white", "grey", "lamp"};

double quarters(int value) { return value / 4.0; }

Json point(double x, double y) { return Json::array({x, y}); }

Json rectangle(ByteReader& in) {
  const double x = quarters(in.next<int8_t>()), y = quarters(in.next<int8_t>());
  const double w = quarters(1 + in.next<uint8_t>()), h = quarters(1 + in.next<uint8_t>());
  return Json::array({point(x, y), point(x + w, y), point(x + w, y + h), point(x, y + h)});
}

Json profile(ByteReader& in) {
  const auto shape = in.next<uint8_t>();
  if (shape % 3 == 0) return rectangle(in);
  Json points = Json::array();
  if (shape % 3 == 1) {
    const int sides = 3 + in.next<uint8_t>() % 6;
    const double x = quarters(in.next<int8_t>()), y = quarters(in.next<int8_t>()), r = quarters(1 + in.next<uint8_t>());
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * std::numbers::pi * i / sides;
      points.push_back(point(x + r * std::cos(a), y + r * std::sin(a)));
    }
  } else {
    for (int i = 3 + in.next<uint8_t>() % 5; i > 0; --i) points.push_back(point(quarters(in.next<int8_t>()), quarters(in.next<int8_t>())));
  }
  return points;
}

Json faceOverride(ByteReader& in) {
  const auto what = in.next<uint8_t>();
  const char* material = kMaterials[(what >> 2) % 3];
  switch (what % 4) {
    case 0: return {{"open", true}};
    case 1: return {{"material", material}};
    case 2: return {{"holes", Json::array({Json{{"polygon", rectangle(in)}}})}};
    default: return {{"holes", Json::array({Json{{"polygon", rectangle(in)}, {"fill", material}}})}};
  }
}

Json solid(ByteReader& in) {
  const auto kind = in.next<uint8_t>();
  Json s = {{"axis", std::string(1, static_cast<char>('x' + (kind & 3) % 3))}, {"inward", (kind & 4) != 0},
            {"material", kMaterials[(kind >> 5) % 3]}};
  const double from = quarters(in.next<int8_t>());
  s["from"] = from;
  s["to"] = from + quarters(1 + in.next<uint8_t>());
  s["profile"] = profile(in);
  const size_t sides = s["profile"].size();
  switch ((kind >> 3) % 4) {
    case 2: s["taper"] = {{"kind", "linear"}, {"scale", in.next<uint8_t>() / 64.0}}; break;
    case 3: {
      const auto slices = in.next<uint8_t>();
      s["taper"] = {{"kind", "radial"}, {"slices", 1 + slices % 8}, {"both_ends", (slices & 8) != 0}};
      break;
    }
    default: break;
  }
  Json faces = Json::object();
  for (int f = in.next<uint8_t>() % 4; f > 0; --f) {
    const auto which = in.next<uint8_t>();
    const std::string name = which % 4 == 0 ? "top" : which % 4 == 1 ? "bottom" : "side " + std::to_string(which / 4 % sides);
    faces[name] = faceOverride(in);
  }
  if (!faces.empty()) s["faces"] = faces;
  return s;
}

std::string sceneFromBytes(const uint8_t* data, size_t size) {
  ByteReader in(data, size);
  Json scene = {{"format", "walkrad-scene/1"},
                {"materials", {{"white", {{"reflectance", {0.8, 0.8, 0.8}}}},
                               {"grey", {{"reflectance", {0.4, 0.4, 0.4}}}},
                               {"lamp", {{"reflectance", {0.5, 0.5, 0.5}}, {"emission", {5, 5, 5}}}}}}};
  const auto settings = in.next<uint8_t>();
  if (!(settings & 0x80)) scene["settings"] = {{"patch_size", quarters(1 + settings % 16)}};
  Json objects = Json::array();
  for (int o = 0; o < 8 && !in.atEnd(); ++o) {
    const auto tag = in.next<uint8_t>();
    const double turns[] = {0, 90, 45, 180};
    Json object = {{"name", "object " + std::to_string(o)}, {"movable", (tag & 1) != 0}, {"rotate_y", turns[(tag >> 2) % 4]}};
    object["position"] = {quarters(in.next<int8_t>()), quarters(in.next<int8_t>()), quarters(in.next<int8_t>())};
    object["solids"] = Json::array();
    for (int s = 1 + (tag >> 1) % 2; s > 0; --s) object["solids"].push_back(solid(in));
    objects.push_back(object);
  }
  scene["objects"] = objects;
  return scene.dump();
}

}  // namespace

void fuzzOne(const uint8_t* data, size_t size) {
  const bool text = size > 0 && data[0] == '{';
  try {
    const std::string decoded = text ? std::string() : sceneFromBytes(data, size);
    expectMeshableSurfaces(engine::parseScene(text ? std::string_view(reinterpret_cast<const char*>(data), size) : decoded, "fuzz.json"));
  } catch (const engine::SceneError&) {
    // Refused with its place: what bad input must get.
  }
}

}  // namespace fuzz::scene_text

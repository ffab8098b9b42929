#include "engine/io/scene_saver.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace engine {

namespace {

using Json = nlohmann::ordered_json;

// Where a member of a JSON object lies in the text: its key's first byte and its value's bytes.
struct MemberSpan {
  size_t key = 0, valueBegin = 0, valueEnd = 0;
};

// The bytes of a JSON text that nlohmann has parsed already (so it is valid), walked to find
// where the objects' members lie.
class Skimmer {
 public:
  explicit Skimmer(std::string_view text) : t_(text) {}

  size_t at() const { return i_; }
  void space() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
  }
  // At a value: steps past it.
  void skipValue() {
    space();
    const char c = t_[i_];
    if (c == '"') return skipString();
    if (c == '{' || c == '[') {
      int depth = 0;
      do {
        if (t_[i_] == '"') {
          skipString();
          continue;
        }
        depth += (t_[i_] == '{' || t_[i_] == '[') - (t_[i_] == '}' || t_[i_] == ']');
        ++i_;
      } while (depth > 0);
      return;
    }
    while (i_ < t_.size() && std::string_view(",]} \t\r\n").find(t_[i_]) == std::string_view::npos) ++i_;
  }
  // At an object's '{': its members by key, stepping past its '}'.
  std::map<std::string, MemberSpan> members() {
    std::map<std::string, MemberSpan> out;
    ++i_;
    for (space(); t_[i_] != '}'; space()) {
      if (t_[i_] == ',') {
        ++i_;
        continue;
      }
      MemberSpan span;
      span.key = i_;
      skipString();
      const std::string key = Json::parse(t_.substr(span.key, i_ - span.key)).get<std::string>();
      space();
      ++i_;  // ':'
      space();
      span.valueBegin = i_;
      skipValue();
      span.valueEnd = i_;
      out[key] = span;  // a key given twice: the last counts, as nlohmann reads it
    }
    ++i_;
    return out;
  }
  // At an array's '[': steps to its first element (true) or past its ']' (false, when empty).
  bool enterArray() {
    ++i_;
    space();
    if (t_[i_] != ']') return true;
    ++i_;
    return false;
  }
  // After an element: steps to the next (true) or past the ']' (false).
  bool nextElement() {
    space();
    return t_[i_++] == ',' ? (space(), true) : false;
  }
  void seek(size_t at) { i_ = at; }

 private:
  void skipString() {
    for (++i_; t_[i_] != '"'; ++i_)
      if (t_[i_] == '\\') ++i_;
    ++i_;
  }
  std::string_view t_;
  size_t i_ = 0;
};

// A number as nlohmann writes it (the shortest text that reads back the same double).
std::string number(double value) { return Json(value).dump(); }

std::string positionText(const Vec3& p) { return "[" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + "]"; }

// A change of the text: `length` bytes at `at` become `with`.
struct Splice {
  size_t at, length;
  std::string with;
};

// A member added to an object after its last member (an object of a scene has at least its
// name): on a line of its own, indented as the last member, when that stands on a line of its own
// in the object (after a line break past the object's '{' at `open`); else on the same line.
Splice addedMember(std::string_view text, size_t open, const std::map<std::string, MemberSpan>& members,
                   std::string_view member) {
  Splice splice{0, 0, ", "};
  size_t lastKey = 0;
  for (const auto& [key, span] : members)
    if (span.valueEnd > splice.at) lastKey = span.key, splice.at = span.valueEnd;
  const size_t lineStart = text.rfind('\n', lastKey);
  if (lineStart != std::string_view::npos && lineStart > open)
    splice.with.assign(",\n").append(text.substr(lineStart + 1, lastKey - lineStart - 1));
  splice.with.append(member);
  return splice;
}

}  // namespace

std::string sceneTextWithPoses(std::string_view text, const Scene& scene) {
  const Json root = Json::parse(text);
  const Json& objects = root.at("objects");
  if (objects.size() != scene.objects.size())
    throw std::invalid_argument(scene.file + ": the text has " + std::to_string(objects.size()) + " objects, the scene " +
                                std::to_string(scene.objects.size()));

  Skimmer skim(text);
  skim.space();
  const MemberSpan objectsSpan = skim.members().at("objects");
  skim.seek(objectsSpan.valueBegin);
  std::vector<Splice> splices;
  bool more = skim.enterArray();
  for (size_t i = 0; more; ++i, more = skim.nextElement()) {
    const Object& o = scene.objects[i];
    const Json& in = objects[i];
    const size_t open = skim.at();
    const std::map<std::string, MemberSpan> members = skim.members();
    const auto set = [&](const char* key, bool differs, const std::string& value) {
      if (!differs) return;  // poses the file already states are left in its own spelling (0, not 0.0)
      const auto found = members.find(key);
      if (found != members.end())
        splices.push_back({found->second.valueBegin, found->second.valueEnd - found->second.valueBegin, value});
      else
        splices.push_back(addedMember(text, open, members, std::string("\"").append(key).append("\": ").append(value)));
    };
    const Json position = {o.position.x, o.position.y, o.position.z};
    set("position", in.value("position", Json::array({0, 0, 0})) != position, positionText(o.position));
    set("rotate_y", in.value("rotate_y", 0.0) != o.rotateYDeg, number(o.rotateYDeg));
  }

  std::stable_sort(splices.begin(), splices.end(), [](const Splice& a, const Splice& b) { return a.at < b.at; });
  std::string out;
  size_t from = 0;
  for (const Splice& s : splices) {
    out.append(text.substr(from, s.at - from)).append(s.with);
    from = s.at + s.length;
  }
  out.append(text.substr(from));
  return out;
}

}  // namespace engine

#include "engine/io/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>
#include <sstream>

namespace engine {

namespace {

const char* typeName(const Json& value) {
  if (value.is_number()) return "a number";
  return value.type_name();
}

std::string rangeText(double lo, double hi) {
  std::ostringstream s;
  s << "expected " << lo << " to " << hi;
  return s.str();
}

// Watches the parser's events to refuse an object that names a key twice (nlohmann keeps the
// last silently), reporting the JSON path of the second one.
class DuplicateKeyGuard {
 public:
  explicit DuplicateKeyGuard(const std::string& file) : file_(file) {}

  bool operator()(int, Json::parse_event_t event, const Json& parsed) {
    using Event = Json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        enterValue();
        frames_.push_back(Frame{event == Event::array_start, {}, 0, 0, {}});
        break;
      case Event::object_end:
      case Event::array_end:
        frames_.pop_back();
        break;
      case Event::key: {
        Frame& object = frames_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second)
          throw SceneError(Diag::DuplicateKey, file_, pathTo(frames_.size()));
        break;
      }
      case Event::value:
        enterValue();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool isArray;
    std::string key;   // objects: the key being read
    size_t index = 0;  // arrays: the element being read
    size_t next = 0;   // arrays: the index of the next element
    std::set<std::string> keys;
  };

  // A value starts inside the innermost container: an array counts it as its next element.
  void enterValue() {
    if (!frames_.empty() && frames_.back().isArray) frames_.back().index = frames_.back().next++;
  }

  std::string pathTo(size_t depth) const {
    std::string path;
    for (size_t i = 0; i < depth; ++i)
      path = frames_[i].isArray ? child(path, frames_[i].index) : child(path, frames_[i].key);
    return path;
  }

  const std::string& file_;
  std::vector<Frame> frames_;
};

constexpr std::string_view kNumberCharacters = "+-.0123456789eE";

// ":LINE:COLUMN" of a byte offset, as the messages of syntax errors place them.
std::string lineAndColumn(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return ":" + std::to_string(line) + ":" + std::to_string(column);
}

// The offset of the first number (outside strings) that overflows a double, where nlohmann's
// parser stopped; the text's end when there is none.
size_t firstOverflowingNumber(std::string_view text) {
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
      const size_t end = std::min(text.find_first_not_of(kNumberCharacters, i), text.size());
      if (std::isinf(std::strtod(std::string(text.substr(i, end - i)).c_str(), nullptr))) return i;
      i = end - 1;
    }
  }
  return text.size();
}

}  // namespace

void JsonReader::fail(Diag diag, const std::string& path, std::string detail) const {
  throw SceneError(diag, file_, path.empty() ? "(top level)" : path, std::move(detail));
}

Json JsonReader::parse(std::string_view text) const {
  try {
    return Json::parse(text.begin(), text.end(), DuplicateKeyGuard(file_));
  } catch (const Json::parse_error& e) {
    std::string what = e.what();
    if (const size_t colon = what.rfind(": "); colon != std::string::npos) what = what.substr(colon + 2);
    throw SceneError(Diag::NotJson, file_, lineAndColumn(text, e.byte == 0 ? 0 : e.byte - 1), what);
  } catch (const Json::out_of_range&) {  // nlohmann names the number too large for a double, not where it is
    const size_t at = firstOverflowingNumber(text);
    const std::string number(text.substr(at, text.find_first_not_of(kNumberCharacters, at) - at));
    throw SceneError(Diag::NotFinite, file_, lineAndColumn(text, at), number + " is too large for a double");
  }
}

void JsonReader::expectObject(const Json& value, const std::string& path) const {
  if (!value.is_object())
    fail(Diag::WrongType, path, std::string("expected an object, found ") + typeName(value));
}

void JsonReader::expectArray(const Json& value, const std::string& path) const {
  if (!value.is_array())
    fail(Diag::WrongType, path, std::string("expected an array, found ") + typeName(value));
}

void JsonReader::allowOnly(const Json& object, const std::string& path,
                           std::initializer_list<std::string_view> allowed) const {
  for (const auto& item : object.items())
    if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
      fail(Diag::UnknownKey, child(path, item.key()));
}

const Json& JsonReader::required(const Json& object, const std::string& path, const char* key) const {
  const auto found = object.find(key);
  if (found == object.end()) fail(Diag::MissingField, child(path, key));
  return *found;
}

double JsonReader::number(const Json& value, const std::string& path, double lo, double hi) const {
  // nlohmann reads NaN and Infinity as null; a string "nan" is caught as the wrong type.
  if (value.is_null()) fail(Diag::NotFinite, path, "null (NaN or infinity?)");
  if (!value.is_number())
    fail(Diag::WrongType, path, std::string("expected a number, found ") + typeName(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(Diag::NotFinite, path);
  if (x < lo || x > hi) fail(Diag::OutOfRange, path, value.dump() + ", " + rangeText(lo, hi));
  return x;
}

int JsonReader::integer(const Json& value, const std::string& path, int lo, int hi) const {
  const double x = number(value, path, lo, hi);
  if (x != std::floor(x)) fail(Diag::WrongType, path, "expected a whole number, found " + value.dump());
  return static_cast<int>(x);
}

bool JsonReader::boolean(const Json& value, const std::string& path) const {
  if (!value.is_boolean())
    fail(Diag::WrongType, path, std::string("expected true or false, found ") + typeName(value));
  return value.get<bool>();
}

std::string JsonReader::string(const Json& value, const std::string& path) const {
  if (!value.is_string())
    fail(Diag::WrongType, path, std::string("expected a string, found ") + typeName(value));
  return value.get<std::string>();
}

glm::dvec3 JsonReader::vec3(const Json& value, const std::string& path, double lo, double hi) const {
  if (!value.is_array() || value.size() != 3)
    fail(Diag::WrongType, path, "expected an array of 3 numbers, found " + std::string(typeName(value)));
  return {number(value[0], child(path, 0), lo, hi), number(value[1], child(path, 1), lo, hi),
          number(value[2], child(path, 2), lo, hi)};
}

mesher::Ring2 JsonReader::ring2(const Json& value, const std::string& path, double lo, double hi) const {
  expectArray(value, path);
  if (value.size() < 3)
    fail(Diag::TooFewPoints, path, std::to_string(value.size()) + " given");
  mesher::Ring2 ring;
  ring.reserve(value.size());
  for (size_t i = 0; i < value.size(); ++i) {
    const Json& p = value[i];
    const std::string at = child(path, i);
    if (!p.is_array() || p.size() != 2)
      fail(Diag::WrongType, at, "expected a point [a, b], found " + std::string(typeName(p)));
    ring.push_back({number(p[0], child(at, 0), lo, hi), number(p[1], child(at, 1), lo, hi)});
  }
  return ring;
}

}  // namespace engine

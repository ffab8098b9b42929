// Typed access to a parsed JSON document that reports every problem as a SceneError carrying
// the file and the JSON path of the offending value (e.g. objects[2].solids[0].profile).
#pragma once

#include "engine/diagnostics.h"
#include "mesher/polygon.h"

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <string_view>

namespace engine {

using Json = nlohmann::ordered_json;  // keeps the file's order of materials and cameras

class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  [[noreturn]] void fail(Diag diag, const std::string& path, std::string detail = {}) const;

  // Parses text; syntax errors are reported as FILE:LINE:COLUMN, a key named twice in one
  // object by its path.
  Json parse(std::string_view text) const;

  void expectObject(const Json& value, const std::string& path) const;
  void expectArray(const Json& value, const std::string& path) const;
  // Refuses keys outside `allowed`: a misspelt key would otherwise be silently ignored.
  void allowOnly(const Json& object, const std::string& path,
                 std::initializer_list<std::string_view> allowed) const;
  const Json& required(const Json& object, const std::string& path, const char* key) const;

  double number(const Json& value, const std::string& path, double lo, double hi) const;
  int integer(const Json& value, const std::string& path, int lo, int hi) const;
  bool boolean(const Json& value, const std::string& path) const;
  std::string string(const Json& value, const std::string& path) const;
  glm::dvec3 vec3(const Json& value, const std::string& path, double lo, double hi) const;
  mesher::Ring2 ring2(const Json& value, const std::string& path, double lo, double hi) const;

 private:
  std::string file_;
};

}  // namespace engine

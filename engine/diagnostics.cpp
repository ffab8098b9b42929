#include "engine/diagnostics.h"

#include <algorithm>
#include <cctype>

namespace engine {

namespace {

std::string oneLine(Diag diag, const std::string& file, const std::string& place,
                    const std::string& detail) {
  std::string line = file;
  if (!place.empty()) line += (place.front() == ':' ? "" : ": ") + place;
  line += std::string(": ") + describe(diag);
  if (!detail.empty()) line += ": " + detail;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return line;
}

}  // namespace

const char* describe(Diag diag) {
  switch (diag) {
#define WALKRAD_DIAG_TEXT(id, text) \
  case Diag::id:                    \
    return text;
    WALKRAD_SCENE_DIAGNOSTICS(WALKRAD_DIAG_TEXT)
#undef WALKRAD_DIAG_TEXT
  }
  return "unknown diagnostic";
}

SceneError::SceneError(Diag diag, std::string file, std::string place, std::string detail)
    : std::runtime_error(oneLine(diag, file, place, detail)),
      diag_(diag),
      file_(std::move(file)),
      place_(std::move(place)) {}

std::string child(const std::string& path, std::string_view key) {
  const bool identifier = !key.empty() && !std::isdigit(static_cast<unsigned char>(key.front())) &&
                          std::all_of(key.begin(), key.end(), [](char c) {
                            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                          });
  if (identifier) return path.empty() ? std::string(key) : path + "." + std::string(key);
  std::string quoted;
  for (char c : key) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return path + "[\"" + quoted + "\"]";
}

std::string child(const std::string& path, size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

}  // namespace engine

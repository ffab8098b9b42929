#include "engine/io/gltf_files.h"

#include "engine/diagnostics.h"
#include "engine/io/input_file.h"
#include "engine/io/json_reader.h"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <variant>

namespace engine {

namespace {

namespace fs = std::filesystem;

constexpr size_t kShownUriLength = 120;  // a data: URI may run to megabytes

// A URI as a message shows it: quoted, a long one cut short.
std::string shown(const std::string& uri) {
  return "\"" + (uri.size() <= kShownUriLength ? uri : uri.substr(0, kShownUriLength) + "...") + "\"";
}

// The JSON of a model: all of a .gltf, the first chunk of a .glb (nothing when its header is
// broken; tinygltf then refuses the model).
std::string_view jsonOf(std::string_view model) {
  if (model.substr(0, 4) != "glTF") return model;
  if (model.size() < 20 || model.substr(16, 4) != "JSON") return {};
  const auto byte = [&](size_t i) { return static_cast<uint32_t>(static_cast<unsigned char>(model[i])); };
  const uint32_t length = byte(12) | byte(13) << 8 | byte(14) << 16 | byte(15) << 24;  // little-endian
  if (length > model.size() - 20) return {};
  return model.substr(20, length);
}

// The model's top-level "buffers" and "images", everything else dropped while parsing; an empty
// object when the JSON does not parse (tinygltf says why).
Json buffersAndImages(std::string_view json) {
  const Json::parser_callback_t keep = [](int depth, Json::parse_event_t event, Json& parsed) {
    return depth != 1 || event != Json::parse_event_t::key || parsed == "buffers" || parsed == "images";
  };
  Json root = Json::parse(json.begin(), json.end(), keep, /*allow_exceptions=*/false);
  return root.is_object() ? root : Json::object();
}

unsigned char hexDigit(char c) {
  if (c >= '0' && c <= '9') return static_cast<unsigned char>(c - '0');
  if (c >= 'a' && c <= 'f') return static_cast<unsigned char>(c - 'a' + 10);
  if (c >= 'A' && c <= 'F') return static_cast<unsigned char>(c - 'A' + 10);
  return 0;
}

// A URI as tinygltf reads it as a file name (its dlib::urldecode), so that the callbacks are
// asked for exactly the names read here: %XX is the byte XX (a digit that is not hex counts 0),
// + is a space.
std::string fileNameOf(const std::string& uri) {
  std::string name;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      name += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      name += static_cast<char>(hexDigit(uri[i + 1]) << 4 | hexDigit(uri[i + 2]));
      i += 2;
    } else {
      name += uri[i];
    }
  }
  return name;
}

// Whether a relative path climbs out of its folder by its own `..`s.
bool climbsOut(const std::string& path) {
  int depth = 0;
  for (const fs::path& part : fs::path(path)) {
    if (part == "..") {
      if (--depth < 0) return true;
    } else if (part != "." && !part.empty()) {
      ++depth;
    }
  }
  return false;
}

// The length of what a data: URI that tinygltf::IsDataURI accepts decodes to: tinygltf's base64
// decoding stops at the first character that is not a base64 digit ('=' included).
uint64_t decodedLength(const std::string& uri) {
  const size_t start = uri.find(',') + 1;
  uint64_t digits = 0;
  for (size_t i = start; i < uri.size(); ++i, ++digits) {
    const auto c = static_cast<unsigned char>(uri[i]);
    if (!std::isalnum(c) && c != '+' && c != '/') break;
  }
  return digits / 4 * 3 + (digits % 4 ? digits % 4 - 1 : 0);
}

}  // namespace

GltfFiles::GltfFiles(std::string_view model, const std::string& file) {
  const Json root = buffersAndImages(jsonOf(model));
  std::optional<std::string> folder;  // canonical, once a URI names a file
  for (const char* kind : {"buffers", "images"}) {
    const bool buffer = kind == std::string_view("buffers");
    const auto list = root.find(kind);
    if (list == root.end() || !list->is_array()) continue;
    for (size_t i = 0; i < list->size(); ++i) {
      const Json& entry = (*list)[i];
      const auto uriValue = entry.is_object() ? entry.find("uri") : entry.end();
      if (!entry.is_object() || uriValue == entry.end() || !uriValue->is_string()) continue;
      const std::string uri = uriValue->get<std::string>();
      const std::string place = child(child(kind, i), "uri");
      const auto refuse = [&](Diag diag, const std::string& detail) {
        throw SceneError(diag, file, place, shown(uri) + (detail.empty() ? "" : ": " + detail));
      };
      // tinygltf refuses a buffer without a byteLength before it reads anything.
      std::optional<uint64_t> byteLength;
      if (buffer) {
        const auto length = entry.find("byteLength");
        if (length == entry.end() || !length->is_number_unsigned()) continue;
        byteLength = length->get<uint64_t>();
      }

      // Embedded data: only a buffer's has a length to check (an image's that tinygltf cannot
      // decode leaves its texture white).
      if (uri.rfind("data:", 0) == 0) {
        if (!buffer) continue;
        if (!tinygltf::IsDataURI(uri)) refuse(Diag::NotGltf, "a data: URI that is not base64 of a buffer or an image");
        if (const uint64_t length = decodedLength(uri); length != *byteLength)
          refuse(Diag::WrongByteLength, "decodes to " + std::to_string(length) + " bytes, byteLength says " + std::to_string(*byteLength));
        continue;
      }

      // A file: refused by its name alone, when it can be, so that nothing is opened.
      const std::string name = fileNameOf(uri);
      if (name.empty()) continue;  // tinygltf refuses a buffer without a URI in a .gltf
      if (name.front() == '/') refuse(Diag::UriAbsolute, "");
      if (climbsOut(name)) refuse(Diag::UriOutsideFolder, "");
      if (!folder) {
        const fs::path parent = fs::path(file).parent_path();
        std::error_code error;
        folder = fs::canonical(parent.empty() ? fs::path(".") : parent, error).string();
        if (error) refuse(Diag::FileUnreadable, "the model's folder: " + error.message());
      }
      std::variant<std::vector<unsigned char>, FileRefusal> read = readRegularFileBytes(*folder + "/" + name, {*folder, byteLength});
      if (const FileRefusal* refusal = std::get_if<FileRefusal>(&read)) {
        if (!buffer && refusal->diag == Diag::FileUnreadable) continue;  // a missing texture is white
        refuse(refusal->diag, refusal->detail);
      }
      File& stored = files_[name];
      if (stored.uses++ == 0) stored.bytes = std::get<std::vector<unsigned char>>(std::move(read));
    }
  }
}

tinygltf::FsCallbacks GltfFiles::callbacks() {
  const auto sameName = [](const std::string& path, void*) { return path; };
  return {&GltfFiles::exists, sameName, &GltfFiles::read, nullptr, this};
}

bool GltfFiles::exists(const std::string& path, void* self) {
  const std::map<std::string, File>& files = static_cast<GltfFiles*>(self)->files_;
  const auto found = files.find(path);
  return found != files.end() && found->second.uses > 0;
}

bool GltfFiles::read(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* self) {
  std::map<std::string, File>& files = static_cast<GltfFiles*>(self)->files_;
  const auto found = files.find(path);
  if (found == files.end() || found->second.uses == 0) {
    if (error) *error += "not among the files walkrad read for the model";
    return false;
  }
  File& file = found->second;
  if (--file.uses == 0) {
    *out = std::move(file.bytes);
  } else {
    *out = file.bytes;
  }
  return true;
}

}  // namespace engine

// Reading a file a stranger may have sent (a scene, sidecar, polygon case, glTF model, or a buffer
// or image a model names) so that it cannot hang walkrad or make it read without end: opened
// without blocking, so a FIFO never waits for a writer, then judged on the open descriptor (no
// check-then-open race): regular files only, of a bounded size.
#pragma once

#include "engine/diagnostics.h"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace engine {

// The largest file walkrad reads, of any kind (tinygltf takes sizes below 4 GiB).
constexpr uint64_t kMaxInputFileBytes = uint64_t{1} << 30;

// Why a file was not read: a diagnostic of the table and the detail to print with it.
struct FileRefusal {
  Diag diag;
  std::string detail;
};

struct FileLimits {
  // When not empty, a canonical folder (std::filesystem::canonical) the file must lie in once
  // symbolic links are resolved. It is checked first, so a refusal tells nothing about a file
  // outside it (not whether it exists, nor its kind, nor its size).
  std::string folder;
  std::optional<uint64_t> exactBytes;  // the size the file must have (a glTF buffer's byteLength)
};

// The whole of a regular file of at most kMaxInputFileBytes, or why not: FileUnreadable (cannot
// be opened or changed while read, with the system's reason), UriOutsideFolder, NotRegularFile
// (a folder, device, FIFO or socket), FileTooLarge, WrongByteLength (not limits.exactBytes).
// Nothing is read before every check has passed.
std::variant<std::string, FileRefusal> readRegularFile(const std::string& path, const FileLimits& limits = {});
std::variant<std::vector<unsigned char>, FileRefusal> readRegularFileBytes(const std::string& path,
                                                                          const FileLimits& limits = {});

// The whole text of a file the user named (a scene, sidecar, polygon case or model):
// readRegularFile, throwing SceneError naming it when it cannot be read (FileUnreadable,
// NotRegularFile, FileTooLarge).
std::string readInputFile(const std::string& path);

}  // namespace engine

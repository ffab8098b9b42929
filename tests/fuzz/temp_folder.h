// An empty folder of the fuzzing process's own, for targets whose loaders take a file name: a
// model named as a file there finds no sidecar and no external buffer beside it.
#pragma once

#include <filesystem>

namespace fuzz {

// Made on first use under the system's temporary folder; removed when the process exits.
const std::filesystem::path& tempFolder();

}  // namespace fuzz

// Writing a file so that it is replaced whole or not at all: write a temporary file in the same
// folder (temporary_file.h: created exclusively, never through a symbolic link, and nameless
// until written, so a process killed meanwhile leaves nothing), flush it, then rename it over
// the target. The one writer of every file walkrad writes.
#pragma once

#include <string>
#include <string_view>

namespace engine {

// Throws std::runtime_error naming `path` when the file cannot be written; the old file, if
// any, is then untouched and no temporary file is left behind. A new file has the permissions
// of any new file (0666 less the umask), a replaced one keeps its own. A symbolic link's target
// is replaced (the link stays); a device or pipe is written in place, since it cannot be
// replaced.
void writeFileAtomically(const std::string& path, std::string_view bytes);

// Throws as writeFileAtomically would when `path` cannot become a file: its folder (a symbolic
// link's target's) is missing or not writable, the path names a folder, or it is a device or
// pipe that cannot be written. A long computation can then fail before it starts
// rather than after. Creates nothing.
void checkCanWrite(const std::string& path);

}  // namespace engine

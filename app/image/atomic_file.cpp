#include "app/image/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace app {

namespace {

// A device or pipe (`--out /dev/stdout`) is written in place: renaming over it would replace
// the device's entry with a file.
void writeInPlace(const std::string& path, std::string_view bytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size() && std::fflush(file) == 0;
  const std::string reason = std::strerror(errno);
  if (std::fclose(file) != 0 || !written) throw std::runtime_error(path + ": cannot write: " + reason);
}

}  // namespace

void writeFileAtomically(const std::string& given, std::string_view bytes) {
  struct stat info {};
  if (::stat(given.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) return writeInPlace(given, bytes);
  // A symbolic link stays one: its target is what is replaced.
  std::string path = given;
  if (::lstat(given.c_str(), &info) == 0 && S_ISLNK(info.st_mode))
    if (char* target = ::realpath(given.c_str(), nullptr)) path = target, std::free(target);
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot " + what + ": " + reason);
  };
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) fail("create");
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size() &&
                       std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
  if (std::fclose(file) != 0 || !written) fail("write");
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("rename into place");
}

void checkCanWrite(const std::string& path) {
  struct stat info {};
  if (path.empty() || path.back() == '/' || (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)))
    throw std::runtime_error(path + ": cannot create: " + std::strerror(EISDIR));
  const std::string::size_type slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (::access(folder.c_str(), W_OK | X_OK) != 0) throw std::runtime_error(path + ": cannot create: " + std::strerror(errno));
}

}  // namespace app

#include "app/image/atomic_file.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace app {

namespace {

// Writes all the bytes and flushes them (to the disk too, with `sync`); false on any failure,
// errno telling why.
bool writeAll(std::FILE* file, std::string_view bytes, bool sync) {
  return std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size() && std::fflush(file) == 0 &&
         (!sync || ::fsync(::fileno(file)) == 0);
}

// A device or pipe (`--out /dev/stdout`) is written in place: renaming over it would replace
// the device's entry with a file.
bool isDeviceOrPipe(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

void writeInPlace(const std::string& path, std::string_view bytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  const bool written = writeAll(file, bytes, false);
  const std::string reason = std::strerror(errno);
  if (std::fclose(file) != 0 || !written) throw std::runtime_error(path + ": cannot write: " + reason);
}

// Where the bytes for `given` go: a symbolic link stays one, its target (there yet or not) is
// what is written.
std::string writtenPath(const std::string& given) {
  struct stat info {};
  if (::lstat(given.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return given;
  if (char* target = ::realpath(given.c_str(), nullptr)) {
    std::string path = target;
    std::free(target);
    return path;
  }
  std::string target(PATH_MAX, '\0');
  const ssize_t length = ::readlink(given.c_str(), target.data(), target.size());
  if (length <= 0) return given;
  target.resize(static_cast<size_t>(length));
  const std::string::size_type slash = given.find_last_of('/');
  return target.front() == '/' || slash == std::string::npos ? target : given.substr(0, slash + 1) + target;
}

std::string folderOf(const std::string& path) {
  const std::string::size_type slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

void writeFileAtomically(const std::string& given, std::string_view bytes) {
  if (isDeviceOrPipe(given)) return writeInPlace(given, bytes);
  const std::string path = writtenPath(given);
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot " + what + ": " + reason);
  };
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) fail("create");
  const bool written = writeAll(file, bytes, true);
  if (std::fclose(file) != 0 || !written) fail("write");
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("rename into place");
}

void checkCanWrite(const std::string& given) {
  struct stat info {};
  if (given.empty() || given.back() == '/' || (::stat(given.c_str(), &info) == 0 && S_ISDIR(info.st_mode)))
    throw std::runtime_error(given + ": cannot create: " + std::strerror(EISDIR));
  // Checked as the write will go: a device in place, anything else beside what is replaced.
  if (isDeviceOrPipe(given)) {
    if (::access(given.c_str(), W_OK) != 0) throw std::runtime_error(given + ": cannot write: " + std::strerror(errno));
    return;
  }
  if (::access(folderOf(writtenPath(given)).c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(given + ": cannot create: " + std::strerror(errno));
}

}  // namespace app

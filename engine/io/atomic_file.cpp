#include "engine/io/atomic_file.h"

#include "engine/io/temporary_file.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <stdexcept>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace engine {

namespace {

// Writes all the bytes; false on failure, errno telling why.
bool writeAll(int file, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(file, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes.remove_prefix(static_cast<size_t>(written));
  }
  return true;
}

// A device or pipe (`--out /dev/stdout`) is written in place: renaming over it would replace
// the device's entry with a file.
bool isDeviceOrPipe(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

void writeInPlace(const std::string& path, std::string_view bytes) {
  const int file = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (file < 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  const bool written = writeAll(file, bytes);
  const std::string reason = std::strerror(errno);
  if (::close(file) != 0 || !written) throw std::runtime_error(path + ": cannot write: " + reason);
}

// A file replaced keeps its permissions; a new one has those of any new file (the umask's).
bool keepMode(int file, const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) || ::fchmod(file, info.st_mode & 07777) == 0;
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

std::string fileNameOf(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

}  // namespace

void writeFileAtomically(const std::string& given, std::string_view bytes) {
  if (isDeviceOrPipe(given)) return writeInPlace(given, bytes);
  const std::string path = writtenPath(given);
  const auto cannot = [&](const char* what, int error) {
    throw std::runtime_error(path + ": cannot " + what + ": " + std::strerror(error));
  };
  // On any failure the temporary file goes with `file`.
  std::optional<TemporaryFile> file;
  try {
    file.emplace(folderOf(path), fileNameOf(path));
  } catch (const std::system_error& e) {
    cannot("create", e.code().value());
  }
  if (!writeAll(file->descriptor(), bytes) || !keepMode(file->descriptor(), path) || ::fsync(file->descriptor()) != 0)
    cannot("write", errno);
  try {
    file->replace(fileNameOf(path));
  } catch (const std::system_error& e) {
    cannot("rename into place", e.code().value());
  }
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

}  // namespace engine

#include "engine/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

namespace engine {

namespace {

namespace fs = std::filesystem;

// An open file descriptor, closed when it goes.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Whether a canonical path is the canonical `folder` or lies under it (whole components, so
// /models/a is not under /model).
bool liesIn(const fs::path& path, const std::string& folder) {
  const fs::path root(folder);
  return std::mismatch(root.begin(), root.end(), path.begin(), path.end()).first == root.end();
}

// Where `path` leads, every symbolic link followed (also one that leads to nothing, which
// std::filesystem::weakly_canonical leaves as it is, so that a link out of the folder is told
// apart from a missing file inside without asking whether its target exists); nothing after 40
// links (a loop) or when a link cannot be read.
std::optional<fs::path> whereLeads(const fs::path& path) {
  constexpr int kMaxLinks = 40;  // as the kernel's ELOOP
  std::vector<fs::path> parts;   // still to follow, the next one last
  const auto pushParts = [&](const fs::path& p) {
    const size_t next = parts.size();
    const fs::path relative = p.relative_path();
    parts.insert(parts.end(), relative.begin(), relative.end());
    std::reverse(parts.begin() + static_cast<std::ptrdiff_t>(next), parts.end());
  };
  std::error_code error;
  fs::path done = path.is_absolute() ? fs::path("/") : fs::current_path(error);
  if (error) return std::nullopt;
  pushParts(path);
  for (int links = 0; !parts.empty();) {
    const fs::path part = std::move(parts.back());
    parts.pop_back();
    if (part.empty() || part == ".") continue;
    if (part == "..") {
      done = done.parent_path();
      continue;
    }
    if (!fs::is_symlink(fs::symlink_status(done / part, error))) {
      done /= part;  // a file, a folder, or nothing there
      continue;
    }
    const fs::path target = fs::read_symlink(done / part, error);
    if (error || ++links > kMaxLinks) return std::nullopt;
    if (target.is_absolute()) done = "/";
    pushParts(target);
  }
  return done;
}

// Where an open descriptor leads, every symbolic link resolved (the kernel's own record, so it
// is the file that was opened, not whatever the path names now).
std::optional<fs::path> pathOf(const Descriptor& file) {
  std::error_code error;
  fs::path path = fs::read_symlink("/proc/self/fd/" + std::to_string(file.get()), error);
  if (error) return std::nullopt;
  return path;
}

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Reads exactly bytes.size() bytes.
template <class Bytes>
std::optional<FileRefusal> readAll(const Descriptor& file, Bytes& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(file.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return FileRefusal{Diag::FileUnreadable, std::strerror(errno)};
    if (n == 0) return FileRefusal{Diag::FileUnreadable, "it became shorter while read"};
    done += static_cast<size_t>(n);
  }
  return std::nullopt;
}

template <class Bytes>
std::variant<Bytes, FileRefusal> readChecked(const std::string& path, const FileLimits& limits) {
  const FileRefusal outside{Diag::UriOutsideFolder, ""};
  // A path that leads out of the folder is not even opened (opening some devices does
  // something); the check that counts is the one on what was opened, below.
  if (!limits.folder.empty()) {
    const std::optional<fs::path> leads = whereLeads(path);
    if (!leads || !liesIn(*leads, limits.folder)) return outside;
  }
  // Open first, then judge what was opened. O_NONBLOCK: a FIFO without a writer opens at once
  // instead of waiting; O_NOCTTY: a terminal does not become ours.
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (file.get() < 0) return FileRefusal{Diag::FileUnreadable, std::strerror(errno)};
  if (!limits.folder.empty()) {
    const std::optional<fs::path> opened = pathOf(file);
    if (!opened || !liesIn(*opened, limits.folder)) return outside;
  }
  struct stat status {};
  if (::fstat(file.get(), &status) != 0) return FileRefusal{Diag::FileUnreadable, std::strerror(errno)};
  if (!S_ISREG(status.st_mode)) return FileRefusal{Diag::NotRegularFile, kindOf(status.st_mode)};
  const auto size = static_cast<uint64_t>(status.st_size);
  if (size > kMaxInputFileBytes) return FileRefusal{Diag::FileTooLarge, std::to_string(size) + " bytes"};
  if (limits.exactBytes && size != *limits.exactBytes)
    return FileRefusal{Diag::WrongByteLength, std::to_string(size) + " bytes, byteLength says " + std::to_string(*limits.exactBytes)};
  Bytes bytes(static_cast<size_t>(size), 0);
  if (std::optional<FileRefusal> refusal = readAll(file, bytes)) return *refusal;
  return bytes;
}

}  // namespace

std::variant<std::string, FileRefusal> readRegularFile(const std::string& path, const FileLimits& limits) {
  return readChecked<std::string>(path, limits);
}

std::variant<std::vector<unsigned char>, FileRefusal> readRegularFileBytes(const std::string& path, const FileLimits& limits) {
  return readChecked<std::vector<unsigned char>>(path, limits);
}

std::string readInputFile(const std::string& path) {
  std::variant<std::string, FileRefusal> read = readRegularFile(path);
  if (const FileRefusal* refusal = std::get_if<FileRefusal>(&read)) throw SceneError(refusal->diag, path, "", refusal->detail);
  return std::get<std::string>(std::move(read));
}

}  // namespace engine

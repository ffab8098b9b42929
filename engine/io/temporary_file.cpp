#include "engine/io/temporary_file.h"

#include <cerrno>
#include <fcntl.h>
#include <random>
#include <system_error>
#include <unistd.h>

namespace engine {

namespace {

constexpr int kAttempts = 100;    // names tried before giving up (random ones collide with odds of 62^-12)
constexpr size_t kMaxStem = 200;  // keeps `.STEM.tmp-SUFFIX` within a file name's 255 bytes

[[noreturn]] void failWithErrno(const std::string& what) { throw std::system_error(errno, std::generic_category(), what); }

}  // namespace

std::string randomSuffix() {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device random;  // the kernel's getrandom
  std::string suffix(12, ' ');
  for (char& c : suffix) c = kAlphabet[random() % (sizeof kAlphabet - 1)];
  return suffix;
}

TemporaryFile::Descriptor::~Descriptor() {
  if (fd >= 0) ::close(fd);
}

TemporaryFile::TemporaryFile(const std::string& folder, const std::string& stem, bool unnamed, NameSuffixes suffixes)
    : stem_(stem.substr(0, kMaxStem)), suffixes_(std::move(suffixes)) {
  folder_.fd = ::open(folder.c_str(), O_DIRECTORY | O_RDONLY | O_CLOEXEC);
  if (folder_.fd < 0) failWithErrno(folder);
  if (unnamed) {
    file_.fd = ::openat(folder_.fd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (file_.fd >= 0) return;
    // Only a file system (or kernel) without O_TMPFILE falls back to a named file.
    if (errno != EOPNOTSUPP && errno != EISDIR) failWithErrno(folder);
  }
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const std::string name = nextName();
    file_.fd = ::openat(folder_.fd, name.c_str(), O_CREAT | O_EXCL | O_NOFOLLOW | O_WRONLY | O_CLOEXEC, 0666);
    if (file_.fd >= 0) {
      name_ = name;
      return;
    }
    if (errno != EEXIST) break;
  }
  failWithErrno(folder);
}

TemporaryFile::~TemporaryFile() {
  if (!name_.empty()) ::unlinkat(folder_.fd, name_.c_str(), 0);
}

std::string TemporaryFile::nextName() { return "." + stem_ + ".tmp-" + suffixes_(); }

void TemporaryFile::link() {
  const std::string self = "/proc/self/fd/" + std::to_string(file_.fd);
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const std::string name = nextName();
    // linkat neither follows nor replaces what a name already holds (EEXIST: the next name).
    // Without /proc, AT_EMPTY_PATH does the same for a process allowed to use it.
    if (::linkat(AT_FDCWD, self.c_str(), folder_.fd, name.c_str(), AT_SYMLINK_FOLLOW) == 0 ||
        (errno == ENOENT && ::linkat(file_.fd, "", folder_.fd, name.c_str(), AT_EMPTY_PATH) == 0)) {
      name_ = name;
      return;
    }
    if (errno != EEXIST) break;
  }
  failWithErrno("link");
}

void TemporaryFile::replace(const std::string& name) {
  if (name_.empty()) link();
  if (::renameat(folder_.fd, name_.c_str(), folder_.fd, name.c_str()) != 0) failWithErrno("rename");
  name_.clear();
  ::fsync(folder_.fd);  // the rename itself, to the disk; a file system that cannot has it anyway
}

}  // namespace engine

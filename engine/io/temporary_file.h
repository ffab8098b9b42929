// The temporary file behind writeFileAtomically (atomic_file.h): opened in the destination's
// folder so that no one else can have made, opened or named it, and renamed over the
// destination once written. Separate from atomic_file.h so that tests can choose its names.
#pragma once

#include <functional>
#include <string>
#include <sys/types.h>

namespace engine {

// Where the parts of a temporary file's name after its stem come from: tried in turn until one
// names nothing in the folder.
using NameSuffixes = std::function<std::string()>;

// 12 letters and digits from the system's random source, so a name cannot be planted ahead.
std::string randomSuffix();

class TemporaryFile {
 public:
  // Opens a new, empty file in `folder` for writing, with the mode a new file gets (0666 less
  // the umask): without a name (Linux's O_TMPFILE) where the file system allows and `unnamed`,
  // so that a process killed before replace() leaves nothing behind; else as
  // `folder/.STEM.tmp-SUFFIX`, created exclusively (O_EXCL | O_NOFOLLOW: a name taken by
  // anything, a symbolic link too, is never opened; the next suffix is tried). Throws
  // std::system_error naming what failed.
  TemporaryFile(const std::string& folder, const std::string& stem, bool unnamed = true,
                NameSuffixes suffixes = randomSuffix);
  ~TemporaryFile();  // closes the file and removes its name, unless replace() renamed it
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  int descriptor() const { return file_.fd; }

  // Makes the written file `name` in its folder (a file name, no '/'), replacing whatever is
  // there: an unnamed file is first linked at a fresh temporary name (never through or over
  // anything there), then renamed. Throws std::system_error; the temporary name is then gone.
  void replace(const std::string& name);

 private:
  // A file descriptor closed with its owner, so a constructor that throws leaks none.
  struct Descriptor {
    int fd = -1;
    Descriptor() = default;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor();
  };

  // `.STEM.tmp-SUFFIX` with the next suffix.
  std::string nextName();
  // Gives the unnamed file a fresh temporary name.
  void link();

  std::string stem_;
  NameSuffixes suffixes_;
  Descriptor folder_, file_;
  std::string name_;  // the temporary name in the folder, once it has one
};

}  // namespace engine

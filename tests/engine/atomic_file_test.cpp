// Atomic writes (engine/io/atomic_file.h): temporary files are created exclusively, never
// through a symbolic link planted where they might go, and leave nothing behind when a write
// fails or the writer is killed. Runs as root in CI, so failures are made with a file size
// limit rather than permissions.
#include "engine/io/atomic_file.h"
#include "engine/io/temporary_file.h"
#include "tests/engine/file_size_limit.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace engine {
namespace {

namespace fs = std::filesystem;

// An empty folder of its own for each test.
fs::path freshFolder(const std::string& name) {
  const fs::path folder = fs::path(WALKRAD_TEST_OUTPUT) / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string readAll(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::set<std::string> namesIn(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// Suffixes given in turn, as an attacker who knew them would plant links there.
NameSuffixes suffixes(std::vector<std::string> list) {
  return [list, next = size_t(0)]() mutable { return list.at(next++); };
}

void write(const TemporaryFile& file, const std::string& bytes) {
  ASSERT_EQ(::write(file.descriptor(), bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
}

TEST(AtomicFile, ALinkPlantedAtTheOldTemporaryNameIsNotFollowed) {
  const fs::path folder = freshFolder("atomic-old-name");
  std::ofstream(folder / "secret.txt") << "secret";
  fs::create_symlink("secret.txt", folder / ("out.txt.tmp." + std::to_string(::getpid())));
  writeFileAtomically((folder / "out.txt").string(), "written");
  EXPECT_EQ(readAll(folder / "secret.txt"), "secret");
  EXPECT_EQ(readAll(folder / "out.txt"), "written");
  EXPECT_FALSE(fs::is_symlink(folder / "out.txt"));
}

// Whether the file is nameless until written (O_TMPFILE, then linked) or made under a name
// (where the file system has no O_TMPFILE), a name taken by a link is passed over: the link's
// target is untouched and the link stays.
TEST(AtomicFile, ALinkPlantedAtATemporaryNameIsPassedOver) {
  for (const bool unnamed : {true, false}) {
    const fs::path folder = freshFolder(unnamed ? "atomic-planted-unnamed" : "atomic-planted-named");
    std::ofstream(folder / "secret.txt") << "secret";
    fs::create_symlink("secret.txt", folder / ".out.txt.tmp-planted");
    {
      TemporaryFile file(folder.string(), "out.txt", unnamed, suffixes({"planted", "free"}));
      write(file, "written");
      file.replace("out.txt");
    }
    EXPECT_EQ(readAll(folder / "secret.txt"), "secret") << "unnamed " << unnamed;
    EXPECT_EQ(readAll(folder / "out.txt"), "written");
    EXPECT_TRUE(fs::is_symlink(folder / ".out.txt.tmp-planted"));
    EXPECT_EQ(namesIn(folder), (std::set<std::string>{".out.txt.tmp-planted", "out.txt", "secret.txt"}));
  }
}

TEST(AtomicFile, ATemporaryFileNotRenamedIsRemoved) {
  for (const bool unnamed : {true, false}) {
    const fs::path folder = freshFolder("atomic-abandoned");
    {
      TemporaryFile file(folder.string(), "out.txt", unnamed);
      write(file, "half");
    }
    EXPECT_TRUE(namesIn(folder).empty()) << "unnamed " << unnamed;
  }
}

// A write that fails midway (the disk full), a rename that fails (a folder in the way) and a
// folder that is not there: the old file, if any, stays and no temporary is left.
TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path folder = freshFolder("atomic-failed");
  writeFileAtomically((folder / "keep.txt").string(), "old");
  {
    const test::FileSizeLimit full(1024);
    try {
      writeFileAtomically((folder / "keep.txt").string(), std::string(65536, 'x'));
      ADD_FAILURE() << "a write past the size limit succeeded";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), (folder / "keep.txt").string() + ": cannot write: File too large");
    }
  }
  EXPECT_EQ(readAll(folder / "keep.txt"), "old");
  fs::create_directories(folder / "a-folder" / "inside");
  EXPECT_THROW(writeFileAtomically((folder / "a-folder").string(), "new"), std::runtime_error);
  EXPECT_THROW(writeFileAtomically((folder / "missing" / "keep.txt").string(), "new"), std::runtime_error);
  EXPECT_EQ(namesIn(folder), (std::set<std::string>{"a-folder", "keep.txt"}));
}

// Killed while it writes (SIGKILL from the file size limit's signal, mid-write), the writer
// leaves the old file and no temporary: the file being written has no name yet.
TEST(AtomicFile, AWriterKilledMidWriteLeavesNothingBehind) {
  const fs::path folder = freshFolder("atomic-killed");
  const std::string path = (folder / "big.bin").string();
  writeFileAtomically(path, "old");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    rlimit limit{1 << 20, RLIM_INFINITY};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, [](int) { ::raise(SIGKILL); });
    writeFileAtomically(path, std::string(8 << 20, 'x'));
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_EQ(readAll(path), "old");
  EXPECT_EQ(namesIn(folder), std::set<std::string>{"big.bin"});
}

// A new file gets what the umask leaves of 0666, as any new file; a replaced one keeps its mode.
TEST(AtomicFile, PermissionsAreANewFilesOrTheReplacedOnes) {
  const fs::path folder = freshFolder("atomic-modes");
  const mode_t saved = ::umask(027);
  writeFileAtomically((folder / "new.txt").string(), "new");
  ::umask(saved);
  EXPECT_EQ(fs::status(folder / "new.txt").permissions(), fs::perms(0640));
  fs::permissions(folder / "new.txt", fs::perms(0705));
  writeFileAtomically((folder / "new.txt").string(), "replaced");
  EXPECT_EQ(fs::status(folder / "new.txt").permissions(), fs::perms(0705));
  EXPECT_EQ(readAll(folder / "new.txt"), "replaced");
}

}  // namespace
}  // namespace engine

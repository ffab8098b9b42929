// Hostile input for tests: files a stranger could send, made in a folder of their own (FIFOs,
// symbolic links, files too large to read, sparse so that they take no disk), a guard that turns
// a hang into a failure, and the refusal a load must end in.
#pragma once

#include "engine/diagnostics.h"
#include "tests/engine/gltf_writer.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace engine::test {

// A fresh folder under the system's temporary folder, removed with everything in it.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "walkrad-test-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) ADD_FAILURE() << "cannot make a temporary folder";
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  // The path of `name` inside the folder.
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

  // Writes `bytes` as `name` (its folders made) and returns its path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path path = path_ / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }

  std::string makeFolder(const std::string& name) const {
    std::filesystem::create_directories(path_ / name);
    return (path_ / name).string();
  }

  // A FIFO nobody writes to: a blocking open or read of it never returns.
  std::string makeFifo(const std::string& name) const {
    const std::string path = (path_ / name).string();
    if (::mkfifo(path.c_str(), 0600) != 0) ADD_FAILURE() << "cannot make the FIFO " << path;
    return path;
  }

  std::string makeLink(const std::string& name, const std::string& target) const {
    std::filesystem::create_symlink(target, path_ / name);
    return (path_ / name).string();
  }

  // A file of `size` bytes that takes no disk (a hole).
  std::string makeSparse(const std::string& name, uint64_t size) const {
    const std::string path = write(name, "");
    std::filesystem::resize_file(path, size);
    return path;
  }

 private:
  std::filesystem::path path_;
};

// While it lives, a test that hangs is killed (SIGALRM) after `seconds` instead of waiting for
// ever: what it guards reads a FIFO or a device, and must return at once.
class HangGuard {
 public:
  explicit HangGuard(unsigned seconds = 60) { ::alarm(seconds); }
  ~HangGuard() { ::alarm(0); }
  HangGuard(const HangGuard&) = delete;
  HangGuard& operator=(const HangGuard&) = delete;
};

// The diagnostic a load is refused with (and its message in `what`); a failure when it is not.
inline Diag refusalOf(const std::function<void()>& load, std::string* what = nullptr) {
  try {
    load();
  } catch (const SceneError& e) {
    if (what) *what = e.what();
    return e.diag();
  }
  ADD_FAILURE() << "accepted";
  return Diag::FileUnreadable;
}

// The smallest model that loads: a unit floor square of one material, "white".
inline GltfModel floorModel() {
  GltfPrimitive floor;
  floor.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  floor.indices = {0, 1, 2, 0, 2, 3};
  floor.material = 0;
  GltfModel m;
  m.nodes = {{"floor", {floor}, {}, {}, {}, {}, {}, -1}};
  m.roots = {0};
  m.materials = {{"white", {0.5, 0.5, 0.5, 1}, Vec3{0}, 0, ""}};
  return m;
}

}  // namespace engine::test

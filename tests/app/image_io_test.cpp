#include "app/image/image.h"
#include "engine/io/atomic_file.h"
#include "tests/app/image_read.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace app {
namespace {

const std::string kDir = WALKRAD_TEST_OUTPUT;

std::string readAll(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(ImageIo, PngRoundTrip) {
  ImageRgb8 image{3, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30, 40, 50, 60, 70, 80, 90}};
  writePng(kDir + "/roundtrip.png", image);
  const ImageRgb8 back = test::readPng(kDir + "/roundtrip.png");
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.pixels, image.pixels);
}

// Standard PFM: little-endian (negative scale) and the bottom row stored first.
TEST(ImageIo, PfmStoresTheBottomRowFirst) {
  ImageRgbF image{2, 2, {1, 2, 3, 4, 5, 6, /* bottom row: */ 7, 8, 9, 10, 11, 12}};
  const std::string path = kDir + "/rows.pfm";
  writePfm(path, image);
  const std::string bytes = readAll(path);
  ASSERT_EQ(bytes.rfind("PF\n2 2\n-1.0\n", 0), 0u);
  float first = 0;
  std::memcpy(&first, bytes.data() + std::string("PF\n2 2\n-1.0\n").size(), sizeof first);
  EXPECT_EQ(first, 7);
  EXPECT_EQ(test::readPfm(path).pixels, image.pixels);
}

TEST(ImageIo, RenamingOntoADirectoryFailsCleanly) {
  const std::string path = kDir + "/a-directory";
  std::filesystem::create_directories(path);
  EXPECT_THROW(writePng(path, ImageRgb8{1, 1, {0, 0, 0}}), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_directory(path));
}

// `--out` may name a link or a pipe (`/dev/stdout`): a link keeps pointing at the file it names,
// now with the new bytes, and a pipe stays a pipe whose reader gets them.
TEST(ImageIo, ALinkOrAPipeIsWrittenThroughNotReplaced) {
  const std::filesystem::path dir = std::filesystem::path(kDir) / "through";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  engine::writeFileAtomically((dir / "target.txt").string(), "old");
  std::filesystem::create_symlink("target.txt", dir / "link.txt");
  engine::writeFileAtomically((dir / "link.txt").string(), "new");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.txt"));
  EXPECT_EQ(readAll((dir / "target.txt").string()), "new");
  // A link to a file not there yet stays a link, and the file appears where it points.
  std::filesystem::create_symlink("later.txt", dir / "ahead.txt");
  engine::checkCanWrite((dir / "ahead.txt").string());
  engine::writeFileAtomically((dir / "ahead.txt").string(), "made");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "ahead.txt"));
  EXPECT_EQ(readAll((dir / "later.txt").string()), "made");
  // One pointing into a folder that is not there cannot be written: that is known up front.
  std::filesystem::create_symlink("no-such-folder/x.txt", dir / "nowhere.txt");
  EXPECT_THROW(engine::checkCanWrite((dir / "nowhere.txt").string()), std::runtime_error);

  const std::string pipe = (dir / "pipe").string();
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  // The reader's end is open first (without waiting for a writer), so the write neither blocks
  // nor, were the pipe replaced, leaves anyone waiting.
  const int reader = ::open(pipe.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  engine::writeFileAtomically(pipe, "through the pipe");
  char buffer[64] = {};
  const ssize_t got = ::read(reader, buffer, sizeof buffer);
  ::close(reader);
  EXPECT_EQ(std::string(buffer, got > 0 ? static_cast<size_t>(got) : 0), "through the pipe");
  EXPECT_EQ(std::filesystem::status(pipe).type(), std::filesystem::file_type::fifo);
}

TEST(ImageIo, ReadingGarbageThrows) {
  engine::writeFileAtomically(kDir + "/garbage.png", "not a png");
  EXPECT_THROW(test::readPng(kDir + "/garbage.png"), std::runtime_error);
  EXPECT_THROW(test::readPfm(kDir + "/garbage.png"), std::runtime_error);
}

}  // namespace
}  // namespace app

// Input files a stranger could send (scenes, sidecars, polygon cases, glTF models) are read only
// when they are regular files of a bounded size: a FIFO, a device or a folder is refused at once,
// never read or waited on.
#include "engine/io/input_file.h"

#include "engine/io/gltf_loader.h"
#include "engine/io/load_scene.h"
#include "tests/engine/hostile_input.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

TEST(InputFile, ARegularFileIsReadWhole) {
  test::TempFolder dir;
  const std::string bytes("two\0lines\n", 10);
  const std::string path = dir.write("bytes.bin", bytes);
  EXPECT_EQ(readInputFile(path), bytes);
  const auto read = readRegularFileBytes(path);
  ASSERT_TRUE(std::holds_alternative<std::vector<unsigned char>>(read));
  EXPECT_EQ(std::get<std::vector<unsigned char>>(read), std::vector<unsigned char>(bytes.begin(), bytes.end()));
}

// A FIFO without a writer would block a plain open for ever: as a scene file, a sidecar named
// on the command line or one found beside its model, it is refused at once.
TEST(InputFile, AFifoIsRefusedWithoutWaiting) {
  test::TempFolder dir;
  const test::HangGuard guard;
  std::string what;
  const std::string scene = dir.makeFifo("scene.json");
  EXPECT_EQ(test::refusalOf([&] { loadScene(scene); }, &what), Diag::NotRegularFile);
  EXPECT_EQ(what, scene + ": not a regular file: a FIFO (named pipe)");
  const std::string model = dir.write("model.gltf", test::gltfText(test::floorModel()));
  const std::string sidecar = dir.makeFifo("lights.walkrad.json");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model, {"", sidecar}); }, &what), Diag::NotRegularFile);
  EXPECT_EQ(what.rfind(sidecar + ": ", 0), 0u) << what;
  dir.makeFifo("model.walkrad.json");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(model); }, &what), Diag::NotRegularFile);
  EXPECT_EQ(what.rfind(dir / "model.walkrad.json: ", 0), 0u) << what;
}

// /dev/zero never ends: it is refused unread, as any device.
TEST(InputFile, ADeviceIsRefusedUnread) {
  const test::HangGuard guard;
  std::string what;
  EXPECT_EQ(test::refusalOf([&] { loadScene("/dev/zero"); }, &what), Diag::NotRegularFile);
  EXPECT_EQ(what, "/dev/zero: not a regular file: a device");
}

TEST(InputFile, AFolderIsRefused) {
  test::TempFolder dir;
  std::string what;
  const std::string folder = dir.makeFolder("scene.json");
  EXPECT_EQ(test::refusalOf([&] { loadScene(folder); }, &what), Diag::NotRegularFile);
  EXPECT_EQ(what, folder + ": not a regular file: a folder");
}

// The size is judged before anything is read: a sparse file over the limit takes no memory.
TEST(InputFile, AFileOverTheLimitIsRefusedUnread) {
  test::TempFolder dir;
  std::string what;
  const std::string huge = dir.makeSparse("huge.json", kMaxInputFileBytes + 1);
  EXPECT_EQ(test::refusalOf([&] { loadScene(huge); }, &what), Diag::FileTooLarge);
  EXPECT_EQ(what, huge + ": file larger than walkrad reads (1 GiB): 1073741825 bytes");
  EXPECT_EQ(test::refusalOf([&] { loadGltf(dir.makeSparse("huge.glb", kMaxInputFileBytes + 1)); }), Diag::FileTooLarge);
}

TEST(InputFile, ASizeOtherThanTheExpectedIsRefusedUnread) {
  test::TempFolder dir;
  const std::string path = dir.write("twelve.bin", "twelve bytes");
  const auto read = readRegularFileBytes(path, {"", 16});
  ASSERT_TRUE(std::holds_alternative<FileRefusal>(read));
  EXPECT_EQ(std::get<FileRefusal>(read).diag, Diag::WrongByteLength);
  EXPECT_EQ(std::get<FileRefusal>(read).detail, "12 bytes, byteLength says 16");
  EXPECT_TRUE(std::holds_alternative<std::vector<unsigned char>>(readRegularFileBytes(path, {"", 12})));
}

// Confined to a folder, whatever lies outside it (a file, a missing file, a FIFO, a device, a
// folder, what a link leads to or would lead to) gets one answer that tells nothing about it;
// inside, a symbolic link to a file inside is followed.
TEST(InputFile, OutsideItsFolderEveryFileIsRefusedAlike) {
  test::TempFolder dir;
  const test::HangGuard guard;
  const std::string folder = std::filesystem::canonical(dir.makeFolder("model")).string();
  dir.write("secret.bin", "secret");
  dir.makeFifo("pipe");
  dir.write("model/inside.bin", "inside");
  dir.makeLink("model/link-inside.bin", "inside.bin");
  for (const std::string& outside : {dir / "secret.bin", dir / "missing.bin", dir / "pipe", std::string("/dev/zero"), dir / "",
                                     dir.makeLink("model/link.bin", "../secret.bin"), dir.makeLink("model/up", ".."),
                                     dir.makeLink("model/dangling.bin", "../missing.bin"),
                                     dir / "model/up/secret.bin", dir / "model/../secret.bin"}) {
    const auto read = readRegularFile(outside, {folder, std::nullopt});
    ASSERT_TRUE(std::holds_alternative<FileRefusal>(read)) << outside;
    EXPECT_EQ(std::get<FileRefusal>(read).diag, Diag::UriOutsideFolder) << outside;
    EXPECT_EQ(std::get<FileRefusal>(read).detail, "") << outside;
  }
  for (const char* inside : {"model/inside.bin", "model/link-inside.bin", "model/up/model/inside.bin"}) {
    const auto read = readRegularFile(dir / inside, {folder, std::nullopt});
    ASSERT_TRUE(std::holds_alternative<std::string>(read)) << inside;
    EXPECT_EQ(std::get<std::string>(read), "inside");
  }
  const auto missing = readRegularFile(dir.makeLink("model/dangling-inside.bin", "missing.bin"), {folder, std::nullopt});
  ASSERT_TRUE(std::holds_alternative<FileRefusal>(missing));
  EXPECT_EQ(std::get<FileRefusal>(missing).diag, Diag::FileUnreadable);
}

}  // namespace
}  // namespace engine

// The files a glTF model names are read only from the model's folder, only when they are regular
// files of the size the model declares: every other URI is refused, naming it and saying why,
// in .gltf and .glb alike, for buffers and images.
#include "engine/io/gltf_loader.h"

#include "engine/io/input_file.h"
#include "tests/engine/hostile_input.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>

namespace engine {
namespace {

using test::floorModel;
using test::HangGuard;
using test::refusalOf;
using test::TempFolder;


// The floor's buffer bytes (as a .bin beside a model would hold them).
std::string floorBuffer() {
  const std::string glb = test::glbBytes(floorModel());
  const size_t length = nlohmann::json::parse(test::gltfText(floorModel()))["buffers"][0]["byteLength"];
  return glb.substr(glb.size() - length);
}

// The floor's JSON with its buffer at `uri`.
nlohmann::json floorNaming(const std::string& uri) {
  nlohmann::json j = nlohmann::json::parse(test::gltfText(floorModel()));
  j["buffers"][0]["uri"] = uri;
  return j;
}

// A .glb of JSON alone (its buffers named by URI).
std::string glbOf(const nlohmann::json& j) {
  std::string json = j.dump();
  while (json.size() % 4) json += ' ';
  const auto u32 = [](uint32_t v) {
    char bytes[4];
    std::memcpy(bytes, &v, 4);
    return std::string(bytes, 4);
  };
  return "glTF" + u32(2) + u32(static_cast<uint32_t>(20 + json.size())) + u32(static_cast<uint32_t>(json.size())) + "JSON" + json;
}


// A model folder with a buffer in a subfolder, and beside it (outside) a secret of the same size.
class GltfUris : public ::testing::Test {
 protected:
  GltfUris() {
    dir.write("secret/secret.bin", floorBuffer());
    dir.write("model/sub/buffer.bin", floorBuffer());
  }

  // Loads the floor with its buffer at `uri`, as `model` (a .gltf or .glb in the model folder).
  Scene load(const std::string& uri, const std::string& model = "model.gltf") const {
    const nlohmann::json j = floorNaming(uri);
    const bool glb = model.ends_with(".glb");
    return loadGltf(dir.write("model/" + model, glb ? glbOf(j) : j.dump()));
  }

  // Expects the floor with its buffer at `uri` refused with `diag`, in one line that names the
  // model, the buffer's URI and its place.
  void expectRefused(const std::string& uri, Diag diag) const {
    for (const char* model : {"model.gltf", "model.glb"}) {
      std::string what;
      EXPECT_EQ(refusalOf([&] { load(uri, model); }, &what), diag) << uri << " in " << model << ": " << what;
      EXPECT_EQ(what.rfind(dir / "model/" + model + ": buffers[0].uri: " + describe(diag) + ": \"" + uri + "\"", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }

  TempFolder dir;
};

TEST_F(GltfUris, ARelativeUriInTheModelsFolderLoads) {
  dir.makeLink("model/inner.bin", "sub/buffer.bin");
  for (const char* uri : {"sub/buffer.bin", "./sub/buffer.bin", "sub/../sub/buffer.bin", "sub%2Fbuffer.bin", "inner.bin"})
    for (const char* model : {"model.gltf", "model.glb"}) {
      const Scene scene = load(uri, model);
      ASSERT_EQ(scene.surfaces.size(), 1u) << uri << " in " << model;
      EXPECT_NEAR(scene.surfaces[0].area, 1, 1e-9);
    }
}

TEST_F(GltfUris, DotDotOutOfTheFolderIsRefused) {
  for (const char* uri : {"../secret/secret.bin", "sub/../../secret/secret.bin", "%2E%2E/secret/secret.bin", "../model/../secret/x.bin"})
    expectRefused(uri, Diag::UriOutsideFolder);
}

// An absolute URI is refused by its name alone: the message is the same whether the file is
// there or not, and says nothing of its size.
TEST_F(GltfUris, AnAbsolutePathIsRefusedTellingNothingOfTheFile) {
  expectRefused("/etc/shadow", Diag::UriAbsolute);
  std::string there, missing;
  const std::string secret = dir / "secret/secret.bin";
  refusalOf([&] { load(secret); }, &there);
  refusalOf([&] { load(dir / "secret/missing.bin"); }, &missing);
  EXPECT_EQ(there, dir / "model/model.gltf: buffers[0].uri: " + describe(Diag::UriAbsolute) + ": \"" + secret + "\"");
  EXPECT_EQ(missing, dir / "model/model.gltf: buffers[0].uri: " + describe(Diag::UriAbsolute) + ": \"" + dir / "secret/missing.bin\"");
  expectRefused("%2Fetc%2Fshadow", Diag::UriAbsolute);
}

// Links are judged by where they lead: to a file, to a folder on the way, to a device.
TEST_F(GltfUris, ASymbolicLinkOutOfTheFolderIsRefused) {
  dir.makeLink("model/link.bin", dir / "secret/secret.bin");
  dir.makeLink("model/linked", "../secret");
  dir.makeLink("model/zero", "/dev/zero");
  const HangGuard guard;
  for (const char* uri : {"link.bin", "linked/secret.bin", "zero"}) expectRefused(uri, Diag::UriOutsideFolder);
}

// A FIFO nobody writes to is refused at once (a blocking open would wait for ever).
TEST_F(GltfUris, AFifoIsRefusedWithoutWaiting) {
  dir.makeFifo("model/pipe.bin");
  const HangGuard guard;
  expectRefused("pipe.bin", Diag::NotRegularFile);
}

// A device in the model's own folder (a model in /dev) is refused unread: /dev/zero never ends.
TEST_F(GltfUris, ADeviceIsRefusedUnread) {
  const HangGuard guard;
  std::string what;
  EXPECT_EQ(refusalOf([&] { parseGltf(floorNaming("zero").dump(), "/dev/model.gltf"); }, &what), Diag::NotRegularFile);
  EXPECT_EQ(what, "/dev/model.gltf: buffers[0].uri: not a regular file: \"zero\": a device");
}

TEST_F(GltfUris, AFolderIsRefused) {
  for (const char* uri : {"sub", ".", "sub/"}) expectRefused(uri, Diag::NotRegularFile);
}

// Sizes are judged before reading: against the limit (a sparse file takes no memory), then
// against the buffer's byteLength.
TEST_F(GltfUris, ASizeOverTheLimitOrOtherThanTheBuffersIsRefused) {
  dir.makeSparse("model/huge.bin", kMaxInputFileBytes + 1);
  expectRefused("huge.bin", Diag::FileTooLarge);
  dir.write("model/short.bin", floorBuffer().substr(0, 20));
  expectRefused("short.bin", Diag::WrongByteLength);
  expectRefused("missing.bin", Diag::FileUnreadable);
}

// A buffer's data: URI must decode to its byteLength, and be one tinygltf decodes; the message
// quotes only the start of a long one.
TEST_F(GltfUris, ADataUriOfTheWrongLengthIsRefused) {
  nlohmann::json j = nlohmann::json::parse(test::gltfText(floorModel()));
  const size_t length = j["buffers"][0]["byteLength"];
  j["buffers"][0]["byteLength"] = length + 4;
  std::string what;
  EXPECT_EQ(refusalOf([&] { parseGltf(j.dump(), "long.gltf"); }, &what), Diag::WrongByteLength);
  EXPECT_EQ(what.rfind("long.gltf: buffers[0].uri: " + std::string(describe(Diag::WrongByteLength)) + ": \"data:application/octet-stream;base64,", 0), 0u) << what;
  EXPECT_NE(what.find("...\": decodes to " + std::to_string(length) + " bytes, byteLength says " + std::to_string(length + 4)), std::string::npos) << what;
  j = nlohmann::json::parse(test::gltfText(floorModel()));
  const std::string uri = j["buffers"][0]["uri"];
  j["buffers"][0]["uri"] = uri.substr(0, uri.size() - 8);  // 8 base64 digits are 6 bytes
  EXPECT_EQ(refusalOf([&] { parseGltf(j.dump(), "cut.gltf"); }, &what), Diag::WrongByteLength);
  EXPECT_NE(what.find("decodes to " + std::to_string(length - 6) + " bytes, byteLength says " + std::to_string(length)), std::string::npos) << what;
  j["buffers"][0]["uri"] = "data:application/json;base64,e30=";
  EXPECT_EQ(refusalOf([&] { parseGltf(j.dump(), "json.gltf"); }, &what), Diag::NotGltf);
  EXPECT_EQ(what.rfind("json.gltf: buffers[0].uri: ", 0), 0u) << what;
}

// Images are confined as buffers are; one that is not there leaves its texture white.
TEST_F(GltfUris, ImagesAreConfinedAsBuffersAre) {
  dir.write("secret/secret.bmp", "BM");
  dir.makeFifo("model/pipe.bmp");
  const HangGuard guard;
  const auto modelWithImage = [&](const std::string& uri) {
    test::GltfModel m = floorModel();
    m.materials[0].baseColorImage = uri;
    return dir.write("model/textured.gltf", test::gltfText(m));
  };
  const std::pair<const char*, Diag> cases[] = {
      {"../secret/secret.bmp", Diag::UriOutsideFolder}, {"/etc/shadow", Diag::UriAbsolute}, {"pipe.bmp", Diag::NotRegularFile}};
  for (const auto& [uriText, diag] : cases) {
    const std::string uri = uriText;  // clang 14 lambdas take no structured bindings
    std::string what;
    EXPECT_EQ(refusalOf([&] { loadGltf(modelWithImage(uri)); }, &what), diag) << uri;
    EXPECT_EQ(what.rfind(dir / "model/textured.gltf: images[0].uri: ", 0), 0u) << what;
  }
  EXPECT_NEAR(loadGltf(modelWithImage("missing.bmp")).materials[0].reflectance.r, 0.5, 1e-12);
}

}  // namespace
}  // namespace engine

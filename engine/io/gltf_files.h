// The files a glTF model names (its buffers' and images' URIs), read before tinygltf parses the
// model and confined to the model's folder, so that a model a stranger sends cannot make walkrad
// read (and `walkrad export` write back out) any other file, nor hang on a FIFO.
//
// A URI is percent-decoded as tinygltf decodes it, then refused before anything is opened when it
// is an absolute path or climbs out of the folder with `..`; what it names is then opened
// without blocking and refused when, symbolic links resolved, it lies outside the model's folder,
// or is not a regular file, or is larger than kMaxInputFileBytes (input_file.h), or (a buffer)
// is not its byteLength long. A buffer's data: URI must decode to byteLength bytes.
// tinygltf then gets the files through callbacks that never touch the disk.
#pragma once

#include <tiny_gltf.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

class GltfFiles {
 public:
  // Reads the files that `model` (.gltf text or .glb bytes) names, beside `file`. Throws
  // SceneError naming `file`, the URI's JSON path (buffers[N].uri, images[N].uri) and the URI:
  // UriAbsolute, UriOutsideFolder, NotRegularFile, FileTooLarge, WrongByteLength, or
  // FileUnreadable for a buffer's file that cannot be read. An image file that cannot be read
  // is left out: tinygltf warns and its texture counts as white.
  GltfFiles(std::string_view model, const std::string& file);
  GltfFiles(const GltfFiles&) = delete;
  GltfFiles& operator=(const GltfFiles&) = delete;

  // For tinygltf::TinyGLTF::SetFsCallbacks, with "" as the loader's base folder: the files read
  // above, by their decoded URIs, and nothing else. They point at this object.
  tinygltf::FsCallbacks callbacks();

 private:
  struct File {
    std::vector<unsigned char> bytes;
    size_t uses = 0;  // URIs naming it not yet served: the last one takes the bytes
  };

  static bool exists(const std::string& path, void* self);
  static bool read(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* self);

  std::map<std::string, File> files_;  // by decoded URI
};

}  // namespace engine

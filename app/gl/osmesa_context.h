// An offscreen GL 3.3 core context in main memory (Mesa's OSMesa with llvmpipe). Kept apart
// from glad because <GL/osmesa.h> pulls in <GL/gl.h>.
#pragma once

#include <memory>

namespace app {

class OsmesaContext {
 public:
  // Creates the context and makes it current with a width x height RGBA buffer. Throws
  // std::runtime_error when OSMesa cannot give a 3.3 core context.
  OsmesaContext(int width, int height);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  // For gladLoadGL: OSMesa's function lookup.
  using Proc = void (*)();
  static Proc procAddress(const char* name);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace app

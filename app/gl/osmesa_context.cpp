#include "app/gl/osmesa_context.h"

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

namespace app {

struct OsmesaContext::State {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;
};

OsmesaContext::OsmesaContext(int width, int height) : state_(std::make_unique<State>()) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                            OSMESA_STENCIL_BITS, 8, OSMESA_ACCUM_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  state_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!state_->context) throw std::runtime_error("OSMesa could not create a GL 3.3 core context");
  state_->buffer.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  if (!OSMesaMakeCurrent(state_->context, state_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(state_->context);
    throw std::runtime_error("OSMesa could not make its context current");
  }
}

OsmesaContext::~OsmesaContext() { OSMesaDestroyContext(state_->context); }

OsmesaContext::Proc OsmesaContext::procAddress(const char* name) { return OSMesaGetProcAddress(name); }

}  // namespace app

#include "app/gl/headless_render.h"

#include "app/gl/osmesa_context.h"

#include <stdexcept>

namespace app {

HeadlessImages renderHeadless(const engine::Scene& scene, const engine::DisplayMesh& mesh,
                              const engine::ViewCamera& camera, int width, int height, float exposure,
                              bool wireframe, bool wantLinear) {
  const OsmesaContext context(width, height);
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(&OsmesaContext::procAddress)))
    throw std::runtime_error("could not load GL functions from OSMesa");

  SceneRenderer renderer;
  renderer.upload(mesh);
  FrameSettings frame;
  frame.clipFromDisplay = engine::clipFromDisplay(camera, static_cast<double>(width) / height, scene, mesh.origin);
  frame.width = width;
  frame.height = height;
  frame.exposure = exposure;
  frame.wireframe = wireframe;

  HeadlessImages images;
  if (wantLinear) images.linear = renderer.drawLinear(mesh, frame);
  renderer.draw(mesh, frame);
  glFinish();
  images.color = readFramebuffer(width, height, GL_FRONT);
  return images;
}

}  // namespace app

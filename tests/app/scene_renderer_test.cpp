// The renderer's chunks on pixels (OSMesa): culling, per-object transforms and per-surface
// uploads draw what drawing everything anew draws.
#include "app/gl/osmesa_context.h"
#include "app/gl/scene_renderer.h"
#include "engine/document/display_mesh.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/geometry/solid_surfaces.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"
#include "engine/session/view_camera.h"
#include "tests/app/pixel_probe.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <stdexcept>

namespace app {
namespace {

constexpr int kWidth = 320, kHeight = 240;

// A current context for the test, its functions loaded.
struct Context {
  OsmesaContext osmesa{kWidth, kHeight};
  Context() {
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(&OsmesaContext::procAddress))) throw std::runtime_error("no GL");
  }
};

ImageRgb8 drawn(SceneRenderer& renderer, const engine::DisplayMesh& mesh, const FrameSettings& frame) {
  renderer.draw(mesh, frame);
  glFinish();
  return readFramebuffer(frame.width, frame.height, GL_FRONT);
}

FrameSettings frameFor(const engine::Scene& scene, const engine::DisplayMesh& mesh) {
  engine::ViewCamera camera;
  EXPECT_TRUE(engine::chooseCamera(scene, "", camera));
  FrameSettings frame;
  frame.clipFromDisplay = engine::clipFromDisplay(camera, static_cast<double>(kWidth) / kHeight, scene, mesh.origin);
  frame.width = kWidth;
  frame.height = kHeight;
  frame.exposure = static_cast<float>(engine::autoExposure(mesh));
  return frame;
}

// A 2 x 2 square facing +z at depth z, of its own object, with radiance 1.
engine::SurfaceDisplay square(uint32_t object, float z) {
  engine::SurfaceDisplay s;
  s.object = object;
  s.positions = {{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}};
  s.radiance.assign(4, glm::vec3{1});
  s.area.assign(4, 1);
  s.triangles = {0, 1, 2, 0, 2, 3};
  s.edges = {0, 1, 1, 2, 2, 3, 0, 3};
  s.elements = s.quads = 1;
  return s;
}

// A camera at the origin looking down -z: the square ahead is drawn, the one behind is culled
// (counted, not drawn), and moved ahead by its object's transform it is drawn.
TEST(SceneRenderer, ChunksOutsideTheViewAreNotDrawn) {
  const Context context;
  engine::DisplayMesh mesh;
  mesh.surfaces = {square(0, -5), square(1, 5)};
  SceneRenderer renderer;
  renderer.upload(mesh);
  ASSERT_EQ(renderer.chunkCount(), 2u);
  FrameSettings frame;
  frame.width = kWidth;
  frame.height = kHeight;
  frame.clipFromDisplay = glm::perspective(glm::radians(60.0f), static_cast<float>(kWidth) / kHeight, 0.1f, 100.0f) *
                          glm::lookAt(glm::vec3{0}, glm::vec3{0, 0, -1}, glm::vec3{0, 1, 0});
  const ImageRgb8 image = drawn(renderer, mesh, frame);
  EXPECT_EQ(renderer.lastFrame().chunksDrawn, 1u);
  EXPECT_EQ(renderer.lastFrame().chunksCulled, 1u);
  EXPECT_GT(test::meanColor(image, 0.45, 0.55, 0.45, 0.55).r, 250);  // the square ahead, white

  renderer.setObjectTransform(1, glm::translate(glm::mat4{1}, glm::vec3{0, 0, -8}));
  drawn(renderer, mesh, frame);
  EXPECT_EQ(renderer.lastFrame().chunksDrawn, 2u);
  EXPECT_EQ(renderer.lastFrame().chunksCulled, 0u);
}

// A room and a red box floating in it (nothing rests on anything, so a move remeshes nothing).
constexpr const char* kFloatingBox = R"({
  "format": "walkrad-scene/1", "units": "m", "settings": { "patch_size": 0.5 },
  "materials": { "white": { "reflectance": [0.6, 0.6, 0.6] }, "red": { "reflectance": [0.8, 0.1, 0.1] },
                 "lamp": { "reflectance": [0.5, 0.5, 0.5], "emission": [8, 8, 8] } },
  "objects": [
    { "name": "room", "movable": false,
      "solids": [ { "profile": [[0, 0], [4, 0], [4, 3], [0, 3]], "from": 0, "to": 2.5, "inward": true, "material": "white",
                    "faces": { "top": { "holes": [ { "polygon": [[1.5, 1], [2.5, 1], [2.5, 2], [1.5, 2]], "fill": "lamp" } ] } } } ] },
    { "name": "box",
      "solids": [ { "profile": [[1.2, 1.3], [2.1, 1.3], [2.1, 2.2], [1.2, 2.2]], "from": 0.4, "to": 1.0, "material": "red" } ] }
  ],
  "cameras": { "default": { "position": [2.6, 1.6, 0.2], "look_at": [1.65, 0.6, 1.6], "fov_y": 55 } }
})";

// The box moved (0.6 m along x, 0.3 m up, turned 30 degrees) by its object's transform alone
// gives the picture of the box's vertices moved. llvmpipe draws the two the same to the pixel
// today; the bounds leave room for pixels on the box's edges, where vertices moved in double and
// then rounded, and vertices moved by a float transform, may round apart.
TEST(SceneRenderer, AnObjectTransformMovesThePictureAsMovingTheVerticesDoes) {
  const Context context;
  const engine::Scene loaded = engine::parseScene(kFloatingBox, "floating-box.json");
  engine::SceneEditor editor(loaded, engine::meshScene(loaded));
  engine::DisplayMesh before = engine::displayMesh(editor.scene(), editor.meshed());
  engine::shadeWithAmbient(editor.scene(), before);
  const uint32_t box = *editor.findObject("box");
  const engine::Object home = editor.scene().objects[box];
  engine::Object moved = home;
  moved.position += engine::Vec3{0.6, 0.3, 0};
  moved.rotateYDeg += 30;
  ASSERT_TRUE(editor.setPose(box, engine::poseOf(moved)));
  ASSERT_TRUE(editor.remeshed().empty());
  engine::DisplayMesh after = engine::displayMesh(editor.scene(), editor.meshed(), before.origin);
  engine::shadeWithAmbient(editor.scene(), after);
  const FrameSettings frame = frameFor(editor.scene(), before);

  SceneRenderer byVertices;
  byVertices.upload(after);
  const ImageRgb8 expected = drawn(byVertices, after, frame);

  // World from world: the box's placement now after its placement as loaded undone; in display
  // coordinates, about the display's origin.
  const engine::Placement from = engine::placementOf(home), to = engine::placementOf(moved);
  const glm::dmat3 turn = to.worldFromObject * glm::transpose(from.worldFromObject);
  const glm::dmat4 displayFromObjectDisplay = glm::translate(glm::dmat4{1}, to.translation - before.origin) * glm::dmat4(turn) *
                                              glm::translate(glm::dmat4{1}, before.origin - from.translation);
  SceneRenderer byTransform;
  byTransform.upload(before);
  const ImageRgb8 unmoved = drawn(byTransform, before, frame);
  byTransform.setObjectTransform(box, glm::mat4(displayFromObjectDisplay));
  const ImageRgb8 image = drawn(byTransform, before, frame);

  EXPECT_GT(test::difference(unmoved, expected, 8).shareBeyond, 0.02);  // the move shows
  const test::ImageDifference d = test::difference(image, expected, 8);
  EXPECT_LT(d.meanLevels, 0.1);
  EXPECT_LT(d.shareBeyond, 0.001);  // at most 76 pixels
}

// A chair lifted off the office floor: the floor is meshed again (more vertices where its
// footprint went) and the chair moves. Uploading only the chunks of the surfaces that changed
// draws what uploading the whole display anew draws, pixel for pixel, and the radiance of the
// new vertex counts is taken after.
TEST(SceneRenderer, UpdatingTheChangedSurfacesDrawsWhatUploadingAnewDraws) {
  const Context context;
  const engine::Scene loaded = engine::loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  engine::SceneEditor editor(loaded, engine::meshScene(loaded));
  engine::DisplayMesh mesh = engine::displayMesh(editor.scene(), editor.meshed());
  engine::shadeWithAmbient(editor.scene(), mesh);
  SceneRenderer updated;
  updated.upload(mesh);

  const uint32_t chair = *editor.findObject("chair");
  engine::ObjectPose pose = engine::poseOf(editor.scene().objects[chair]);
  pose.position += engine::Vec3{-0.3, 0.4, 0.2};
  ASSERT_TRUE(editor.setPose(chair, pose));
  ASSERT_FALSE(editor.remeshed().empty());
  std::vector<uint32_t> changed;
  for (const engine::EditedSurface& e : editor.takeEdited()) {
    const uint32_t object = editor.scene().surfaces[e.surface].object;
    engine::replaceSurface(mesh, e.surface, engine::surfaceDisplay(editor.meshed().surfaces[e.surface], object, engine::displayFromWorld(mesh), engine::surfaceOutline(editor.meshed().surfaces[e.surface])));
    changed.push_back(e.surface);
  }
  engine::shadeWithAmbient(editor.scene(), mesh);
  EXPECT_THROW(updated.updateRadiance(mesh), std::invalid_argument);  // the floor's vertices are not those uploaded
  updated.updateSurfaces(mesh, changed);
  updated.updateRadiance(mesh);
  const FrameSettings frame = frameFor(editor.scene(), mesh);
  const ImageRgb8 image = drawn(updated, mesh, frame);

  SceneRenderer anew;
  anew.upload(mesh);
  const ImageRgb8 expected = drawn(anew, mesh, frame);
  EXPECT_EQ(image.pixels, expected.pixels);
}

// Uploads `mesh` (objects 0 and 1 at the same place) with object 0 moved left and object 1 right,
// and returns a frame that looks at both.
FrameSettings sideBySide(SceneRenderer& renderer, const engine::DisplayMesh& mesh) {
  renderer.upload(mesh);
  renderer.setObjectTransform(0, glm::translate(glm::mat4{1}, glm::vec3{-1.5f, 0, 0}));
  renderer.setObjectTransform(1, glm::translate(glm::mat4{1}, glm::vec3{1.5f, 0, 0}));
  FrameSettings frame;
  frame.width = kWidth;
  frame.height = kHeight;
  frame.clipFromDisplay = glm::perspective(glm::radians(60.0f), static_cast<float>(kWidth) / kHeight, 0.1f, 100.0f) *
                          glm::lookAt(glm::vec3{0}, glm::vec3{0, 0, -1}, glm::vec3{0, 1, 0});
  return frame;
}

// The selected object's edges are drawn in the highlight colour, and no other's.
TEST(SceneRenderer, TheSelectedObjectIsHighlighted) {
  const Context context;
  engine::DisplayMesh mesh;
  mesh.surfaces = {square(0, -5), square(1, -5)};
  for (glm::vec3& r : mesh.surfaces[0].radiance) r = glm::vec3{0};
  for (glm::vec3& r : mesh.surfaces[1].radiance) r = glm::vec3{0};
  SceneRenderer renderer;
  FrameSettings frame = sideBySide(renderer, mesh);
  frame.highlight = 1;
  const ImageRgb8 image = drawn(renderer, mesh, frame);
  // The highlight is orange (1, 0.8, 0.1); the left square (object 0) has no edges drawn.
  auto orangePixels = [&](double x0, double x1) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = static_cast<int>(x0 * image.width); x < static_cast<int>(x1 * image.width); ++x) {
        const uint8_t* p = &image.pixels[(static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x)) * 3];
        n += p[0] > 200 && p[1] > 150 && p[2] < 120;
      }
    return n;
  };
  EXPECT_EQ(orangePixels(0, 0.5), 0u);
  EXPECT_GT(orangePixels(0.5, 1), 100u);
}

// A chunk's element edges are uploaded when first drawn, once until its chunk is filled again:
// not for frames without the wireframe, for the selected object's chunk alone when it is
// highlighted. Drawn after an update, they are the updated surface's.
TEST(SceneRenderer, EdgesAreUploadedWhenFirstDrawn) {
  const Context context;
  engine::DisplayMesh mesh;
  mesh.surfaces = {square(0, -5), square(1, -5)};
  SceneRenderer renderer;
  FrameSettings frame = sideBySide(renderer, mesh);
  drawn(renderer, mesh, frame);
  EXPECT_EQ(renderer.edgeUploads(), 0u);
  frame.highlight = 1;
  drawn(renderer, mesh, frame);
  drawn(renderer, mesh, frame);
  EXPECT_EQ(renderer.edgeUploads(), 1u);
  frame.wireframe = true;
  drawn(renderer, mesh, frame);
  EXPECT_EQ(renderer.edgeUploads(), 2u);

  // Object 1's square made a triangle: its edges drawn again are the triangle's.
  mesh.surfaces[1].triangles = {0, 1, 2};
  mesh.surfaces[1].edges = {0, 1, 1, 2, 0, 2};
  const std::vector<uint32_t> changed{1};
  renderer.updateSurfaces(mesh, changed);
  const ImageRgb8 image = drawn(renderer, mesh, frame);
  EXPECT_EQ(renderer.edgeUploads(), 3u);
  SceneRenderer anew;
  anew.upload(mesh);
  anew.setObjectTransform(0, glm::translate(glm::mat4{1}, glm::vec3{-1.5f, 0, 0}));
  anew.setObjectTransform(1, glm::translate(glm::mat4{1}, glm::vec3{1.5f, 0, 0}));
  EXPECT_EQ(image.pixels, drawn(anew, mesh, frame).pixels);
}

// The office's display, shaded by the ambient term: one radiance per surface.
engine::DisplayMesh officeDisplay(const engine::Scene& office) {
  engine::DisplayMesh mesh = engine::displayMesh(office, engine::meshScene(office));
  engine::shadeWithAmbient(office, mesh);
  return mesh;
}

// Radiance rising steeply across the display, far more within an element than a solution's: no
// surface evenly lit.
void lightSteeply(engine::DisplayMesh& mesh) {
  for (engine::SurfaceDisplay& s : mesh.surfaces)
    for (size_t v = 0; v < s.positions.size(); ++v) s.radiance[v] = glm::vec3{0.05f + 0.4f * std::abs(s.positions[v].x * s.positions[v].y)};
}

// At its level of detail the office draws far fewer triangles where its surfaces are evenly lit
// (shaded by the ambient term: one radiance per surface), and the same picture; lit by a steep
// gradient instead (no surface evenly lit), it draws the same picture as with every element.
TEST(SceneRenderer, TheLevelOfDetailDrawsFewerTrianglesAndTheSamePicture) {
  const Context context;
  const engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  engine::DisplayMesh mesh = officeDisplay(scene);
  FrameSettings frame = frameFor(scene, mesh);
  const auto compare = [&](const char* light) {
    SCOPED_TRACE(light);
    SceneRenderer renderer;
    renderer.upload(mesh);
    frame.levelOfDetail = false;
    const ImageRgb8 every = drawn(renderer, mesh, frame);
    const size_t everyTriangles = renderer.lastFrame().triangles;
    frame.levelOfDetail = true;
    const ImageRgb8 detailed = drawn(renderer, mesh, frame);
    const test::ImageDifference d = test::difference(detailed, every, 4);
    EXPECT_LT(d.meanLevels, 0.05);
    EXPECT_LT(d.shareBeyond, 0.001);
    return std::pair{renderer.lastFrame().triangles, everyTriangles};
  };
  const auto [evenTriangles, allTriangles] = compare("ambient");
  EXPECT_LT(evenTriangles, allTriangles / 3);

  lightSteeply(mesh);
  const auto [unevenTriangles, unevenAll] = compare("gradient");
  EXPECT_GT(unevenTriangles, evenTriangles);
}

// Colours tone mapped per vertex and interpolated are close to the exact per-pixel colours and
// never brighter (but for rounding): the sRGB encoding is concave, so the mean of encoded
// colours is at most the encoding of the mean. On the office lit by a steep gradient.
TEST(SceneRenderer, ToneMappingTheVerticesIsCloseToToneMappingThePixelsAndNeverBrighter) {
  const Context context;
  const engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  engine::DisplayMesh mesh = officeDisplay(scene);
  lightSteeply(mesh);
  SceneRenderer renderer;
  renderer.upload(mesh);
  FrameSettings frame = frameFor(scene, mesh);
  frame.exposure = 1;
  const ImageRgb8 perPixel = drawn(renderer, mesh, frame);
  frame.toneMapVertices = true;
  const ImageRgb8 perVertex = drawn(renderer, mesh, frame);
  ASSERT_NE(perPixel.pixels, perVertex.pixels);
  const test::ImageDifference d = test::difference(perVertex, perPixel, 4);
  EXPECT_LT(d.meanLevels, 1.0);
  EXPECT_LT(d.shareBeyond, 0.02);  // 1.3% today, in this steep light
  size_t brighter = 0;
  for (size_t i = 0; i < perPixel.pixels.size(); ++i) brighter += perVertex.pixels[i] > perPixel.pixels[i] + 1;
  EXPECT_EQ(brighter, 0u);
}

// Colours made per vertex are made again when the exposure changes: the same renderer draws at the
// new exposure what a fresh one draws there, and not the picture at the old.
TEST(SceneRenderer, ColoursMadePerVertexFollowTheExposure) {
  const Context context;
  const engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/office.json");
  engine::DisplayMesh mesh = officeDisplay(scene);
  lightSteeply(mesh);
  FrameSettings frame = frameFor(scene, mesh);
  frame.toneMapVertices = true;
  frame.exposure = 1;
  SceneRenderer renderer;
  renderer.upload(mesh);
  const ImageRgb8 before = drawn(renderer, mesh, frame);
  frame.exposure = 2;
  const ImageRgb8 after = drawn(renderer, mesh, frame);
  SceneRenderer fresh;
  fresh.upload(mesh);
  EXPECT_EQ(after.pixels, drawn(fresh, mesh, frame).pixels);
  EXPECT_NE(after.pixels, before.pixels);
}

}  // namespace
}  // namespace app

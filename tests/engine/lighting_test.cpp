// The solver on its own thread: snapshots of the shared meshes' radiance, pause and restart.
#include "engine/document/lighting.h"

#include "engine/document/display_mesh.h"
#include "engine/document/mesh_adaptation.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace engine {
namespace {

Scene loadAsset(const char* name) { return loadScene(std::string(WALKRAD_ASSETS) + "/" + name); }

// Polls until `ready` holds for the newest snapshot; fails the test after a minute.
template <typename Ready>
std::shared_ptr<const LightingSnapshot> waitFor(const LightingThread& lighting, Ready ready) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  for (;;) {
    std::shared_ptr<const LightingSnapshot> s = lighting.latest();
    if (ready(*s)) return s;
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "no such snapshot within a minute; the newest has " << s->shots << " shots";
      return s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

TEST(Lighting, SnapshotsMatchASolveOnThisThreadShotForShot) {
  const Scene scene = loadAsset("cornell.json");
  const MeshedScene meshed = meshScene(scene);
  const DisplayMesh display = displayMesh(scene, meshed);
  LightingSettings settings;
  settings.converge = 0.05;
  LightingThread lighting(scene, meshed, settings);
  const std::shared_ptr<const LightingSnapshot> first = lighting.latest();
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->radiance.size(), display.vertices);
  const auto done = waitFor(lighting, [](const LightingSnapshot& s) { return s.converged; });
  EXPECT_GT(done->version, first->version);
  EXPECT_LE(done->unshotFraction, 0.05);
  EXPECT_EQ(done->elements, display.elements);

  // The same number of shots here gives the same radiance, bit for bit.
  radiosity::Solver solver(radiosityInput(scene, meshed), settings.solver);
  for (uint64_t i = 0; i < done->shots; ++i) ASSERT_TRUE(solver.step());
  std::vector<glm::vec3> here;
  displayRadiance(solver, here);
  EXPECT_EQ(here, done->radiance);
}

TEST(Lighting, PauseStopsShootingAndRestartStartsOver) {
  const Scene scene = loadAsset("cornell.json");
  const MeshedScene meshed = meshScene(scene);
  LightingSettings settings;
  settings.converge = 1e-4;
  LightingThread lighting(scene, meshed, settings);
  waitFor(lighting, [](const LightingSnapshot& s) { return s.shots >= 5; });
  lighting.setPaused(true);
  // The first paused snapshot comes once the shot in flight has landed, and shows it (with any
  // others since the last snapshot); then nothing more is shot, however long a shot takes.
  const auto settled = waitFor(lighting, [](const LightingSnapshot& s) { return s.paused; });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto later = lighting.latest();
  EXPECT_TRUE(later->paused);
  EXPECT_EQ(later->shots, settled->shots);

  lighting.restart();
  lighting.setPaused(false);
  const uint64_t before = later->shots;
  const auto restarted = waitFor(lighting, [&](const LightingSnapshot& s) { return s.shots < before; });
  EXPECT_LT(restarted->shots, before);
}

// Snapshots normally come at most so often; a pause shows the shots since the last one anyway.
TEST(Lighting, APausedSnapshotShowsEveryShot) {
  const Scene scene = loadAsset("cornell.json");
  const MeshedScene meshed = meshScene(scene);
  LightingSettings settings;
  settings.converge = 1e-6;
  settings.publishSeconds = 1e9;  // no snapshot but the first, unless pausing makes one
  LightingThread lighting(scene, meshed, settings);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(lighting.latest()->shots, 0u);
  lighting.setPaused(true);
  const auto paused = waitFor(lighting, [](const LightingSnapshot& s) { return s.paused && s.shots > 0; });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(lighting.latest()->shots, paused->shots);  // nothing shot since
}

// Moves sent while the thread shoots (on two graphics processors), with a pause between them,
// are all taken in: the last snapshot counts them, and with the object back where it was its
// light is the unmoved scene's (within 0.5%, as EditPath.MovingAnObjectAndBackRestoresTheSolution).
TEST(Lighting, MovesSentWhileShootingAreAllTakenIn) {
  SceneEditor editor(loadAsset("cornell.json"), meshScene(loadAsset("cornell.json")));
  LightingSettings settings;
  settings.converge = 0.002;
  settings.solver.graphicsProcessors = 2;
  LightingThread lighting(editor.scene(), editor.meshed(), settings);
  const uint32_t block = *editor.findObject("short block");
  const ObjectPose home = poseOf(editor.scene().objects[block]);
  uint64_t sent = 0;
  for (const Vec3 offset : {Vec3{120, 0, 100}, Vec3{-60, 0, 40}, Vec3{0, 0, 0}}) {
    // The last move taken in: its corrections are being shot.
    waitFor(lighting, [&](const LightingSnapshot& s) { return s.edits == sent; });
    if (sent == 1) {
      lighting.setPaused(true);
      lighting.setPaused(false);
    }
    editor.setPose(block, {home.position + offset, home.rotateYDeg});
    lighting.edit(editor.scene(), editor.meshed(), editor.takeEdited());
    ++sent;
  }
  const auto done = waitFor(lighting, [&](const LightingSnapshot& s) { return s.edits == sent && s.converged; });
  EXPECT_FALSE(done->paused);

  radiosity::Solver unmoved(radiosityInput(editor.scene(), editor.meshed()), settings.solver);
  unmoved.solve(settings.converge);
  std::vector<glm::vec3> here;
  displayRadiance(unmoved, here);
  ASSERT_EQ(here.size(), done->radiance.size());
  double difference = 0, level = 0;
  for (size_t v = 0; v < here.size(); ++v)
    for (int c = 0; c < 3; ++c) difference += std::abs(done->radiance[v][c] - here[v][c]), level += std::abs(here[v][c]);
  EXPECT_LT(difference / level, 0.005);
}

// With adaptive refinement the thread publishes its meshes with the radiance, and comes to what a
// solve on this thread with the same passes comes to; an edit keeps them coming.
TEST(Lighting, AdaptiveSnapshotsCarryTheirMeshes) {
  SceneEditor editor(loadAsset("box-on-floor.json"), meshScene(loadAsset("box-on-floor.json")));
  LightingSettings settings;
  settings.converge = 0.05;
  settings.solver.resolution = 128;
  settings.adaptive = AdaptiveSettings{};
  LightingThread lighting(editor.scene(), editor.meshed(), settings);
  const std::shared_ptr<const LightingSnapshot> first = lighting.latest();
  ASSERT_NE(first->meshed, nullptr);
  EXPECT_EQ(first->radiance.size(), displayMesh(editor.scene(), *first->meshed).vertices);
  const auto done = waitFor(lighting, [](const LightingSnapshot& s) { return s.converged; });
  EXPECT_GT(done->adaptivePasses, 0u);
  EXPECT_NE(done->meshed, first->meshed);
  const DisplayMesh adapted = displayMesh(editor.scene(), *done->meshed);
  EXPECT_EQ(done->elements, adapted.elements);
  EXPECT_GT(adapted.elements, displayMesh(editor.scene(), *first->meshed).elements);
  EXPECT_EQ(done->radiance.size(), adapted.vertices);

  MeshAdaptation adaptation(editor.scene(), editor.meshed(), *settings.adaptive);
  radiosity::Solver solver(adaptation.input(), settings.solver);
  solveTo(solver, settings.converge, UINT64_MAX, {}, &adaptation);
  std::vector<glm::vec3> here;
  displayRadiance(solver, here);
  EXPECT_EQ(here, done->radiance);
  EXPECT_EQ(adaptation.passes(), done->adaptivePasses);

  const uint32_t box = *editor.findObject("box");
  ObjectPose pose = poseOf(editor.scene().objects[box]);
  pose.position.x += 0.5;
  editor.setPose(box, pose);
  lighting.edit(editor.scene(), editor.meshed(), editor.takeEdited());
  const auto moved = waitFor(lighting, [](const LightingSnapshot& s) { return s.edits == 1 && s.converged; });
  ASSERT_NE(moved->meshed, nullptr);
  EXPECT_EQ(moved->radiance.size(), displayMesh(editor.scene(), *moved->meshed).vertices);
}

// A room 524,287 m from the origin and a slab floating in it whose top has a small open hole
// 5 um from its edge. Where the slab is loaded its plane coordinates are below 2^19 and the
// mesher resolves 3.8 um; moved 1 m on they are above, and it resolves only 7.6 um.
constexpr const char* kFarSlab = R"({
  "format": "walkrad-scene/1", "units": "m", "settings": { "patch_size": 0.25 },
  "materials": { "white": { "reflectance": [0.5, 0.5, 0.5] }, "lamp": { "reflectance": [0.5, 0.5, 0.5], "emission": [4, 4, 4] } },
  "objects": [
    { "name": "room", "movable": false,
      "solids": [ { "profile": [[524286, 0], [524290, 0], [524290, 2], [524286, 2]], "from": 0, "to": 2, "inward": true,
                    "material": "white",
                    "faces": { "top": { "holes": [ { "polygon": [[524287.5, 0.5], [524288.5, 0.5], [524288.5, 1.5], [524287.5, 1.5]],
                                                     "fill": "lamp" } ] } } } ] },
    { "name": "slab", "position": [524286.5, 0.5, 0.5],
      "solids": [ { "profile": [[0, 0], [1, 0], [1, 1], [0, 1]], "from": 0, "to": 0.1, "material": "white",
                    "faces": { "top": { "holes": [ { "polygon": [[0.5, 5e-6], [0.51, 5e-6], [0.51, 0.01], [0.5, 0.01]] } ] } } } ] }
  ] })";

// Moved rigidly, the slab keeps its loaded mesh in the plane coordinates it was meshed in, where
// the adaptive passes refine its top (main made them anew where it stands, and the mesher
// refused it there): the lighting thread converges after the edit with no error.
TEST(Lighting, AdaptivePassesRefineAMovedSurfaceTheMesherWouldRefuseWhereItNowStands) {
  Scene loaded = parseScene(kFarSlab, "far-slab.json");
  MeshedScene meshed = meshScene(loaded);
  SceneEditor editor(std::move(loaded), std::move(meshed));
  LightingSettings settings;
  settings.converge = 0.05;
  settings.solver.resolution = 128;
  settings.adaptive = AdaptiveSettings{.threshold = 0.01};
  LightingThread lighting(editor.scene(), editor.meshed(), settings);
  const uint32_t slab = *editor.findObject("slab");
  ObjectPose pose = poseOf(editor.scene().objects[slab]);
  pose.position.x += 1;
  ASSERT_TRUE(editor.setPose(slab, pose));
  size_t top = editor.scene().surfaces.size();
  for (size_t s = 0; s < editor.scene().surfaces.size(); ++s)
    if (editor.scene().surfaces[s].object == slab && editor.scene().surfaces[s].normal.y > 0.5) top = s;
  ASSERT_LT(top, editor.scene().surfaces.size());
  mesher::Mesher mesher;
  EXPECT_THROW(meshSurface(editor.scene().surfaces[top], mesher), mesher::MeshRefused);  // the premise: refused where it stands

  lighting.edit(editor.scene(), editor.meshed(), editor.takeEdited());
  const auto done = waitFor(lighting, [](const LightingSnapshot& s) { return s.edits == 1 && (s.converged || !s.error.empty()); });
  EXPECT_EQ(done->error, "");
  EXPECT_TRUE(done->converged);
  EXPECT_GT(done->adaptivePasses, 0u);
  ASSERT_NE(done->meshed, nullptr);
  EXPECT_GT(done->meshed->surfaces[top].mesh.elements.size(), editor.meshed().surfaces[top].mesh.elements.size());
}

}  // namespace
}  // namespace engine

// The document on its own thread: snapshots of the radiance with the meshes that changed, poses
// asked for and refused, pause and restart.
#include "engine/document/lighting.h"

#include "engine/document/display_mesh.h"
#include "engine/document/mesh_adaptation.h"
#include "engine/document/scene_editor.h"
#include "engine/document/scene_view.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace engine {
namespace {

Scene loadAsset(const char* name) { return loadScene(std::string(WALKRAD_ASSETS) + "/" + name); }

// A shipped scene as the window opens it: the scene, its meshes, the objects' poses.
struct Opened {
  explicit Opened(const char* name) : scene(loadAsset(name)), meshed(meshScene(scene)), poses(scene) {}
  const Scene scene;
  const MeshedScene meshed;
  const ScenePoses poses;
};

// How long a test waits for a snapshot before failing: long, as the sanitizer builds run tens of
// times slower than the release build (ctest's timeout still stops a hang).
constexpr auto kPatience = std::chrono::minutes(10);

// Polls until `ready` holds for the newest snapshot; fails the test after kPatience.
template <typename Ready>
std::shared_ptr<const LightingSnapshot> waitFor(const LightingThread& lighting, Ready ready) {
  const auto deadline = std::chrono::steady_clock::now() + kPatience;
  for (;;) {
    std::shared_ptr<const LightingSnapshot> s = lighting.latest();
    if (ready(*s)) return s;
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "no such snapshot in time; the newest has " << s->shots << " shots";
      return s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Polls the thread's updates until `ready` holds for the newest snapshot, the view (when given)
// taking each; fails the test after kPatience. Returns the last update, with every mesh and
// refusal taken since the call.
template <typename Ready>
LightingUpdate takeUntil(LightingThread& lighting, SceneView* view, Ready ready) {
  const auto deadline = std::chrono::steady_clock::now() + kPatience;
  LightingUpdate all;
  for (;;) {
    LightingUpdate update = lighting.take();
    if (view) view->take(update);
    all.snapshot = update.snapshot;
    for (SurfaceUpdate& m : update.meshes) all.meshes.push_back(std::move(m));
    for (PoseRefusal& r : update.refusals) all.refusals.push_back(std::move(r));
    if (ready(*all.snapshot)) return all;
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "no such snapshot in time; the newest has " << all.snapshot->shots << " shots";
      return all;
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
  EXPECT_EQ(first->radiance.capacity(), display.vertices);  // sized once, not grown
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

// Poses asked for while the thread shoots (on two graphics processors), with a pause between
// them, are all taken in: the last snapshot counts them, and with the object back where it was
// its light is the unmoved scene's (within 0.5%, as EditPath.MovingAnObjectAndBackRestoresTheSolution).
TEST(Lighting, PosesAskedForWhileShootingAreAllTakenIn) {
  const Opened cornell("cornell.json");
  const auto& [scene, meshed, poses] = cornell;
  LightingSettings settings;
  settings.converge = 0.002;
  settings.solver.graphicsProcessors = 2;
  LightingThread lighting(scene, meshed, settings);
  const uint32_t block = *poses.findObject("short block");
  const ObjectPose home = poses.pose(block);
  uint64_t sent = 0;
  for (const Vec3 offset : {Vec3{120, 0, 100}, Vec3{-60, 0, 40}, Vec3{0, 0, 0}}) {
    // The last move taken in: its corrections are being shot.
    waitFor(lighting, [&](const LightingSnapshot& s) { return s.edits == sent; });
    if (sent == 1) {
      lighting.setPaused(true);
      lighting.setPaused(false);
    }
    lighting.requestPose(block, {home.position + offset, home.rotateYDeg});
    ++sent;
  }
  const auto done = waitFor(lighting, [&](const LightingSnapshot& s) { return s.edits == sent && s.converged; });
  EXPECT_FALSE(done->paused);

  radiosity::Solver unmoved(radiosityInput(scene, meshed), settings.solver);
  unmoved.solve(settings.converge);
  std::vector<glm::vec3> here;
  displayRadiance(unmoved, here);
  ASSERT_EQ(here.size(), done->radiance.size());
  double difference = 0, level = 0;
  for (size_t v = 0; v < here.size(); ++v)
    for (int c = 0; c < 3; ++c) difference += std::abs(done->radiance[v][c] - here[v][c]), level += std::abs(here[v][c]);
  EXPECT_LT(difference / level, 0.005);
}

// Poses asked for in a burst, before the thread takes any, count each but are taken only as the
// newest per object: the thread meshes the box's move once, not once per mouse move.
TEST(Lighting, ABurstOfPosesIsTakenAsItsNewest) {
  const Opened boxOnFloor("box-on-floor.json");
  const auto& [scene, meshed, poses] = boxOnFloor;
  LightingSettings settings;
  settings.converge = 0.05;
  settings.solver.resolution = 128;
  LightingThread lighting(scene, meshed, settings);
  lighting.setPaused(true);
  const uint32_t box = *poses.findObject("box");
  ObjectPose pose = poses.pose(box);
  for (int i = 0; i < 50; ++i) {
    pose.position.x += 0.01;
    lighting.requestPose(box, pose);
  }
  lighting.setPaused(false);
  const LightingUpdate all = takeUntil(lighting, nullptr, [](const LightingSnapshot& s) { return s.edits == 50 && s.converged; });
  EXPECT_TRUE(all.refusals.empty());
  // The box's surfaces and the floor it stands on, each once, where the last pose put them.
  ASSERT_FALSE(all.meshes.empty());
  for (const SurfaceUpdate& u : all.meshes)
    if (scene.surfaces[u.surface].object == box) {
      EXPECT_EQ(u.pose, pose);
    }
  std::vector<uint32_t> surfaces;
  for (const SurfaceUpdate& u : all.meshes) surfaces.push_back(u.surface);
  EXPECT_TRUE(std::is_sorted(surfaces.begin(), surfaces.end()));
  EXPECT_EQ(std::adjacent_find(surfaces.begin(), surfaces.end()), surfaces.end());
  for (uint32_t s : poses.surfacesOf(box)) EXPECT_NE(std::find(surfaces.begin(), surfaces.end(), s), surfaces.end());
  EXPECT_LT(surfaces.size(), scene.surfaces.size());  // the room's walls and ceiling are not sent
}

// With adaptive refinement the thread sends the meshes it refines with the radiance, so a view
// taking its updates always has the radiance's vertices, and it comes to what a solve on this
// thread with the same passes comes to; a pose asked for keeps them coming.
TEST(Lighting, AdaptiveUpdatesCarryTheirMeshes) {
  const Scene scene = loadAsset("box-on-floor.json");
  const MeshedScene meshed = meshScene(scene);
  LightingSettings settings;
  settings.converge = 0.05;
  settings.solver.resolution = 128;
  settings.adaptive = AdaptiveSettings{};
  LightingThread lighting(scene, meshed, settings);
  SceneView view(scene, meshed);
  const size_t loadedElements = view.display().elements;
  const LightingUpdate first = lighting.take();
  EXPECT_TRUE(view.take(first).radiance);
  const auto matches = [&](const LightingSnapshot& s) { return s.radiance.size() == view.display().vertices; };
  EXPECT_TRUE(matches(*first.snapshot));
  const LightingUpdate done = takeUntil(lighting, &view, [&](const LightingSnapshot& s) {
    EXPECT_TRUE(matches(s));
    return s.converged;
  });
  EXPECT_GT(done.snapshot->adaptivePasses, 0u);
  EXPECT_FALSE(done.meshes.empty());
  EXPECT_EQ(done.snapshot->elements, view.display().elements);
  EXPECT_GT(view.display().elements, loadedElements);

  AdaptiveMeshes adaptive(scene.surfaces.size());
  MeshAdaptation adaptation(scene, meshed, *settings.adaptive, adaptive);
  radiosity::Solver solver(adaptation.input(), settings.solver);
  solveTo(solver, settings.converge, UINT64_MAX, {}, &adaptation);
  std::vector<glm::vec3> here;
  displayRadiance(solver, here);
  EXPECT_EQ(here, done.snapshot->radiance);
  EXPECT_EQ(adaptation.passes(), done.snapshot->adaptivePasses);

  const uint32_t box = *view.poses().findObject("box");
  ObjectPose pose = view.poses().pose(box);
  pose.position.x += 0.5;
  view.setPose(box, pose);
  lighting.requestPose(box, pose);
  takeUntil(lighting, &view, [&](const LightingSnapshot& s) {
    EXPECT_TRUE(matches(s));
    return s.edits == 1 && s.converged;
  });
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
  const Scene loaded = parseScene(kFarSlab, "far-slab.json");
  const MeshedScene meshed = meshScene(loaded);
  SceneEditor editor(loaded, meshed);
  LightingSettings settings;
  settings.converge = 0.05;
  settings.solver.resolution = 128;
  settings.adaptive = AdaptiveSettings{.threshold = 0.01};
  LightingThread lighting(loaded, meshed, settings);
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

  lighting.requestPose(slab, pose);
  const LightingUpdate done =
      takeUntil(lighting, nullptr, [](const LightingSnapshot& s) { return s.edits == 1 && (s.converged || !s.error.empty()); });
  EXPECT_EQ(done.snapshot->error, "");
  EXPECT_TRUE(done.snapshot->converged);
  EXPECT_TRUE(done.refusals.empty());
  EXPECT_GT(done.snapshot->adaptivePasses, 0u);
  size_t topElements = 0;
  for (const SurfaceUpdate& u : done.meshes)
    if (u.surface == top) topElements = u.mesh.mesh.elements.size();  // the newest
  EXPECT_GT(topElements, editor.meshed().surfaces[top].mesh.elements.size());
}

}  // namespace
}  // namespace engine

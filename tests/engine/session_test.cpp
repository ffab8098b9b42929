// The window's logic without a window: frames of a session with its real lighting thread, driven
// by inputs as the window would make them from keys and the mouse, and no display (no GLFW, no GL).
#include "engine/session/session.h"

#include "engine/io/load_scene.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <thread>

namespace engine {
namespace {

const std::string kBoxOnFloor = std::string(WALKRAD_ASSETS) + "/box-on-floor.json";
// box-on-floor.json: a 4 x 3 m room (object 0) with a box (object 1) on its floor, its footprint
// x 1.2..2.1, z 1.3..2.2, its top at y = 0.8.
constexpr uint32_t kBox = 1;

ViewCamera defaultCamera(const Scene& scene) {
  ViewCamera camera;
  chooseCamera(scene, "", camera);
  return camera;
}

// A ray from just below the ceiling straight down at (x, z).
Ray down(double x, double z) { return {{x, 2, z}, {0, -1, 0}}; }

// What a run of frames changed, gathered.
struct Changes {
  std::set<uint32_t> moved, surfaces;
  std::vector<std::string> reports;
  void add(const SessionFrame& frame) {
    moved.insert(frame.moved.begin(), frame.moved.end());
    surfaces.insert(frame.surfaces.begin(), frame.surfaces.end());
    reports.insert(reports.end(), frame.reports.begin(), frame.reports.end());
  }
};

// Frames of `input` (by default none: a drag ends) until the lighting thread has taken every pose
// sent and converged again. Fails the test when that takes more than about a minute of frames.
// Every object whose pose a frame changed is among the frame's `moved`, for its transform to follow.
void settle(Session& session, Changes* changes = nullptr, const SessionInput& input = {}) {
  const auto poses = [&] {
    std::vector<ObjectPose> all;
    for (const Object& o : session.scene().objects) all.push_back(poseOf(o));
    return all;
  };
  for (int i = 0; i < 60000; ++i) {
    const std::vector<ObjectPose> before = poses();
    const SessionFrame frame = session.frame(input);
    const std::vector<ObjectPose> after = poses();
    for (uint32_t o = 0; o < after.size(); ++o) {
      const bool listed = std::count(frame.moved.begin(), frame.moved.end(), o) > 0;
      EXPECT_TRUE(after[o] == before[o] || listed) << "object " << o;
    }
    if (changes) changes->add(frame);
    const PanelModel& panel = session.panel();
    if (panel.posesWaiting == 0 && panel.light->converged) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  FAIL() << "the light did not converge";
}

// How many of the reports say that box-on-floor's light converged.
long convergedLines(const Changes& changes) {
  return std::count_if(changes.reports.begin(), changes.reports.end(), [](const std::string& line) {
    return line.rfind(kBoxOnFloor + ": converged after ", 0) == 0;
  });
}

// The floor's display vertices (world coordinates) strictly inside x0..x1, z0..z1, with their
// mean radiance (red).
struct FloorPatch {
  size_t vertices = 0;
  double meanRadiance = 0;
};
// The room's floor: the surface of object 0 that faces up at y = 0.
size_t floorOf(const Scene& scene) {
  for (size_t s = 0; s < scene.surfaces.size(); ++s) {
    const Surface& surface = scene.surfaces[s];
    if (surface.object == 0 && surface.normal.y > 0.5 && surface.outer[0].y == 0) return s;
  }
  ADD_FAILURE() << "no floor";
  return 0;
}

FloorPatch floorIn(const Session& session, double x0, double x1, double z0, double z1) {
  FloorPatch patch;
  const DisplayMesh& mesh = session.display();
  const SurfaceDisplay& floor = mesh.surfaces[floorOf(session.scene())];
  // Only vertices drawn: a cut-out's hole insertion may leave vertices no element uses.
  std::vector<uint8_t> drawn(floor.positions.size(), 0);
  for (uint32_t v : floor.triangles) drawn[v] = 1;
  for (size_t v = 0; v < floor.positions.size(); ++v) {
    if (!drawn[v]) continue;
    const glm::dvec3 p = glm::dvec3(floor.positions[v]) + mesh.origin;
    if (p.x <= x0 || p.x >= x1 || p.z <= z0 || p.z >= z1) continue;
    ++patch.vertices;
    patch.meanRadiance += floor.radiance[v].r;
  }
  if (patch.vertices > 0) patch.meanRadiance /= static_cast<double>(patch.vertices);
  return patch;
}

// The strip of floor the box stands on at first and leaves when moved 0.5 m along +x.
FloorPatch stripLeft(const Session& session) { return floorIn(session, 1.25, 1.65, 1.35, 2.15); }

LightingSettings quickLight() {
  LightingSettings settings;
  settings.publishSeconds = 0;  // a snapshot after every shot: frames see the light as it comes
  return settings;
}

TEST(Session, WalkingForwardMovesTheCameraAlongItsHeadingByTheSpeed) {
  OpenedScene opened = openScene(kBoxOnFloor);
  const ViewCamera start = defaultCamera(opened.scene);
  Session session(std::move(opened), quickLight(), start);
  SessionInput input;
  input.walk.forward = true;
  input.seconds = 0.1;
  for (int i = 0; i < 10; ++i) session.frame(input);
  // 1.4 m/s for 1 s, along the heading, level.
  const glm::dvec3 heading{std::sin(start.yaw), 0, std::cos(start.yaw)};
  const glm::dvec3 walked = session.camera().position - start.position;
  EXPECT_NEAR(glm::length(walked), 1.4, 1e-9);
  EXPECT_NEAR(glm::dot(walked, heading), 1.4, 1e-9);
  EXPECT_EQ(session.camera().yaw, start.yaw);
  EXPECT_EQ(session.panel().walkSpeed, 1.4);
}

// Empty frames until `done` holds (true), or about a minute of them (false).
template <typename Done>
bool framesUntil(Session& session, Done done) {
  for (int i = 0; i < 60000; ++i) {
    session.frame({});
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

// The panel's model lists the scene; its pause, restart and camera buttons, sent back as input,
// reach the solver and the camera.
TEST(Session, ThePanelModelAndItsButtons) {
  OpenedScene opened = openScene(kBoxOnFloor);
  const Scene loaded = opened.scene;
  Session session(std::move(opened), quickLight(), overviewCamera(loaded));
  const PanelModel& panel = session.panel();
  EXPECT_EQ(panel.file, "box-on-floor.json");
  EXPECT_EQ(panel.units, "m");
  ASSERT_EQ(panel.objects.size(), 2u);
  EXPECT_EQ(panel.objects[0].name, "room");
  EXPECT_FALSE(panel.objects[0].movable);
  EXPECT_EQ(panel.objects[kBox].name, "box");
  EXPECT_EQ(panel.objects[kBox].surfaces, 6u);
  EXPECT_EQ(panel.objects[0].surfaces + panel.objects[kBox].surfaces, panel.surfaces);
  EXPECT_EQ(panel.cameras, std::vector<std::string>{"default"});
  EXPECT_EQ(panel.elements, session.display().elements);
  EXPECT_FALSE(panel.selected);

  SessionInput press;
  press.press = true;
  press.pointer = down(1.65, 1.75);
  session.frame(press);
  ASSERT_TRUE(panel.selected);
  EXPECT_EQ(panel.selected->name, "box");
  EXPECT_TRUE(panel.selected->movable);

  SessionInput jump;
  jump.jumpToCamera = 0;
  session.frame(jump);
  EXPECT_EQ(session.camera().position, fromSceneCamera(loaded.cameras[0]).position);
  EXPECT_EQ(session.camera().yaw, fromSceneCamera(loaded.cameras[0]).yaw);

  ASSERT_TRUE(framesUntil(session, [&] { return panel.light->shots > 0; }));
  SessionInput pause;
  pause.pause = true;
  session.frame(pause);
  EXPECT_TRUE(panel.paused);
  ASSERT_TRUE(framesUntil(session, [&] { return panel.light->paused; }));
  ASSERT_GT(panel.light->shots, 0u);
  SessionInput restart;
  restart.restart = true;
  session.frame(restart);
  ASSERT_TRUE(framesUntil(session, [&] { return panel.light->shots == 0; }));
  EXPECT_EQ(panel.light->unshotFraction, 1);  // from the emitters again, and paused
}

// A drag of the box through frames: the box follows the ray at once, the document cuts its new
// footprint out of the floor and the light converges again; undo puts box, floor and light back,
// redo moves them again.
TEST(Session, ADraggedBoxIsRelitAndUndoAndRedoTakeItBackAndForth) {
  OpenedScene opened = openScene(kBoxOnFloor);
  const ViewCamera camera = defaultCamera(opened.scene);
  Session session(std::move(opened), quickLight(), camera);
  Changes first;
  settle(session, &first);
  EXPECT_EQ(convergedLines(first), 1);  // the terminal hears it once
  const FloorPatch before = stripLeft(session);
  EXPECT_EQ(before.vertices, 0u);  // cut out under the box
  const FloorPatch open = floorIn(session, 2.15, 3.5, 0.2, 1.25);  // floor in the open, for scale
  ASSERT_GT(open.vertices, 0u);
  const size_t floor = floorOf(session.scene());
  const std::vector<glm::vec3> floorLight = session.display().surfaces[floor].radiance;

  // Grabbed on its top (y = 0.8) at (1.65, 1.75); the pointer moves 0.5 m along +x in two frames.
  Changes dragged;
  SessionInput input;
  input.press = input.held = true;
  input.pointer = down(1.65, 1.75);
  dragged.add(session.frame(input));
  ASSERT_TRUE(session.dragging());
  EXPECT_EQ(session.selected(), kBox);
  input.press = false;
  input.pointer = down(1.9, 1.75);
  dragged.add(session.frame(input));
  EXPECT_NEAR(session.scene().objects[kBox].position.x, 0.25, 1e-12);
  input.pointer = down(2.15, 1.75);
  dragged.add(session.frame(input));
  EXPECT_NEAR(session.scene().objects[kBox].position.x, 0.5, 1e-12);
  EXPECT_EQ(session.scene().objects[kBox].position.y, 0);  // on the floor
  input.held = false;
  dragged.add(session.frame(input));
  EXPECT_FALSE(session.dragging());
  EXPECT_EQ(dragged.moved, std::set<uint32_t>{kBox});
  EXPECT_TRUE(session.panel().canUndo);
  EXPECT_TRUE(session.panel().unsaved);

  settle(session, &dragged);
  EXPECT_EQ(convergedLines(dragged), 1);  // again, after the drag
  // The floor was meshed again around the new footprint and uploaded; the strip the box left is
  // floor again, lit like the open floor.
  const FloorPatch left = stripLeft(session);
  EXPECT_GT(left.vertices, 0u);
  EXPECT_GT(left.meanRadiance, 0.5 * open.meanRadiance);
  EXPECT_EQ(floorIn(session, 1.75, 2.55, 1.35, 2.15).vertices, 0u);  // under the box now
  EXPECT_TRUE(dragged.surfaces.count(static_cast<uint32_t>(floor)));

  Changes undone;
  SessionInput undo;
  undo.undo = true;
  undone.add(session.frame(undo));
  EXPECT_EQ(session.scene().objects[kBox].position, Vec3(0));
  EXPECT_EQ(undone.moved, std::set<uint32_t>{kBox});
  EXPECT_FALSE(session.panel().canUndo);
  EXPECT_TRUE(session.panel().canRedo);
  EXPECT_FALSE(session.panel().unsaved);
  settle(session, &undone);
  EXPECT_EQ(stripLeft(session).vertices, 0u);
  // The same floor mesh as before the drag, its light corrected back to within a percent.
  EXPECT_TRUE(undone.surfaces.count(static_cast<uint32_t>(floor)));
  const std::vector<glm::vec3>& relit = session.display().surfaces[floor].radiance;
  ASSERT_EQ(relit.size(), floorLight.size());
  for (size_t v = 0; v < relit.size(); ++v) EXPECT_NEAR(relit[v].r, floorLight[v].r, 0.01 * floorLight[v].r + 1e-6) << v;

  SessionInput redo;
  redo.redo = true;
  session.frame(redo);
  EXPECT_NEAR(session.scene().objects[kBox].position.x, 0.5, 1e-12);
  settle(session);
  EXPECT_GT(stripLeft(session).vertices, 0u);
}

// box-on-floor.json copied into a fresh folder of the test output; its path.
std::string copyOfBoxOnFloor(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(WALKRAD_TEST_OUTPUT) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / "box-on-floor.json";
  std::filesystem::copy_file(kBoxOnFloor, path);
  return path.string();
}

TEST(Session, SavingWritesTheDraggedPoseIntoTheSceneFile) {
  const std::string path = copyOfBoxOnFloor("session_save");
  OpenedScene opened = openScene(path);
  const ViewCamera camera = defaultCamera(opened.scene);
  Session session(std::move(opened), quickLight(), camera);
  SessionInput input;
  input.press = input.held = true;
  input.pointer = down(1.65, 1.75);
  session.frame(input);
  input.press = false;
  input.pointer = down(1.65, 1.45);
  session.frame(input);
  SessionInput save;
  save.save = true;  // the drag ends in the same frame
  const SessionFrame saved = session.frame(save);
  ASSERT_EQ(saved.reports, std::vector<std::string>{"saved " + path});
  EXPECT_EQ(session.panel().saveReport, "saved " + path);
  EXPECT_FALSE(session.panel().unsaved);
  const Object& box = session.scene().objects[kBox];
  EXPECT_NEAR(box.position.z, -0.3, 1e-12);
  EXPECT_EQ(loadScene(path).objects[kBox].position, box.position);
  // Nothing but the file itself is left in its folder.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()),
                          std::filesystem::directory_iterator()),
            1);
}

// Dragged so that its footprint would leave a strip of floor 3 um wide 900 km from the origin
// (finer than the mesher resolves there), the document refuses the pose: the box goes back to its
// last good pose, the terminal and the panel say why.
TEST(Session, ARefusedPosePutsTheObjectBack) {
  OpenedScene opened = openScene(std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json");
  const ViewCamera camera = defaultCamera(opened.scene);
  LightingSettings settings = quickLight();
  settings.converge = 1;  // nothing to shoot: only the edits
  Session session(std::move(opened), settings, camera);
  const auto below = [](double x, double z) { return Ray{{x, 0.9, z}, {0, -1, 0}}; };  // under the ceiling
  SessionInput input;
  input.press = input.held = true;
  input.pointer = below(900000.5, 900000.5);  // the box's top, its origin 0.1 away
  session.frame(input);
  ASSERT_TRUE(session.dragging());
  const uint32_t box = *session.selected();
  input.press = false;
  input.pointer = below(900000.6, 900000.5);
  settle(session, nullptr, input);  // held there
  const ObjectPose good = poseOf(session.scene().objects[box]);
  ASSERT_TRUE(session.dragging()) << session.panel().editReport;

  input.pointer = below(900000.100003, 900000.5);  // its side 3 um from the wall x = 900000
  Changes refused;
  refused.add(session.frame(input));
  // Held still (a ray that misses the resting plane moves nothing) until the verdict is in; it may
  // come within the same frame (the lighting thread can take the pose between the frame's sending
  // and taking).
  SessionInput still = input;
  still.pointer = {{900000.5, 0.9, 900000.5}, {0, 1, 0}};
  settle(session, &refused, still);
  ASSERT_TRUE(session.dragging());
  EXPECT_EQ(poseOf(session.scene().objects[box]), good);
  EXPECT_TRUE(refused.moved.count(box));
  ASSERT_EQ(refused.reports.size(), 1u);
  EXPECT_EQ(refused.reports[0].rfind("move refused: ", 0), 0u) << refused.reports[0];
  EXPECT_NE(session.panel().editReport.find("detail finer than the coordinates resolve"), std::string::npos)
      << session.panel().editReport;

  // Held on the refused spot, the pose is not asked for again: the document does not try to mesh
  // it frame after frame.
  const uint64_t taken = session.panel().light->edits;
  for (int i = 0; i < 5; ++i) settle(session, nullptr, input);
  EXPECT_EQ(session.panel().light->edits, taken);
  EXPECT_EQ(poseOf(session.scene().objects[box]), good);

  // Dragged on to a pose the document takes, the report goes; the drag is one edit.
  input.pointer = below(900000.3, 900000.5);
  session.frame(input);
  settle(session, nullptr, still);
  EXPECT_EQ(session.panel().editReport, "");
  session.frame({});
  EXPECT_FALSE(session.dragging());
  EXPECT_TRUE(session.panel().canUndo);
  SessionInput undo;
  undo.undo = true;
  session.frame(undo);
  EXPECT_EQ(session.scene().objects[box].position, Vec3(900000.4, 0, 900000.4));
}

}  // namespace
}  // namespace engine

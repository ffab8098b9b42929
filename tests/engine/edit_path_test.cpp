// The edit path's contract on real scenes: a move changes only the surfaces whose light it
// changes, and moving an object and moving it back gives the solution of the unmoved scene.
#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace engine {
namespace {

SceneEditor editorFor(const std::string& asset) {
  Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/" + asset);
  MeshedScene meshed = meshScene(scene);
  return SceneEditor(std::move(scene), std::move(meshed));
}

// Moving the office's chair across the floor touches the chair and the floor it stands on,
// nothing else: every other surface keeps its elements and vertices.
TEST(EditPath, AMoveChangesOnlyTheObjectAndWhatItStandsOn) {
  SceneEditor editor = editorFor("office.json");
  const MeshedScene before = editor.meshed();
  const uint32_t chair = *editor.findObject("chair");
  ObjectPose pose = poseOf(editor.scene().objects[chair]);
  pose.position += Vec3{0.3, 0, -0.2};
  editor.setPose(chair, pose);
  std::set<std::string> changed;
  for (uint32_t s = 0; s < before.surfaces.size(); ++s) {
    const bool same = editor.meshed().surfaces[s].mesh.elements == before.surfaces[s].mesh.elements &&
                      editor.meshed().surfaces[s].positions == before.surfaces[s].positions;
    const Surface& surface = editor.scene().surfaces[s];
    if (!same) changed.insert(editor.scene().objects[surface.object].name + (surface.object == chair ? "" : " " + surface.face));
  }
  EXPECT_EQ(changed, (std::set<std::string>{"chair", "room bottom"}));
  for (uint32_t s : editor.remeshed()) EXPECT_EQ(editor.scene().surfaces[s].face, "bottom");
}

// A drag of the office's chair in three steps, then the light takes it: the solver is handed
// the chair's surfaces (moved along, their elements going on by key) and the floor, whose
// footprints changed in its adaptive mesh (its elements away from them going on by key; it was
// meshed anew, every key new), and no other.
TEST(EditPath, AMoveHandsTheSolverOnlyTheObjectAndTheSurfacesWhoseCutOutsChanged) {
  SceneEditor editor = editorFor("office.json");
  radiosity::SolverSettings settings;
  settings.resolution = 64;
  radiosity::Solver solver(radiosityInput(editor.scene(), editor.meshed()), settings);
  solver.solve(0, 20);
  std::vector<std::vector<uint64_t>> solverKeysBefore;
  for (const SurfaceMesh& m : editor.meshed().surfaces) {
    solverKeysBefore.push_back(m.keys);
    std::sort(solverKeysBefore.back().begin(), solverKeysBefore.back().end());
  }
  const uint32_t chair = *editor.findObject("chair");
  ObjectPose pose = poseOf(editor.scene().objects[chair]);
  for (const Vec3 step : {Vec3{0.1, 0, 0}, Vec3{0.1, 0, -0.1}, Vec3{0.1, 0, -0.1}}) {
    pose.position += step;
    editor.setPose(chair, pose);
  }
  const std::vector<radiosity::SurfaceChange> changes = applyEdit(solver, editor.scene(), editor.meshed(), editor.takeEdited());
  const size_t chairSurfaces = editor.surfacesOf(chair).size();
  EXPECT_EQ(changes.size(), chairSurfaces + 1);
  EXPECT_EQ(solver.stats().editedSurfaces, chairSurfaces + 1);
  for (const radiosity::SurfaceChange& c : changes) {
    const Surface& surface = editor.scene().surfaces[c.surface];
    EXPECT_FALSE(c.meshedAnew) << surface.face;
    if (surface.object != chair) {
      EXPECT_EQ(editor.scene().objects[surface.object].name + " " + surface.face, "room bottom");
      // Most of the floor's elements went on.
      const std::vector<uint64_t>& before = solverKeysBefore[c.surface];
      size_t kept = 0;
      for (uint64_t key : c.now.keys) kept += std::binary_search(before.begin(), before.end(), key);
      EXPECT_GT(kept, before.size() * 3 / 4);
    }
  }
  EXPECT_TRUE(editor.takeEdited().empty());  // taken
}

// The box of box-on-floor moved across the floor and back, the light taking each move: the
// floor's elements away from the footprints keep their light (the solver is told no surface was
// meshed anew), the power ledgers close after every move, and back home the floor has its loaded
// mesh again.
TEST(EditPath, AFootprintMovedAndBackKeepsTheFloorsLightAndClosesTheLedger) {
  SceneEditor editor = editorFor("box-on-floor.json");
  const MeshedScene loaded = editor.meshed();
  radiosity::SolverSettings settings;
  settings.resolution = 64;
  settings.overshoot = true;
  radiosity::Solver solver(radiosityInput(editor.scene(), editor.meshed()), settings);
  solver.solve(0.01);
  const uint32_t box = *editor.findObject("box");
  const ObjectPose home = poseOf(editor.scene().objects[box]);
  for (const Vec3 step : {Vec3{0.3, 0, 0}, Vec3{0.3, 0, 0.3}, Vec3{0}}) {
    ASSERT_TRUE(editor.setPose(box, {home.position + step, home.rotateYDeg}));
    for (const radiosity::SurfaceChange& c : applyEdit(solver, editor.scene(), editor.meshed(), editor.takeEdited()))
      EXPECT_FALSE(c.meshedAnew) << editor.scene().surfaces[c.surface].face;
    solver.solve(0.01);
    EXPECT_LT(solver.ledgerResidual(), 1e-12);
  }
  for (size_t s = 0; s < loaded.surfaces.size(); ++s) {
    EXPECT_EQ(editor.meshed().surfaces[s].mesh.elements, loaded.surfaces[s].mesh.elements);
    EXPECT_EQ(editor.meshed().surfaces[s].positions, loaded.surfaces[s].positions);
  }
}

// Mean absolute difference of two solutions' element radiance, over the mean, on the surfaces
// meshed alike in both (all of them, when `sameMeshes`).
double relativeDifference(const radiosity::Solver& a, const radiosity::Solver& b, bool sameMeshes) {
  double difference = 0, level = 0;
  for (uint32_t s = 0; s < a.surfaceCount(); ++s) {
    const auto ra = a.elementRadiance(s), rb = b.elementRadiance(s);
    if (sameMeshes) {
      EXPECT_EQ(ra.size(), rb.size());
    }
    if (ra.size() != rb.size()) continue;
    for (size_t e = 0; e < ra.size(); ++e)
      for (int c = 0; c < 3; ++c) difference += std::abs(ra[e][c] - rb[e][c]), level += std::abs(rb[e][c]);
  }
  return difference / level;
}

// The Cornell box's short block moved away and back: the light converges to what it was (within
// 0.5%, the bound). Solved to 0.2% unshot: at 1%, what is still unshot (which depends on
// the order of shots, and so on the mesh) alone moves the comparison by half a percent.
TEST(EditPath, MovingAnObjectAndBackRestoresTheSolution) {
  SceneEditor editor = editorFor("cornell.json");
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = 2;
  const auto input = radiosityInput(editor.scene(), editor.meshed());
  radiosity::Solver unmoved(input, settings);
  unmoved.solve(0.002);
  auto solver = std::make_unique<radiosity::Solver>(input, settings);
  solver->solve(0.002);
  const uint32_t block = *editor.findObject("short block");
  const ObjectPose home = poseOf(editor.scene().objects[block]);
  editor.setPose(block, {home.position + Vec3{120, 0, 100}, home.rotateYDeg + 30});
  applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited());
  solver->solve(0.002);
  const double moved = relativeDifference(*solver, unmoved, false);
  editor.setPose(block, home);
  applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited());
  solver->solve(0.002);
  EXPECT_GT(moved, 0.01);  // the move itself changed the light
  EXPECT_LT(relativeDifference(*solver, unmoved, true), 0.005);
}

// After moves, corrections take back exactly what was shot: no element is left with light below
// zero beyond rounding (on main some were, and the display hid it), the display shows none, and
// the picture's exposure stays a number (it was NaN, and `walkrad render --move` wrote black PNGs).
// The power ledgers close to rounding after every move: they drifted by 9.4e-10 of the emitted
// power a move (a cabinet side's frame, made from a window, held a pixel more than the hemisphere,
// and its correction sent that much more than its take-back took), which tripped the sanitizer
// build's check after the second move.
TEST(EditPath, TheDisplayAfterAMoveHasNoNegativeLight) {
  SceneEditor editor = editorFor("office.json");
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = 2;
  settings.overshoot = true;  // as walkrad render solves
  auto solver = std::make_unique<radiosity::Solver>(radiosityInput(editor.scene(), editor.meshed()), settings);
  solver->solve(0.01);
  const uint32_t chair = *editor.findObject("chair");
  ObjectPose pose = poseOf(editor.scene().objects[chair]);
  double lowest = 0, highest = 0;
  for (const Vec3 step : {Vec3{0.5, 0, -0.3}, Vec3{-0.4, 0, 0.5}, Vec3{0.3, 0, 0.4}, Vec3{-0.6, 0, -0.2}, Vec3{0.2, 0, -0.5}}) {
    pose.position += step;
    editor.setPose(chair, pose);
    applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited());
    solver->solve(0.01);
    EXPECT_LT(solver->ledgerResidual(), 1e-12);
    for (uint32_t s = 0; s < solver->surfaceCount(); ++s)
      for (const glm::dvec3& r : solver->vertexRadiance(s, solver->ambient()))
        for (int c = 0; c < 3; ++c) lowest = std::min(lowest, r[c]), highest = std::max(highest, r[c]);
  }
  EXPECT_GE(lowest, -1e-9 * highest);
  DisplayMesh mesh = displayMesh(editor.scene(), editor.meshed());
  setRadiance(mesh, *solver);
  for (const SurfaceDisplay& s : mesh.surfaces)
    for (const glm::vec3& r : s.radiance) ASSERT_TRUE(r.x >= 0 && r.y >= 0 && r.z >= 0) << r.x << " " << r.y << " " << r.z;
  const double exposure = autoExposure(mesh);
  EXPECT_TRUE(std::isfinite(exposure) && exposure > 0) << exposure;
}

}  // namespace
}  // namespace engine

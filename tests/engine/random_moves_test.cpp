// 200 random moves through the edit path (editor, cut-outs, the solution taking the edit): every
// mesh stays exact and conforming, the light keeps its energy, and moving everything back
// restores the loaded scene exactly.
#include "engine/document/lighting.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "mesher/mesh_check.h"
#include "tests/engine/test_scenes.h"

#include <gtest/gtest.h>

#include <random>

namespace engine {
namespace {

// The test room with its box and a second, smaller crate.
Scene roomWithTwoBoxes() {
  Json json = test::baseScene();
  json["objects"].push_back(Json::parse(R"({ "name": "crate", "position": [2.5, 0, 1.8], "rotate_y": 20,
    "solids": [ { "profile": [[0, 0], [0.5, 0], [0.5, 0.4], [0, 0.4]], "from": 0, "to": 0.4, "material": "white" } ] })"));
  return test::parse(json);
}

TEST(RandomMoves, TwoHundredMovesKeepMeshesAndEnergyAndComeBack) {
  const Scene loaded = roomWithTwoBoxes();
  MeshedScene meshed = meshScene(loaded);
  const MeshedScene meshedLoaded = meshed;
  SceneEditor editor(loaded, std::move(meshed));
  const uint32_t movable[] = {*editor.findObject("box"), *editor.findObject("crate")};
  radiosity::SolverSettings settings;
  settings.resolution = 64;  // coarse frames: the test is about the edit path, not accuracy
  auto solver = std::make_unique<radiosity::Solver>(radiosityInput(editor.scene(), editor.meshed()), settings);
  solver->solve(0, 20);

  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(-1.5, 2.5), z(-1.5, 1.5), turn(-180, 180), unit(0, 1);
  size_t footprints = 0;
  for (int move = 0; move < 200; ++move) {
    SCOPED_TRACE(move);
    const uint32_t object = movable[move % 2];
    ObjectPose pose{{x(random), unit(random) < 0.2 ? 0.3 * unit(random) : 0.0, z(random)},
                    unit(random) < 0.5 ? 90.0 * std::floor(4 * unit(random)) : turn(random)};
    editor.setPose(object, pose);
    for (uint32_t s : editor.remeshed()) {
      const mesher::MeshCheck check = mesher::checkMesh(editor.meshed().surfaces[s].polygon, editor.meshed().surfaces[s].mesh);
      EXPECT_EQ(check.tVertices, 0u);
      EXPECT_EQ(check.notCounterClockwiseOrConvex, 0u);
      EXPECT_NEAR(check.elementArea, check.polygonArea, 1e-9 * check.polygonArea);
    }
    footprints += test::surfaceOf(editor.scene(), "room", "bottom").contactHoles;
    applyEdit(*solver, editor.scene(), editor.meshed(), editor.takeEdited());
    while (solver->pendingCorrections() > 0) solver->step();
    solver->solve(0, 5);
    ASSERT_LT(solver->ledgerResidual(), 1e-9);
  }
  EXPECT_GT(footprints, 20u);  // the boxes stood on the floor often enough to be cut out

  for (uint32_t object : movable) editor.setPose(object, poseOf(loaded.objects[object]));
  for (size_t s = 0; s < loaded.surfaces.size(); ++s) {
    EXPECT_EQ(editor.scene().surfaces[s].outer, loaded.surfaces[s].outer);
    EXPECT_EQ(editor.scene().surfaces[s].holes, loaded.surfaces[s].holes);
    EXPECT_EQ(editor.meshed().surfaces[s].mesh.elements, meshedLoaded.surfaces[s].mesh.elements);
    EXPECT_EQ(editor.meshed().surfaces[s].positions, meshedLoaded.surfaces[s].positions);
  }
}

}  // namespace
}  // namespace engine

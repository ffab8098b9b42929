// A move costs what it concerns, not the scene: on a scene of a million elements, moving one box
// cuts, meshes and sends only its own surfaces and the tile it stands on.
#include "engine/document/scene_editor.h"
#include "engine/document/scene_view.h"
#include "engine/geometry/meshed_scene.h"
#include "tests/engine/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace engine {
namespace {

// n x n floor tiles, 2 m square, 3 m apart (one fixed object), each with a 1 m box standing on
// it (an object each, "box I J", turning about its middle); at patches of 0.25 m a cell meshes into about 270 elements.
Json tiledScene(int n) {
  Json scene = test::baseScene();
  scene["settings"]["patch_size"] = 0.25;
  Json tiles = {{"name", "tiles"}, {"movable", false}, {"solids", Json::array()}};
  Json objects = Json::array();
  const auto square = [](double x, double z, double side) {
    return Json::array({{x, z}, {x + side, z}, {x + side, z + side}, {x, z + side}});
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = 3.0 * i, z = 3.0 * j;
      tiles["solids"].push_back({{"profile", square(x, z, 2)}, {"from", -0.1}, {"to", 0}, {"material", "white"}});
      objects.push_back({{"name", "box " + std::to_string(i) + " " + std::to_string(j)},
                         {"position", {x + 1, 0, z + 1}},
                         {"solids", Json::array({{{"profile", square(-0.5, -0.5, 1)}, {"from", 0}, {"to", 1},
                                                        {"material", "white"}}})}});
    }
  objects.push_back(tiles);
  scene["objects"] = objects;
  return scene;
}

TEST(EditCost, AMoveOnAMillionElementsTouchesOnlyTheBoxAndItsTile) {
  const Scene scene = test::parse(tiledScene(62));
  const MeshedScene meshed = meshScene(scene);
  size_t elements = 0;
  for (const SurfaceMesh& m : meshed.surfaces) elements += m.mesh.elements.size();
  ASSERT_GE(elements, 1'000'000u);
  SceneEditor editor(scene, meshed);
  SceneView view(scene, meshed);
  const uint32_t box = *editor.findObject("box 31 31");
  // The top of the tile under box 31 31 (x and z from 93 to 95).
  uint32_t tileIndex = 0;
  while (!(scene.surfaces[tileIndex].face == "top" && scene.surfaces[tileIndex].normal.y > 0.5 &&
           std::abs(test::centroidOf(scene.surfaces[tileIndex]).x - 94) < 0.5 &&
           std::abs(test::centroidOf(scene.surfaces[tileIndex]).z - 94) < 0.5 && scene.surfaces[tileIndex].outer[0].y == 0))
    ASSERT_LT(++tileIndex, scene.surfaces.size());
  const Surface& tile = scene.surfaces[tileIndex];
  ASSERT_EQ(tile.contactHoles, 1u);

  const ObjectPose pose{Vec3{94.25, 0, 94.25}, 30};  // still on its tile
  ASSERT_TRUE(editor.setPose(box, pose));
  std::vector<uint32_t> expected = editor.surfacesOf(box);
  expected.push_back(tileIndex);
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(editor.recut(), expected);
  EXPECT_EQ(editor.remeshed(), std::vector<uint32_t>{tileIndex});
  // The tile's footprint moved in its adaptive mesh: its elements near the box's old and new
  // footprints were removed and added, the rest went on (on this 2 m tile under a 1 m box turned
  // by 30 degrees, 31 of 48 go, 51 come).
  ASSERT_EQ(editor.holeEdits().size(), 1u);
  const SceneEditor::HoleEdit& holeEdit = editor.holeEdits().front();
  const size_t tileElements = meshed.surfaces[tileIndex].mesh.elements.size();
  std::printf("tile of %zu elements: %zu removed, %zu added\n", tileElements, holeEdit.removed, holeEdit.added);
  EXPECT_EQ(holeEdit.surface, tileIndex);
  EXPECT_LT(holeEdit.removed, tileElements * 3 / 4);
  EXPECT_EQ(editor.meshed().surfaces[tileIndex].mesh.elements.size(), tileElements - holeEdit.removed + holeEdit.added);
  std::vector<uint32_t> edited;
  for (const EditedSurface& e : editor.takeEdited()) {
    edited.push_back(e.surface);
    EXPECT_FALSE(e.meshedAnew);
  }
  EXPECT_EQ(edited, expected);
  // The footprint moved with the box.
  EXPECT_EQ(editor.scene().surfaces[tileIndex].contactHoles, 1u);
  EXPECT_NE(editor.scene().surfaces[tileIndex].holes, tile.holes);
  for (uint32_t s = 0; s < scene.surfaces.size(); ++s)
    if (!std::binary_search(expected.begin(), expected.end(), s)) {
      ASSERT_EQ(editor.scene().surfaces[s].holes, scene.surfaces[s].holes) << s;
      ASSERT_EQ(editor.meshed().surfaces[s].positions, meshed.surfaces[s].positions) << s;
    }

  // The view shows the move, and takes the document's meshes of just those surfaces.
  ASSERT_TRUE(view.setPose(box, pose));
  std::vector<SurfaceUpdate> updates;
  for (uint32_t s : expected)
    updates.push_back({s, editor.meshed().surfaces[s], pose, s == tileIndex, surfaceOutline(editor.meshed().surfaces[s])});
  EXPECT_EQ(view.take({nullptr, updates, {}}).surfaces, std::vector<uint32_t>{tileIndex});  // the box moved along
  EXPECT_EQ(view.display().elements, elements - meshed.surfaces[tileIndex].mesh.elements.size() +
                                         editor.meshed().surfaces[tileIndex].mesh.elements.size());
}

}  // namespace
}  // namespace engine

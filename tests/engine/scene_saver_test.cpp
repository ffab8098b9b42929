// Saving poses back into the scene's text: what is saved loads as what was edited.
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/scene_loader.h"
#include "engine/io/scene_saver.h"
#include "tests/engine/test_scenes.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

TEST(SceneSaver, SavedPosesLoadAsEditedAndNothingElseChanges) {
  const std::string text = test::baseScene().dump(2);
  Scene scene = parseScene(text, "test.json");
  MeshedScene meshed = meshScene(scene);
  SceneEditor editor(std::move(scene), std::move(meshed));
  const uint32_t box = *editor.findObject("box");
  editor.setPose(box, {Vec3{0.75, 0, -0.5}, 30});

  const std::string saved = sceneTextWithPoses(text, editor.scene());
  const Scene reloaded = parseScene(saved, "test.json");
  EXPECT_EQ(reloaded.objects[box].position, (Vec3{0.75, 0, -0.5}));
  EXPECT_EQ(reloaded.objects[box].rotateYDeg, 30);
  ASSERT_EQ(reloaded.surfaces.size(), editor.scene().surfaces.size());
  for (size_t s = 0; s < reloaded.surfaces.size(); ++s)
    for (size_t i = 0; i < reloaded.surfaces[s].outer.size(); ++i)
      EXPECT_NEAR(glm::length(reloaded.surfaces[s].outer[i] - editor.scene().surfaces[s].outer[i]), 0, 1e-12);

  // The room never moved: no pose appears for it; everything else is the file's own.
  Json savedJson = Json::parse(saved), original = Json::parse(text);
  EXPECT_FALSE(savedJson["objects"][0].contains("position"));
  savedJson["objects"][box].erase("position");
  savedJson["objects"][box].erase("rotate_y");
  EXPECT_EQ(savedJson, original);
}

}  // namespace
}  // namespace engine

// Saving poses back into the scene's text: what is saved loads as what was edited.
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/scene_loader.h"
#include "engine/io/scene_saver.h"
#include "tests/engine/test_scenes.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

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

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The shipped kitchen, its arrays on one line each: a chair moved and turned changes its two pose
// lines and nothing else of the file, as a scene under version control wants.
TEST(SceneSaver, AMoveChangesTheLinesOfItsPoseAndNoOther) {
  std::ifstream file(std::string(WALKRAD_ASSETS) + "/kitchen.json");
  std::ostringstream read;
  read << file.rdbuf();
  const std::string text = read.str();
  Scene scene = parseScene(text, "kitchen.json");
  MeshedScene meshed = meshScene(scene);
  SceneEditor editor(std::move(scene), std::move(meshed));
  const uint32_t chair = *editor.findObject("chair 1");
  ASSERT_TRUE(editor.setPose(chair, {Vec3{92.5, 0, 140.25}, 18}));

  const std::string saved = sceneTextWithPoses(text, editor.scene());
  const std::vector<std::string> before = lines(text), after = lines(saved);
  ASSERT_EQ(after.size(), before.size());
  std::vector<std::string> changed;
  for (size_t i = 0; i < before.size(); ++i)
    if (after[i] != before[i]) changed.push_back(after[i]);
  EXPECT_EQ(changed, (std::vector<std::string>{"   \"position\": [92.5, 0.0, 140.25],", "   \"rotate_y\": 18.0,"}));
  const Scene reloaded = parseScene(saved, "kitchen.json");
  EXPECT_EQ(reloaded.objects[chair].position, (Vec3{92.5, 0, 140.25}));
  EXPECT_EQ(reloaded.objects[chair].rotateYDeg, 18);
}

// An object that states no pose gets one added after its last member, laid out as its members
// are (on lines of their own, or on the object's one line); the rest of the text stays as it was.
TEST(SceneSaver, APoseTheFileDoesNotStateIsAddedInItsLayout) {
  for (const int indent : {1, -1}) {
    SCOPED_TRACE(indent);
    Json base = test::baseScene();
    base["objects"][0]["movable"] = true;
    const std::string text = base.dump(indent);
    Scene scene = parseScene(text, "test.json");
    MeshedScene meshed = meshScene(scene);
    SceneEditor editor(std::move(scene), std::move(meshed));
    ASSERT_FALSE(base["objects"][0].contains("position"));
    ASSERT_FALSE(base["objects"][0].contains("rotate_y"));
    editor.setPose(0, {Vec3{0.5, 0, 0.25}, -90});

    const std::string saved = sceneTextWithPoses(text, editor.scene());
    const Scene reloaded = parseScene(saved, "test.json");
    EXPECT_EQ(reloaded.objects[0].position, (Vec3{0.5, 0, 0.25}));
    EXPECT_EQ(reloaded.objects[0].rotateYDeg, -90);
    // One run of added text: the original before it and after it.
    size_t head = 0;
    while (head < text.size() && text[head] == saved[head]) ++head;
    const std::string added = saved.substr(head, saved.size() - text.size());
    EXPECT_EQ(saved.substr(head + added.size()), text.substr(head));
    const std::string between = indent > 0 ? ",\n   " : ", ";
    EXPECT_EQ(added, between + "\"position\": [0.5, 0.0, 0.25]" + between + "\"rotate_y\": -90.0");
  }
}

}  // namespace
}  // namespace engine

#include "app/window/scene_panel.h"

#include <imgui.h>

#include <filesystem>
#include <vector>

namespace app {

namespace {

void objectList(const engine::Scene& scene) {
  std::vector<int> surfacesOf(scene.objects.size(), 0);
  for (const engine::Surface& s : scene.surfaces) ++surfacesOf[s.object];
  if (!ImGui::CollapsingHeader("Objects", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::BeginChild("objects", ImVec2(0, 160), true);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const engine::Object& o = scene.objects[i];
    ImGui::Text("%s", o.name.c_str());
    ImGui::SameLine(150);
    ImGui::TextDisabled("%zu solids, %d surfaces%s", o.solids.size(), surfacesOf[i], o.movable ? "" : ", fixed");
  }
  ImGui::EndChild();
}

void cameraList(const engine::Scene& scene, PanelState& state) {
  if (!ImGui::CollapsingHeader("Cameras", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (scene.cameras.empty()) ImGui::TextDisabled("the scene has no cameras");
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    if (ImGui::Selectable(scene.cameras[i].name.c_str(), false)) state.jumpToCamera = static_cast<int>(i);
}

}  // namespace

void drawScenePanel(const engine::Scene& scene, const engine::DisplayMesh& mesh, PanelState& state) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("walkrad");
  ImGui::Text("%s (%s)", std::filesystem::path(scene.file).filename().c_str(), scene.units.c_str());
  ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "Shading: emission + reflectance x ambient.");
  ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "No radiosity solution yet.");
  ImGui::TextDisabled("Mesh: modified quadtree (thesis ch. 5)");
  ImGui::Separator();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::Text("%.1f fps (%.2f ms a frame)", io.Framerate, 1000.0f / io.Framerate);
  ImGui::Text("%zu objects, %zu surfaces", scene.objects.size(), scene.surfaces.size());
  ImGui::Text("%zu patches (%zu quads), %zu vertices", mesh.elements, mesh.quads, mesh.positions.size());
  ImGui::Separator();
  ImGui::SliderFloat("exposure", &state.exposure, 1e-3f, 1e3f, "%.3g", ImGuiSliderFlags_Logarithmic);
  ImGui::Checkbox("wireframe", &state.wireframe);
  ImGui::SameLine();
  if (ImGui::Button("screenshot (F12)")) state.screenshotRequested = true;
  if (!state.lastScreenshot.empty()) ImGui::TextDisabled("saved %s", state.lastScreenshot.c_str());
  ImGui::Text("walking speed %.3g %s/s (wheel)", state.walkSpeed, scene.units.c_str());
  ImGui::TextDisabled("WASD walk, right mouse look, Q/E up/down, Shift fast");
  cameraList(scene, state);
  objectList(scene);
  ImGui::End();
}

}  // namespace app

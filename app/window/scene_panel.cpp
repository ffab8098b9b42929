#include "app/window/scene_panel.h"

#include <imgui.h>

#include <filesystem>
#include <vector>

namespace app {

namespace {

void objectList(const engine::Scene& scene) {
  std::vector<int> surfacesOf(scene.objects.size(), 0);
  for (const engine::Surface& s : scene.surfaces) ++surfacesOf[s.object];
  if (!ImGui::CollapsingHeader("Objects")) return;
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

void lightingSection(const engine::LightingSnapshot& lighting, PanelState& state) {
  if (!ImGui::CollapsingHeader("Radiosity", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Text("%llu shots, %.0f shots/s", static_cast<unsigned long long>(lighting.shots), lighting.shotsPerSecond);
  ImGui::Text("unshot energy %.3g%% of emitted", 100 * lighting.unshotFraction);
  if (lighting.pendingCorrections > 0) ImGui::Text("%zu corrections pending", lighting.pendingCorrections);
  ImGui::ProgressBar(static_cast<float>(1 - lighting.unshotFraction), ImVec2(-1, 0),
                     lighting.converged ? "converged" : lighting.paused ? "paused" : "shooting");
  ImGui::Text("%zu elements, %zu shooting patches", lighting.elements, lighting.patches);
  if (lighting.adaptive) ImGui::Text("adaptive refinement: %llu passes", static_cast<unsigned long long>(lighting.adaptivePasses));
  if (!lighting.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "stopped: %s", lighting.error.c_str());
  ImGui::Checkbox("pause", &state.paused);
  ImGui::SameLine();
  if (ImGui::Button("restart")) state.restartRequested = true;
}

void editSection(const engine::Scene& scene, PanelState& state) {
  if (!ImGui::CollapsingHeader("Edit", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (state.selected.empty()) {
    ImGui::TextDisabled("click an object to select it");
  } else {
    ImGui::Text("selected: %s%s", state.selected.c_str(), state.selectedMovable ? "" : " (fixed)");
    ImGui::Text("at (%.3f, %.3f, %.3f) %s, turned %.3g deg", state.selectedPosition.x, state.selectedPosition.y,
                state.selectedPosition.z, scene.units.c_str(), state.selectedTurn);
  }
  ImGui::TextDisabled("left drag: move on its resting plane; wheel while dragging: height");
  ImGui::TextDisabled("R / Shift+R: turn 15 deg; Esc: deselect");
  ImGui::BeginDisabled(!state.canUndo);
  if (ImGui::Button("undo (Ctrl+Z)")) state.undoRequested = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!state.canRedo);
  if (ImGui::Button("redo (Ctrl+Y)")) state.redoRequested = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button(state.unsaved ? "save* (Ctrl+S)" : "save (Ctrl+S)")) state.saveRequested = true;
  if (!state.saveReport.empty()) ImGui::TextDisabled("%s", state.saveReport.c_str());
  if (!state.editReport.empty()) ImGui::TextWrapped("move refused: %s", state.editReport.c_str());
}

}  // namespace

void drawScenePanel(const engine::Scene& scene, const engine::DisplayMesh& mesh, const engine::LightingSnapshot& lighting,
                    PanelState& state) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("walkrad");
  ImGui::Text("%s (%s)", std::filesystem::path(scene.file).filename().c_str(), scene.units.c_str());
  ImGui::TextDisabled("Mesh: modified quadtree (thesis ch. 5); light: progressive radiosity");
  ImGui::TextDisabled("on an emulated Pixel-Planes 5, ambient term until converged");
  ImGui::TextDisabled("drop a .json, .gltf or .glb file here to open it");
  if (!state.openReport.empty()) ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", state.openReport.c_str());
  ImGui::Separator();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::Text("%.1f fps (%.2f ms a frame)", io.Framerate, 1000.0f / io.Framerate);
  ImGui::Text("%zu objects, %zu surfaces", scene.objects.size(), scene.surfaces.size());
  ImGui::Text("%zu elements (%zu quads), %zu vertices", mesh.elements, mesh.quads, mesh.vertices);
  ImGui::Text("%zu chunks drawn, %zu outside the view", state.chunksDrawn, state.chunksCulled);
  ImGui::Text("%zu triangles drawn", state.trianglesDrawn);
  ImGui::SameLine();
  ImGui::Checkbox("level of detail", &state.levelOfDetail);
  ImGui::Separator();
  lightingSection(lighting, state);
  editSection(scene, state);
  ImGui::Separator();
  ImGui::SliderFloat("exposure", &state.exposure, 1e-3f, 1e3f, "%.3g", ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  if (ImGui::Button("auto")) state.autoExposureRequested = true;
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

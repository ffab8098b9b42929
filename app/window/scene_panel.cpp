#include "app/window/scene_panel.h"

#include <imgui.h>

namespace app {

namespace {

void objectList(const engine::PanelModel& model) {
  if (!ImGui::CollapsingHeader("Objects")) return;
  ImGui::BeginChild("objects", ImVec2(0, 160), true);
  for (const engine::PanelObject& o : model.objects) {
    ImGui::Text("%s", o.name.c_str());
    ImGui::SameLine(150);
    ImGui::TextDisabled("%zu solids, %zu surfaces%s", o.solids, o.surfaces, o.movable ? "" : ", fixed");
  }
  ImGui::EndChild();
}

void cameraList(const engine::PanelModel& model, engine::SessionInput& next) {
  if (!ImGui::CollapsingHeader("Cameras", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (model.cameras.empty()) ImGui::TextDisabled("the scene has no cameras");
  for (size_t i = 0; i < model.cameras.size(); ++i)
    if (ImGui::Selectable(model.cameras[i].c_str(), false)) next.jumpToCamera = i;
}

void lightingSection(const engine::PanelModel& model, engine::SessionInput& next) {
  const engine::LightingSnapshot& lighting = *model.light;
  if (!ImGui::CollapsingHeader("Radiosity", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Text("%llu shots, %.0f shots/s", static_cast<unsigned long long>(lighting.shots), lighting.shotsPerSecond);
  ImGui::Text("unshot energy %.3g%% of emitted", 100 * lighting.unshotFraction);
  if (model.posesWaiting > 0) ImGui::Text("%zu moves waiting for the solver", model.posesWaiting);
  if (lighting.pendingCorrections > 0) ImGui::Text("%zu corrections pending", lighting.pendingCorrections);
  ImGui::ProgressBar(static_cast<float>(1 - lighting.unshotFraction), ImVec2(-1, 0),
                     lighting.converged ? "converged" : lighting.paused ? "paused" : "shooting");
  ImGui::Text("%zu elements, %zu shooting patches", lighting.elements, lighting.patches);
  if (lighting.adaptive) ImGui::Text("adaptive refinement: %llu passes", static_cast<unsigned long long>(lighting.adaptivePasses));
  if (!lighting.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "stopped: %s", lighting.error.c_str());
  bool paused = model.paused;
  if (ImGui::Checkbox("pause", &paused)) next.pause = paused;
  ImGui::SameLine();
  if (ImGui::Button("restart")) next.restart = true;
}

void editSection(const engine::PanelModel& model, engine::SessionInput& next) {
  if (!ImGui::CollapsingHeader("Edit", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (!model.selected) {
    ImGui::TextDisabled("click an object to select it");
  } else {
    const engine::PanelSelection& s = *model.selected;
    ImGui::Text("selected: %s%s", s.name.c_str(), s.movable ? "" : " (fixed)");
    ImGui::Text("at (%.3f, %.3f, %.3f) %s, turned %.3g deg", s.position.x, s.position.y, s.position.z, model.units.c_str(),
                s.turnDeg);
  }
  ImGui::TextDisabled("left drag: move on its resting plane; wheel while dragging: height");
  ImGui::TextDisabled("R / Shift+R: turn 15 deg; Esc: deselect");
  ImGui::BeginDisabled(!model.canUndo);
  if (ImGui::Button("undo (Ctrl+Z)")) next.undo = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!model.canRedo);
  if (ImGui::Button("redo (Ctrl+Y)")) next.redo = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button(model.unsaved ? "save* (Ctrl+S)" : "save (Ctrl+S)")) next.save = true;
  if (!model.saveReport.empty()) ImGui::TextDisabled("%s", model.saveReport.c_str());
  if (!model.editReport.empty()) ImGui::TextWrapped("move refused: %s", model.editReport.c_str());
}

}  // namespace

void drawScenePanel(const engine::PanelModel& model, PanelState& state, engine::SessionInput& next) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("walkrad");
  ImGui::Text("%s (%s)", model.file.c_str(), model.units.c_str());
  ImGui::TextDisabled("Mesh: modified quadtree (thesis ch. 5); light: progressive radiosity");
  ImGui::TextDisabled("on an emulated Pixel-Planes 5, ambient term until converged");
  ImGui::TextDisabled("drop a .json, .gltf or .glb file here to open it");
  if (!state.openReport.empty()) ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", state.openReport.c_str());
  ImGui::Separator();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::Text("%.1f fps (%.2f ms a frame)", io.Framerate, 1000.0f / io.Framerate);
  ImGui::Text("%zu objects, %zu surfaces", model.objects.size(), model.surfaces);
  ImGui::Text("%zu elements (%zu quads), %zu vertices", model.elements, model.quads, model.vertices);
  ImGui::Text("%zu chunks drawn, %zu outside the view", state.chunksDrawn, state.chunksCulled);
  ImGui::Text("%zu triangles drawn", state.trianglesDrawn);
  ImGui::SameLine();
  ImGui::Checkbox("level of detail", &state.levelOfDetail);
  ImGui::Separator();
  lightingSection(model, next);
  editSection(model, next);
  ImGui::Separator();
  ImGui::SliderFloat("exposure", &state.exposure, 1e-3f, 1e3f, "%.3g", ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  if (ImGui::Button("auto")) state.autoExposureRequested = true;
  ImGui::Checkbox("wireframe", &state.wireframe);
  ImGui::SameLine();
  if (ImGui::Button("screenshot (F12)")) state.screenshotRequested = true;
  if (!state.lastScreenshot.empty()) ImGui::TextDisabled("saved %s", state.lastScreenshot.c_str());
  ImGui::Text("walking speed %.3g %s/s (wheel)", model.walkSpeed, model.units.c_str());
  ImGui::TextDisabled("WASD walk, right mouse look, Q/E up/down, Shift fast");
  cameraList(model, next);
  objectList(model);
  ImGui::End();
}

}  // namespace app

#include "app/window/walk_window.h"

#include <glad/gl.h>  // before any other GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/cli/peak_memory.h"
#include "app/gl/scene_renderer.h"
#include "app/image/atomic_file.h"
#include "app/image/image.h"
#include "app/view/view_camera.h"
#include "app/window/frame_times.h"
#include "app/window/scene_edits.h"
#include "app/window/scene_panel.h"
#include "app/window/walk_controls.h"
#include "engine/diagnostics.h"
#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/input_file.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"

#include <nlohmann/json.hpp>

#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>

namespace app {

namespace {

struct GlfwSession {
  GlfwSession() : ok(glfwInit() == GLFW_TRUE) {}
  ~GlfwSession() {
    if (ok) glfwTerminate();
  }
  bool ok;
};

struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the panel's layout is the program's, not a file's
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
};

// Wheel notches since the last frame; GLFW reports them through a callback that Dear ImGui
// chains to.
double g_scroll = 0;
void onScroll(GLFWwindow*, double, double y) { g_scroll += y; }

// The solver's progress on the command line too: a line about every two seconds while it
// shoots, and one when it converges.
class ProgressLine {
 public:
  explicit ProgressLine(std::string scene) : scene_(std::move(scene)) {}
  void report(const engine::LightingSnapshot& s) {
    if (!s.error.empty() && s.error != errorShown_) std::cerr << "walkrad view: the solver stopped: " << s.error << std::endl;
    errorShown_ = s.error;
    const double now = glfwGetTime();
    if (s.converged && !convergedShown_) {
      std::cout << "walkrad view: " << scene_ << ": converged after " << s.shots << " shots in " << s.solveSeconds
                << " s (unshot " << 100 * s.unshotFraction << "%)" << std::endl;
      convergedShown_ = true;
    } else if (!s.converged && s.shots > 0 && now - last_ >= 2) {
      std::cout << "walkrad view: " << scene_ << ": " << s.shots << " shots, unshot " << 100 * s.unshotFraction << "%"
                << std::endl;
      last_ = now;
    }
    if (!s.converged) convergedShown_ = false;
  }

 private:
  std::string scene_, errorShown_;
  double last_ = 0;
  bool convergedShown_ = false;
};

std::string screenshotName(const engine::Scene& scene) {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  const std::string stem = "walkrad-" + std::filesystem::path(scene.file).stem().string() + "-" + stamp;
  // Two in one second must not overwrite the first.
  std::string name = stem + ".png";
  for (int n = 2; std::filesystem::exists(name); ++n) name = stem + "-" + std::to_string(n) + ".png";
  return name;
}

bool controlHeld(GLFWwindow* window) {
  return glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
}

// Key presses since the last frame, with their modifiers, for shortcuts (Ctrl+Z and the like):
// a callback sees every press, however short, and the modifiers held with it. GLFW reports them
// through a callback that Dear ImGui chains to.
struct KeyPress {
  int key, mods;
};
std::vector<KeyPress> g_presses;
void onKey(GLFWwindow*, int key, int, int action, int mods) {
  if (action == GLFW_PRESS) g_presses.push_back({key, mods});
}

// Whether `key` was pressed with exactly the modifiers `mods` (of Shift and Ctrl) since the last
// frame, and not into the panel.
bool pressed(int key, int mods = 0) {
  if (ImGui::GetIO().WantCaptureKeyboard) return false;
  for (const KeyPress& p : g_presses)
    if (p.key == key && (p.mods & (GLFW_MOD_SHIFT | GLFW_MOD_CONTROL)) == mods) return true;
  return false;
}

// The ray under the cursor, for picking and dragging.
Ray cursorRay(GLFWwindow* window, const ViewCamera& camera) {
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  glm::dvec2 mouse;
  glfwGetCursorPos(window, &mouse.x, &mouse.y);
  const glm::dvec2 ndc{2 * mouse.x / std::max(width, 1) - 1, 1 - 2 * mouse.y / std::max(height, 1)};
  return {camera.position, rayThrough(camera, static_cast<double>(width) / std::max(height, 1), ndc)};
}

WalkInput readWalkInput(GLFWwindow* window, glm::dvec2& lastMouse, bool& looking, bool wheelTaken) {
  WalkInput input;
  const ImGuiIO& io = ImGui::GetIO();
  auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
  if (!io.WantCaptureKeyboard && !controlHeld(window)) {
    input.forward = down(GLFW_KEY_W);
    input.back = down(GLFW_KEY_S);
    input.left = down(GLFW_KEY_A);
    input.right = down(GLFW_KEY_D);
    input.up = down(GLFW_KEY_E) || down(GLFW_KEY_PAGE_UP);
    input.down = down(GLFW_KEY_Q) || down(GLFW_KEY_PAGE_DOWN);
    input.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
  }
  glm::dvec2 mouse;
  glfwGetCursorPos(window, &mouse.x, &mouse.y);
  const bool rightHeld = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (rightHeld && !looking && !io.WantCaptureMouse) looking = true;  // a look starts off the panel
  if (!rightHeld) looking = false;
  if (looking) {
    input.lookDx = mouse.x - lastMouse.x;
    input.lookDy = mouse.y - lastMouse.y;
  }
  lastMouse = mouse;
  if (!io.WantCaptureMouse && !wheelTaken) input.scroll = g_scroll;
  return input;
}

// A scene opened in the window: its file's text (kept for saving poses into it; empty for a
// glTF model, which is never written) and the scene.
struct OpenedScene {
  std::string path, text;
  engine::Scene scene;
};

// Throws SceneError for a file that is not a valid scene or model.
OpenedScene openScene(const std::string& path, const engine::LoadOptions& load, std::optional<double> patchSize) {
  OpenedScene opened;
  opened.path = path;
  if (engine::isGltfPath(path)) {
    opened.scene = engine::loadScene(path, load);
  } else {
    engine::refuseGltfOptions(path, load);
    opened.text = engine::readInputFile(path);
    opened.scene = engine::parseScene(opened.text, path);
  }
  if (patchSize) engine::overridePatchSize(opened.scene, *patchSize);
  return opened;
}

// Files dropped onto the window since the last frame (GLFW reports them through a callback).
std::vector<std::string> g_dropped;
void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

// What `view --stats` reports: the frames' times, and the last scene's display and light.
struct ViewRecord {
  FrameTimes frames;
  size_t elements = 0, vertices = 0;
  FrameCounts chunks;  // of the last frame
  uint64_t shots = 0;
  double unshotFraction = 1;
};

void writeViewStats(const std::string& path, const ViewRecord& record) {
  const nlohmann::ordered_json stats = {
      {"frames", record.frames.count()},
      {"frame_ms_median", record.frames.quantile(0.5)},
      {"frame_ms_p95", record.frames.quantile(0.95)},
      {"frame_ms_max", record.frames.quantile(1)},
      {"elements", record.elements},
      {"vertices", record.vertices},
      {"chunks_drawn", record.chunks.chunksDrawn},
      {"chunks_culled", record.chunks.chunksCulled},
      {"triangles_drawn", record.chunks.triangles},
      {"shots", record.shots},
      {"unshot_fraction", record.unshotFraction},
      {"peak_rss_mb", peakResidentMegabytes()},
  };
  writeFileAtomically(path, stats.dump(2) + "\n");
}

// Walks through one scene until the window closes, the frame count runs out (nothing returned)
// or a file dropped onto the window opens (returned: the window goes on with it). A dropped file
// that does not open leaves the scene as it is and says why in the panel. `frame` counts the
// window's frames across the scenes it shows, so --frames bounds the whole run; `record` takes
// each frame's time, from the top of its loop to the swap.
std::optional<OpenedScene> walkScene(GLFWwindow* window, const ViewOptions& options, OpenedScene opened, ViewCamera camera,
                                     int& frame, int& exitCode, ViewRecord& record) {
  // The lighting thread's document and the window's view start from the same meshes.
  engine::MeshedScene meshed = engine::meshScene(opened.scene);
  SceneEdits edits(opened.path, std::move(opened.text), engine::SceneView(opened.scene, meshed));
  const engine::Scene& scene = edits.view().scene();  // follows the edits
  engine::DisplayMesh& mesh = edits.view().display();
  engine::shadeWithAmbient(opened.scene, mesh);

  SceneRenderer renderer;
  renderer.upload(mesh);
  PanelState panel;
  panel.exposure = static_cast<float>(engine::autoExposure(mesh));
  // The document shoots on its own thread; each frame shows its newest snapshot.
  engine::LightingSettings lightingSettings = options.lighting;
  lightingSettings.adaptive = adaptiveSettings(options.adapt, scene);
  engine::LightingThread lighting(std::move(opened.scene), std::move(meshed), lightingSettings);
  std::shared_ptr<const engine::LightingSnapshot> shown = lighting.latest();
  ProgressLine progress(scene.file);
  panel.wireframe = options.wireframe;
  WalkSettings walk;
  walk.speed = defaultWalkSpeed(scene);

  glm::dvec2 lastMouse{0};
  bool looking = false, leftWasDown = false;
  double lastTime = glfwGetTime();
  for (++frame; !glfwWindowShouldClose(window); ++frame) {
    const double frameStart = glfwGetTime();
    g_presses.clear();
    glfwPollEvents();
    const double now = glfwGetTime();
    ObjectDrag& drag = edits.drag();
    applyWalk(readWalkInput(window, lastMouse, looking, drag.dragging()), now - lastTime, walk, camera);
    lastTime = now;
    if (pressed(GLFW_KEY_F12)) panel.screenshotRequested = true;

    // Picking and dragging with the left button, off the panel.
    const bool leftDown = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (leftDown && !leftWasDown && !ImGui::GetIO().WantCaptureMouse) drag.press(cursorRay(window, camera));
    if (leftDown && drag.dragging()) {
      drag.follow(cursorRay(window, camera));
      // A wheel notch lifts by 5 cm.
      if (g_scroll != 0) drag.lift(g_scroll * 0.05 / scene.metersPerUnit);
    }
    g_scroll = 0;
    const auto recordEdit = [&](const std::optional<engine::PoseEdit>& edit) {
      if (edit) edits.record(*edit);
    };
    if (!leftDown && leftWasDown) recordEdit(drag.release());
    leftWasDown = leftDown;
    if (pressed(GLFW_KEY_R) || pressed(GLFW_KEY_R, GLFW_MOD_SHIFT)) recordEdit(drag.turn(pressed(GLFW_KEY_R) ? 15 : -15));
    if (pressed(GLFW_KEY_ESCAPE)) {
      recordEdit(drag.release());
      drag.deselect();
    }
    if (pressed(GLFW_KEY_Z, GLFW_MOD_CONTROL) || panel.undoRequested) edits.undo();
    if (pressed(GLFW_KEY_Y, GLFW_MOD_CONTROL) || panel.redoRequested) edits.redo();
    // An object moved in the view: the picture follows at once, the document is asked for the pose.
    for (const auto& [object, pose] : edits.takePosesToSend()) {
      lighting.requestPose(object, pose);
      renderer.setObjectTransform(object, glm::mat4(edits.view().objectTransform(object)));
    }
    if (pressed(GLFW_KEY_S, GLFW_MOD_CONTROL) || panel.saveRequested) {
      panel.saveReport = edits.save();
      std::cout << "walkrad view: " << panel.saveReport << std::endl;
    }
    panel.undoRequested = panel.redoRequested = panel.saveRequested = false;
    if (drag.refusal() != panel.editReport) {
      panel.editReport = drag.refusal();
      if (!panel.editReport.empty()) std::cout << "walkrad view: move refused: " << panel.editReport << std::endl;
    }

    // What the document did since the last frame: meshes, refusals, light.
    const engine::LightingUpdate update = lighting.take();
    const engine::SceneView::Taken taken = edits.take(update);
    if (!taken.surfaces.empty()) renderer.updateSurfaces(mesh, taken.surfaces);
    if (taken.radiance) renderer.updateRadiance(mesh);
    for (uint32_t object : taken.movedBack) renderer.setObjectTransform(object, glm::mat4(edits.view().objectTransform(object)));
    if (update.snapshot != shown) {
      shown = update.snapshot;
      progress.report(*shown);
    }
    if (panel.autoExposureRequested) {
      panel.exposure = static_cast<float>(engine::autoExposure(mesh));
      panel.autoExposureRequested = false;
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel.walkSpeed = walk.speed;
    panel.chunksDrawn = renderer.lastFrame().chunksDrawn;
    panel.chunksCulled = renderer.lastFrame().chunksCulled;
    panel.trianglesDrawn = renderer.lastFrame().triangles;
    panel.selected.clear();
    if (const auto selected = edits.drag().selected()) {
      const engine::Object& o = scene.objects[*selected];
      panel.selected = o.name;
      panel.selectedMovable = o.movable;
      panel.selectedPosition = o.position;
      panel.selectedTurn = o.rotateYDeg;
    }
    panel.canUndo = edits.history().canUndo();
    panel.canRedo = edits.history().canRedo();
    panel.unsaved = edits.history().unsaved();
    drawScenePanel(scene, mesh, *shown, panel);
    if (panel.paused != shown->paused) lighting.setPaused(panel.paused);
    if (panel.restartRequested) {
      lighting.restart();
      panel.restartRequested = false;
    }
    if (panel.jumpToCamera >= 0) {
      camera = fromSceneCamera(scene.cameras[static_cast<size_t>(panel.jumpToCamera)]);
      panel.jumpToCamera = -1;
    }
    ImGui::Render();

    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width > 0 && height > 0) {
      FrameSettings settings;
      settings.clipFromDisplay = clipFromDisplay(camera, static_cast<double>(width) / height, scene, mesh.origin);
      settings.width = width;
      settings.height = height;
      settings.exposure = panel.exposure;
      settings.wireframe = panel.wireframe;
      settings.highlight = edits.drag().selected();
      settings.levelOfDetail = panel.levelOfDetail;
      settings.toneMapVertices = true;
      renderer.draw(mesh, settings);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      const bool last = options.frames > 0 && frame >= options.frames;
      std::string shot;
      if (panel.screenshotRequested) shot = screenshotName(scene);
      if (last && !options.screenshot.empty()) shot = options.screenshot;
      if (!shot.empty()) {
        panel.screenshotRequested = false;
        try {
          writePng(shot, readFramebuffer(width, height, GL_BACK));  // before the swap
          std::cout << "screenshot: " << shot << std::endl;
          panel.lastScreenshot = shot;
        } catch (const std::exception& e) {  // a failed screenshot must not end the walk
          std::cerr << "walkrad view: " << e.what() << "\n";
          panel.lastScreenshot = "(failed) " + shot;
          if (last) exitCode = 1;
        }
      }
    }
    if (!g_dropped.empty()) {
      const std::string path = g_dropped.back();  // of several files, the last
      g_dropped.clear();
      try {
        OpenedScene next = openScene(path, {}, std::nullopt);
        std::cout << "walkrad view: opened " << path << std::endl;
        return next;
      } catch (const engine::SceneError& e) {
        panel.openReport = e.what();
        std::cerr << "walkrad view: " << e.what() << std::endl;
      }
    }
    glfwSwapBuffers(window);
    record.frames.add(1000 * (glfwGetTime() - frameStart));
    record.elements = mesh.elements;
    record.vertices = mesh.vertices;
    record.chunks = renderer.lastFrame();
    record.shots = shown->shots;
    record.unshotFraction = shown->unshotFraction;
    if (options.frames > 0 && frame >= options.frames) break;
  }
  return std::nullopt;
}

}  // namespace

int runView(const ViewOptions& options) {
  OpenedScene opened = openScene(options.scene, options.load, options.patchSize);
  if (!options.stats.empty()) checkCanWrite(options.stats);
  ViewCamera camera;
  if (!chooseCamera(opened.scene, options.camera, camera)) {
    std::cerr << options.scene << ": cameras: no camera named \"" << options.camera << "\"\n";
    return 2;
  }

  const GlfwSession glfw;
  if (!glfw.ok) {
    std::cerr << "walkrad view: cannot initialise GLFW (no display?)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  const std::string title = "walkrad - " + std::filesystem::path(opened.path).filename().string();
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
  if (!window) {
    std::cerr << "walkrad view: cannot open a window with an OpenGL 3.3 core context\n";
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.frames > 0 ? 0 : 1);
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(&glfwGetProcAddress))) {
    std::cerr << "walkrad view: cannot load OpenGL functions\n";
    glfwDestroyWindow(window);
    return 1;
  }
  glfwSetScrollCallback(window, onScroll);  // before ImGui installs and chains its callbacks
  glfwSetKeyCallback(window, onKey);
  glfwSetDropCallback(window, onDrop);
  // A key or button pressed and released between two frames still reads as pressed once (F12,
  // taps; a click that a slow frame would otherwise miss: the button is polled).
  glfwSetInputMode(window, GLFW_STICKY_KEYS, GLFW_TRUE);
  glfwSetInputMode(window, GLFW_STICKY_MOUSE_BUTTONS, GLFW_TRUE);

  int exitCode = 0, frame = 0;
  ViewRecord record;
  {
    const ImGuiSession imgui(window);
    for (auto next = walkScene(window, options, std::move(opened), camera, frame, exitCode, record); next;
         next = walkScene(window, options, std::move(*next), camera, frame, exitCode, record)) {
      chooseCamera(next->scene, "", camera);
      glfwSetWindowTitle(window, ("walkrad - " + std::filesystem::path(next->path).filename().string()).c_str());
    }
  }
  glfwDestroyWindow(window);
  if (!options.stats.empty()) {
    try {
      writeViewStats(options.stats, record);
    } catch (const std::exception& e) {
      std::cerr << "walkrad view: " << e.what() << "\n";
      return 1;
    }
  }
  return exitCode;
}

}  // namespace app

#include "app/window/walk_window.h"

#include <glad/gl.h>  // before any other GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/cli/peak_memory.h"
#include "app/gl/scene_renderer.h"
#include "app/image/image.h"
#include "app/window/frame_times.h"
#include "app/window/scene_panel.h"
#include "engine/diagnostics.h"
#include "engine/document/display_mesh.h"
#include "engine/io/atomic_file.h"
#include "engine/session/session.h"

#include <nlohmann/json.hpp>

#include <ctime>
#include <filesystem>
#include <iostream>

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

// The ray under the cursor, through the picture on the screen (drawn with the session's camera).
engine::Ray cursorRay(GLFWwindow* window, const engine::ViewCamera& camera) {
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  glm::dvec2 mouse;
  glfwGetCursorPos(window, &mouse.x, &mouse.y);
  const glm::dvec2 ndc{2 * mouse.x / std::max(width, 1) - 1, 1 - 2 * mouse.y / std::max(height, 1)};
  return {camera.position, engine::rayThrough(camera, static_cast<double>(width) / std::max(height, 1), ndc)};
}

// The mouse as the last frame left it.
struct MouseTrack {
  glm::dvec2 last{0};
  bool looking = false;   // the right button turns the view (it went down off the panel)
  bool leftDown = false;
};

// The walk's keys, the look and the wheel, off the panel.
engine::WalkInput readWalk(GLFWwindow* window, MouseTrack& mouse) {
  engine::WalkInput input;
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
  glm::dvec2 at;
  glfwGetCursorPos(window, &at.x, &at.y);
  const bool rightHeld = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (rightHeld && !mouse.looking && !io.WantCaptureMouse) mouse.looking = true;
  if (!rightHeld) mouse.looking = false;
  if (mouse.looking) {
    input.lookDx = at.x - mouse.last.x;
    input.lookDy = at.y - mouse.last.y;
  }
  mouse.last = at;
  if (!io.WantCaptureMouse) input.scroll = g_scroll;
  return input;
}

// The frame's keys and mouse as the session's actions, added to what the panel asked for in the
// last frame (already in `input`).
void readInput(GLFWwindow* window, const engine::Session& session, MouseTrack& mouse, engine::SessionInput& input) {
  input.walk = readWalk(window, mouse);
  g_scroll = 0;
  const bool leftDown = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  input.press = leftDown && !mouse.leftDown && !ImGui::GetIO().WantCaptureMouse;  // picking off the panel
  input.held = leftDown;
  mouse.leftDown = leftDown;
  input.pointer = cursorRay(window, session.camera());
  if (pressed(GLFW_KEY_R)) ++input.turns;
  if (pressed(GLFW_KEY_R, GLFW_MOD_SHIFT)) --input.turns;
  input.deselect = pressed(GLFW_KEY_ESCAPE);
  input.undo |= pressed(GLFW_KEY_Z, GLFW_MOD_CONTROL);
  input.redo |= pressed(GLFW_KEY_Y, GLFW_MOD_CONTROL);
  input.save |= pressed(GLFW_KEY_S, GLFW_MOD_CONTROL);
}

// What a session's frame changed, on the GL side: meshes uploaded again, radiance, transforms.
void showChanges(const engine::Session& session, const engine::SessionFrame& changes, SceneRenderer& renderer) {
  for (uint32_t object : changes.moved) renderer.setObjectTransform(object, glm::mat4(session.objectTransform(object)));
  if (!changes.surfaces.empty()) renderer.updateSurfaces(session.display(), changes.surfaces);
  if (changes.radiance) renderer.updateRadiance(session.display());
}

// Files dropped onto the window since the last frame (GLFW reports them through a callback).
std::vector<std::string> g_dropped;
void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

// The last file dropped onto the window since the last frame, opened; one that does not open
// says why in the panel.
std::optional<engine::OpenedScene> openDropped(PanelState& panel) {
  if (g_dropped.empty()) return std::nullopt;
  const std::string path = g_dropped.back();  // of several files, the last
  g_dropped.clear();
  try {
    engine::OpenedScene next = engine::openScene(path);
    std::cout << "walkrad view: opened " << path << std::endl;
    return next;
  } catch (const engine::SceneError& e) {
    panel.openReport = e.what();
    std::cerr << "walkrad view: " << e.what() << std::endl;
    return std::nullopt;
  }
}

// Saves the frame drawn (the back buffer, before the swap) as `path`. A failed screenshot must not
// end the walk: it says why and returns false.
bool saveScreenshot(const std::string& path, int width, int height, PanelState& panel) {
  try {
    writePng(path, readFramebuffer(width, height, GL_BACK));
    std::cout << "screenshot: " << path << std::endl;
    panel.lastScreenshot = path;
    return true;
  } catch (const std::exception& e) {
    std::cerr << "walkrad view: " << e.what() << "\n";
    panel.lastScreenshot = "(failed) " + path;
    return false;
  }
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
  engine::writeFileAtomically(path, stats.dump(2) + "\n");
}

// Walks through one scene until the window closes, the frame count runs out (nothing returned)
// or a file dropped onto the window opens (returned: the window goes on with it). A dropped file
// that does not open leaves the scene as it is and says why in the panel. `frame` counts the
// window's frames across the scenes it shows, so --frames bounds the whole run; `record` takes
// each frame's time, from the top of its loop to the swap. The session does the walking and
// editing; this shell turns GLFW's input into the session's, and draws.
std::optional<engine::OpenedScene> walkScene(GLFWwindow* window, const ViewOptions& options, engine::OpenedScene opened,
                                             const engine::ViewCamera& camera, int& frame, int& exitCode, ViewRecord& record) {
  engine::LightingSettings lighting = options.lighting;
  lighting.adaptive = adaptiveSettings(options.adapt, opened.scene);
  engine::Session session(std::move(opened), lighting, camera);
  const engine::Scene& scene = session.scene();
  SceneRenderer renderer;
  renderer.upload(session.display());
  PanelState panel;
  panel.exposure = static_cast<float>(engine::autoExposure(session.display()));
  panel.wireframe = options.wireframe;

  MouseTrack mouse;
  engine::SessionInput input;  // the panel's requests wait here for the next frame
  double lastTime = glfwGetTime();
  for (++frame; !glfwWindowShouldClose(window); ++frame) {
    const double frameStart = glfwGetTime();
    g_presses.clear();
    glfwPollEvents();
    // The panel's frame first, so that whether it has the mouse or keys (WantCapture...) is
    // judged where the pointer is now, not where it was a frame ago.
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    readInput(window, session, mouse, input);
    const double now = glfwGetTime();
    input.seconds = now - lastTime;
    lastTime = now;
    if (pressed(GLFW_KEY_F12)) panel.screenshotRequested = true;

    const engine::SessionFrame changes = session.frame(input);
    input = {};
    showChanges(session, changes, renderer);
    for (const std::string& report : changes.reports) std::cout << "walkrad view: " << report << std::endl;
    for (const std::string& error : changes.errors) std::cerr << "walkrad view: " << error << std::endl;
    if (panel.autoExposureRequested) {
      panel.exposure = static_cast<float>(engine::autoExposure(session.display()));
      panel.autoExposureRequested = false;
    }

    panel.chunksDrawn = renderer.lastFrame().chunksDrawn;
    panel.chunksCulled = renderer.lastFrame().chunksCulled;
    panel.trianglesDrawn = renderer.lastFrame().triangles;
    drawScenePanel(session.panel(), panel, input);
    ImGui::Render();

    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width > 0 && height > 0) {
      FrameSettings settings;
      settings.clipFromDisplay =
          engine::clipFromDisplay(session.camera(), static_cast<double>(width) / height, scene, session.display().origin);
      settings.width = width;
      settings.height = height;
      settings.exposure = panel.exposure;
      settings.wireframe = panel.wireframe;
      settings.highlight = session.selected();
      settings.levelOfDetail = panel.levelOfDetail;
      settings.toneMapVertices = true;
      renderer.draw(session.display(), settings);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      const bool last = options.frames > 0 && frame >= options.frames;
      std::string shot;
      if (panel.screenshotRequested) shot = screenshotName(scene);
      if (last && !options.screenshot.empty()) shot = options.screenshot;
      panel.screenshotRequested = false;
      if (!shot.empty() && !saveScreenshot(shot, width, height, panel) && last) exitCode = 1;
    }
    if (auto next = openDropped(panel)) return next;
    glfwSwapBuffers(window);
    record.frames.add(1000 * (glfwGetTime() - frameStart));
    record.elements = session.display().elements;
    record.vertices = session.display().vertices;
    record.chunks = renderer.lastFrame();
    record.shots = session.panel().light->shots;
    record.unshotFraction = session.panel().light->unshotFraction;
    if (options.frames > 0 && frame >= options.frames) break;
  }
  return std::nullopt;
}

}  // namespace

int runView(const ViewOptions& options) {
  engine::OpenedScene opened = engine::openScene(options.scene, options.load, options.patchSize);
  if (!options.stats.empty()) engine::checkCanWrite(options.stats);
  engine::ViewCamera camera;
  if (!engine::chooseCamera(opened.scene, options.camera, camera)) {
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
      engine::chooseCamera(next->scene, "", camera);
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

// Lighting a scene on its own thread (the "Pixel-Planes 5 thread" of DESIGN.md): a thin wrapper
// around the lit-scene document (lit_scene.h) that shoots shot after shot, takes the objects'
// poses the thread that draws asks for, and publishes snapshots of the vertex radiance with the
// meshes that changed. The thread that draws never waits for a shot or an edit: asking for a
// pose costs it nothing, whatever the scene's size.
#pragma once

#include "engine/document/lit_scene.h"
#include "engine/document/scene_poses.h"

#include <glm/vec3.hpp>

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace engine {

struct LightingSettings {
  radiosity::SolverSettings solver{.overshoot = true};
  // Adaptive refinement while shooting (MeshAdaptation).
  std::optional<AdaptiveSettings> adaptive;
  double converge = 1e-3;             // shooting stops once the unshot fraction is below this
  double publishSeconds = 1.0 / 30;   // snapshots at most this often while shooting
};

struct LightingSnapshot {
  uint64_t version = 0;                // grows with every snapshot
  std::vector<glm::vec3> radiance;     // per display vertex (displayRadiance) of the thread's meshes
  uint64_t shots = 0;
  double unshotFraction = 1;           // unshot over emitted energy
  size_t pendingCorrections = 0;       // take-backs of an edit still to do (Solver::edit)
  double solveSeconds = 0;             // time spent shooting
  double shotsPerSecond = 0;
  size_t elements = 0, patches = 0;
  bool converged = false;
  bool paused = false;                 // shooting has stopped: the radiance shows every shot
  uint64_t edits = 0;                  // pose requests (requestPose) the document has taken
  bool adaptive = false;               // the meshes are refined and coarsened as the light comes in
  uint64_t adaptivePasses = 0;         // passes that changed a mesh
  // Set when a shot or a restart failed (out of memory, no threads): shooting has stopped and
  // only a restart tries again. The radiance is the last good one.
  std::string error;
};

// A pose the document refused (SceneEditor::setPose: the mesher refused a surface the move
// would have cut); the object stands at `kept`.
struct PoseRefusal {
  uint32_t object = 0;
  ObjectPose refused, kept;
  std::string why;  // one line
};

// What the thread that draws takes at a frame: the newest snapshot, the surfaces whose meshes
// changed since its last take (the snapshot's radiance is on the meshes with these applied),
// and the poses refused since.
struct LightingUpdate {
  std::shared_ptr<const LightingSnapshot> snapshot;
  std::vector<SurfaceUpdate> meshes;  // by surface, ascending
  std::vector<PoseRefusal> refusals;
};

class LightingThread {
 public:
  // Starts shooting at once at a meshed scene (its meshes at their patch sizes); with
  // settings.adaptive its meshes are refined and coarsened as the light comes in. Throws what
  // radiosity::Solver throws for the surfaces.
  LightingThread(Scene scene, MeshedScene meshed, const LightingSettings& settings);
  ~LightingThread();  // stops after the shot in flight
  LightingThread(const LightingThread&) = delete;
  LightingThread& operator=(const LightingThread&) = delete;

  // The newest snapshot (the first is published before the first shot). Never waits for a shot.
  std::shared_ptr<const LightingSnapshot> latest() const;
  // The newest snapshot with the mesh changes and refusals since the last take. Never waits for
  // a shot.
  LightingUpdate take();

  // Pausing takes effect after the shot in flight; the first paused snapshot comes then and
  // shows its light. Restarting throws the solution away and starts again from the emitters.
  void setPaused(bool paused);
  void restart();
  // Puts `object` at `pose` (LitScene::setPose), after the shot in flight and once the last
  // edit's powerful take-backs are done, with any poses asked for since; a pose asked for while
  // the previous one for the same object waits replaces it. Costs the caller a lock and a copy of
  // the pose. The snapshots count the requests taken; their radiance and mesh updates show an
  // edit once its powerful take-backs are done (until then, the light before it).
  void requestPose(uint32_t object, const ObjectPose& pose);

 private:
  void run();
  // Takes the poses asked for and a restart, and publishes the result.
  void applyRequests(std::unique_lock<std::mutex>& lock);
  void publish(bool converged, std::vector<PoseRefusal> refusals = {});
  void publishError(const std::string& what);

  const LightingSettings settings_;
  LitScene document_;  // the thread's own once it runs
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false, paused_ = false, restart_ = false;
  std::vector<std::pair<uint32_t, ObjectPose>> requests_;  // poses asked for, not yet taken
  uint64_t editsRequested_ = 0, editsApplied_ = 0;
  // Changes published and not yet taken; a surface's newest mesh replaces what it had.
  std::map<uint32_t, SurfaceUpdate> meshUpdates_;
  std::vector<PoseRefusal> refusals_;
  std::shared_ptr<const LightingSnapshot> latest_;
  uint64_t version_ = 0;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace engine

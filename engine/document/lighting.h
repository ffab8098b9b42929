// Lighting a meshed scene with the radiosity solver on its own thread (the "Pixel-Planes 5
// thread" of DESIGN.md): it shoots shot after shot and publishes snapshots of the vertex
// radiance; the UI takes the newest one without ever waiting for a shot.
#pragma once

#include "engine/document/mesh_adaptation.h"
#include "radiosity/radiosity.h"

#include <glm/vec3.hpp>

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace engine {

// The display radiance of every surface, per display vertex (surface after surface, each in its
// mesh's vertex order, as DisplayMesh holds them): the solver's vertex radiance plus
// reflectance times its ambient term.
void displayRadiance(const radiosity::Solver& solver, std::vector<glm::vec3>& out);

// Shoots until the unshot fraction is at most `converge` or `maxShots` shots were taken, calling
// `progress` (when given) after every shot; returns the shots taken. With `adaptation` (whose
// input() the solver has), its passes run when due, and shooting goes on after each that
// changed a mesh until one at convergence changes none.
uint64_t solveTo(radiosity::Solver& solver, double converge, uint64_t maxShots,
                 const std::function<void(const radiosity::Solver&, uint64_t shots)>& progress = {},
                 MeshAdaptation* adaptation = nullptr);

// Takes a scene edit into a solution: the surfaces `edited` names (SceneEditor::takeEdited), as
// `meshed` has them now, replace the solver's, whose light is corrected rather than shot again
// (radiosity::Solver::edit); the other surfaces keep their elements and light. With
// `adaptation` (whose input the solver has), the adaptation takes the edit first and the solver
// its meshes of them (MeshAdaptation::edit). Returns what the solver took. The one way edits
// reach the light, from the window's lighting thread and from `walkrad render --move`.
std::vector<radiosity::SurfaceChange> applyEdit(radiosity::Solver& solver, const Scene& scene, const MeshedScene& meshed,
                                                std::span<const EditedSurface> edited,
                                                MeshAdaptation* adaptation = nullptr);

struct LightingSettings {
  radiosity::SolverSettings solver{.overshoot = true};
  // Adaptive refinement while shooting (MeshAdaptation; only for a thread made from a scene).
  std::optional<AdaptiveSettings> adaptive;
  double converge = 1e-3;             // shooting stops once the unshot fraction is below this
  double publishSeconds = 1.0 / 30;   // snapshots at most this often while shooting
};

struct LightingSnapshot {
  uint64_t version = 0;                // grows with every snapshot
  std::vector<glm::vec3> radiance;     // per display vertex (displayRadiance)
  uint64_t shots = 0;
  double unshotFraction = 1;           // unshot over emitted energy
  size_t pendingCorrections = 0;       // take-backs of an edit still to do (Solver::edit)
  double solveSeconds = 0;             // time spent shooting
  double shotsPerSecond = 0;
  size_t elements = 0, patches = 0;
  bool converged = false;
  bool paused = false;                 // shooting has stopped: the radiance shows every shot
  uint64_t edits = 0;                  // scene edits the radiance takes into account
  // With adaptive refinement: the meshes the radiance is for (a new pointer whenever they
  // changed), and the passes that changed them. Without: null, and the radiance is for the
  // meshes the thread was given.
  std::shared_ptr<const MeshedScene> meshed;
  uint64_t adaptivePasses = 0;
  // Set when a shot or a restart failed (out of memory, no threads): shooting has stopped and
  // only a restart tries again. The radiance is the last good one.
  std::string error;
};

class LightingThread {
 public:
  // Starts shooting at once at a meshed scene (radiosityInput); with settings.adaptive its meshes
  // are refined and coarsened as the light comes in, and the snapshots carry them. Throws what
  // radiosity::Solver throws for the surfaces.
  LightingThread(const Scene& scene, const MeshedScene& meshed, const LightingSettings& settings);
  ~LightingThread();  // stops after the shot in flight
  LightingThread(const LightingThread&) = delete;
  LightingThread& operator=(const LightingThread&) = delete;

  // The newest snapshot (the first is published before the first shot). Never waits for a shot.
  std::shared_ptr<const LightingSnapshot> latest() const;

  // Pausing takes effect after the shot in flight; the first paused snapshot comes then and
  // shows its light. Restarting throws the solution away and starts again from the emitters.
  void setPaused(bool paused);
  void restart();
  // The scene changed (objects moved): the surfaces `edited` names (SceneEditor::takeEdited)
  // take their meshes in `meshed` (the edited scene's, at their patch sizes); the others keep
  // their light and, adapting, their refinement. Applied after the shot in flight, with any
  // edits sent since; the snapshots count the edits applied.
  void edit(const Scene& scene, const MeshedScene& meshed, std::span<const EditedSurface> edited);

 private:
  // Without adaptive refinement: the solver's input of the edited scene, for the thread to take.
  void edit(std::vector<radiosity::Surface> surfaces);
  void start();
  void run(std::unique_ptr<radiosity::Solver> solver);
  void publish(const radiosity::Solver& solver, bool converged);
  void publishError(const std::string& what);

  std::vector<radiosity::Surface> surfaces_;  // the thread's own once it runs
  const LightingSettings settings_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false, paused_ = false, restart_ = false;
  std::unique_ptr<std::pair<Scene, MeshedScene>> editedScene_;  // the newest edit not yet applied
  std::vector<EditedSurface> edited_;                            // the surfaces of the edits not yet applied
  std::unique_ptr<MeshAdaptation> adaptation_;                   // the thread's own once it runs
  std::shared_ptr<const MeshedScene> meshes_;                    // with adaptation: the last published
  uint64_t editsRequested_ = 0, editsApplied_ = 0;
  std::shared_ptr<const LightingSnapshot> latest_;
  uint64_t version_ = 0;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace engine

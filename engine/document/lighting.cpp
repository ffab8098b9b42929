#include "engine/document/lighting.h"

#include <glm/common.hpp>

#include <chrono>
#include <utility>

namespace engine {

void displayRadiance(const radiosity::Solver& solver, std::vector<glm::vec3>& out) {
  out.clear();
  const glm::dvec3 ambient = solver.ambient();
  // Light shot back by corrections (and overshooting) can leave residue a hair below zero,
  // within the unshot tolerance: shown, there is no light there.
  for (uint32_t s = 0; s < solver.surfaceCount(); ++s)
    for (const glm::dvec3& radiance : solver.vertexRadiance(s, ambient)) out.emplace_back(glm::max(radiance, glm::dvec3(0)));
}

uint64_t solveTo(radiosity::Solver& solver, double converge, uint64_t maxShots,
                 const std::function<void(const radiosity::Solver&, uint64_t shots)>& progress,
                 MeshAdaptation* adaptation) {
  uint64_t shots = 0;
  while (shots < maxShots) {
    if (adaptation && adaptation->adaptIfDue(solver, converge)) continue;
    if (solver.converged(converge) || !solver.step()) break;
    ++shots;
    if (progress) progress(solver, shots);
  }
  return shots;
}

std::vector<radiosity::SurfaceChange> applyEdit(radiosity::Solver& solver, const Scene& scene, const MeshedScene& meshed,
                                                std::span<const EditedSurface> edited, MeshAdaptation* adaptation) {
  std::vector<radiosity::SurfaceChange> changes =
      adaptation ? adaptation->edit(scene, meshed, edited) : radiosityChanges(scene, meshed, edited);
  solver.edit(changes);
  return changes;
}

LightingThread::LightingThread(const Scene& scene, const MeshedScene& meshed, const LightingSettings& settings)
    : settings_(settings) {
  if (settings.adaptive) {
    adaptation_ = std::make_unique<MeshAdaptation>(scene, meshed, *settings.adaptive);
    surfaces_ = adaptation_->input();
    meshes_ = std::make_shared<const MeshedScene>(adaptation_->meshed());
  } else {
    surfaces_ = radiosityInput(scene, meshed);
  }
  start();
}

void LightingThread::start() {
  // The first solver is made here, so bad input throws to the caller rather than on the thread.
  auto first = std::make_unique<radiosity::Solver>(surfaces_, settings_.solver);
  publish(*first, first->converged(settings_.converge));
  thread_ = std::thread([this, solver = std::move(first)]() mutable { run(std::move(solver)); });
}

void LightingThread::run(std::unique_ptr<radiosity::Solver> solver) {
  using Clock = std::chrono::steady_clock;
  auto lastPublish = Clock::now();
  bool done = solver->converged(settings_.converge), unpublished = false, failed = false;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      const auto ready = [&] {
        return stop_ || restart_ || editsApplied_ < editsRequested_ || (!paused_ && !done && !failed);
      };
      // A pause (or its end) is shown by the thread once no shot is in flight, so a paused
      // snapshot shows every shot. After a failure the error snapshot stays.
      const auto pauseUnshown = [&] { return !failed && latest_->paused != paused_; };
      if (!ready() && (unpublished || pauseUnshown())) {
        // About to wait (paused): the shots since the last snapshot are shown first.
        lock.unlock();
        publish(*solver, done);
        unpublished = false;
        continue;  // the pause may have changed meanwhile
      }
      wake_.wait(lock, [&] { return ready() || pauseUnshown(); });
      if (stop_) return;
      if (!ready()) continue;  // woken to show a pause
      if (restart_ || editsApplied_ < editsRequested_) {
        restart_ = false;
        std::unique_ptr<std::pair<Scene, MeshedScene>> editedScene = std::move(editedScene_);
        const std::vector<EditedSurface> edited = std::exchange(edited_, {});
        editsApplied_ = editsRequested_;
        lock.unlock();
        try {
          if (editedScene) {
            // The thread's input follows, for a restart.
            for (radiosity::SurfaceChange& c :
                 applyEdit(*solver, editedScene->first, editedScene->second, edited, adaptation_.get()))
              surfaces_[c.surface] = std::move(c.now);
            if (adaptation_) meshes_ = std::make_shared<const MeshedScene>(adaptation_->meshed());
          } else {
            if (adaptation_) surfaces_ = adaptation_->input();  // a restart lights the meshes as adapted so far
            solver = std::make_unique<radiosity::Solver>(surfaces_, settings_.solver);
          }
          done = solver->converged(settings_.converge);
          failed = unpublished = false;
          publish(*solver, done);
        } catch (const std::exception& e) {
          failed = true;
          publishError(e.what());
        }
        continue;
      }
    }
    // A failed shot leaves the solver half-updated: it shoots no more until a restart.
    try {
      const bool shot = solver->step();
      // A pass that changed meshes is shown at once: the display takes the new meshes with it.
      const bool adapted = adaptation_ && adaptation_->adaptIfDue(*solver, settings_.converge);
      if (adapted) meshes_ = std::make_shared<const MeshedScene>(adaptation_->meshed());
      done = !adapted && (!shot || solver->converged(settings_.converge));
      unpublished = true;
      const auto now = Clock::now();
      if (done || adapted || std::chrono::duration<double>(now - lastPublish).count() >= settings_.publishSeconds) {
        publish(*solver, done);
        unpublished = false;
        lastPublish = now;
      }
    } catch (const std::exception& e) {
      failed = true;
      publishError(e.what());
    }
  }
}

void LightingThread::publishError(const std::string& what) {
  std::lock_guard lock(mutex_);
  auto snapshot = std::make_shared<LightingSnapshot>(*latest_);
  snapshot->error = what;
  snapshot->converged = false;
  snapshot->version = ++version_;
  latest_ = std::move(snapshot);
}

LightingThread::~LightingThread() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::shared_ptr<const LightingSnapshot> LightingThread::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

void LightingThread::setPaused(bool paused) {
  {
    std::lock_guard lock(mutex_);
    paused_ = paused;
  }
  wake_.notify_all();
}

void LightingThread::restart() {
  {
    std::lock_guard lock(mutex_);
    restart_ = true;
  }
  wake_.notify_all();
}

void LightingThread::edit(const Scene& scene, const MeshedScene& meshed, std::span<const EditedSurface> edited) {
  auto copy = std::make_unique<std::pair<Scene, MeshedScene>>(scene, meshed);
  {
    std::lock_guard lock(mutex_);
    editedScene_ = std::move(copy);
    addEdits(edited_, edited);
    ++editsRequested_;
  }
  wake_.notify_all();
}

void LightingThread::publish(const radiosity::Solver& solver, bool converged) {
  // Built outside the lock: the UI only ever waits for a pointer swap.
  auto snapshot = std::make_shared<LightingSnapshot>();
  displayRadiance(solver, snapshot->radiance);
  const radiosity::Stats& stats = solver.stats();
  snapshot->shots = stats.shots;
  snapshot->unshotFraction = solver.unshotFraction();
  snapshot->pendingCorrections = solver.pendingCorrections();
  snapshot->solveSeconds = stats.seconds;
  snapshot->shotsPerSecond = stats.seconds > 0 ? static_cast<double>(stats.shots) / stats.seconds : 0;
  snapshot->elements = solver.elementCount();
  snapshot->patches = solver.patchCount();
  snapshot->converged = converged;
  snapshot->meshed = meshes_;
  snapshot->adaptivePasses = adaptation_ ? adaptation_->passes() : 0;
  std::lock_guard lock(mutex_);
  snapshot->edits = editsApplied_;
  snapshot->paused = paused_;
  snapshot->version = ++version_;
  latest_ = std::move(snapshot);
}

}  // namespace engine

#include "engine/document/lighting.h"

#include "engine/diagnostics.h"

#include <chrono>
#include <utility>

namespace engine {

namespace {

// Whether the last edit's light is about right again: its take-backs done but for this share of
// their power (the most powerful go first; the rest adjust what is shown by little).
constexpr double kRelitShare = 0.05;
bool relit(const radiosity::Solver& solver) { return solver.pendingCorrectionShare() <= kRelitShare; }

}  // namespace

LightingThread::LightingThread(Scene scene, MeshedScene meshed, const LightingSettings& settings)
    : settings_(settings), document_(std::move(scene), std::move(meshed), {settings.solver, settings.adaptive}) {
  // The first snapshot is made here, so that latest() always has one.
  publish(document_.solver().converged(settings_.converge));
  thread_ = std::thread([this] { run(); });
}

void LightingThread::run() {
  using Clock = std::chrono::steady_clock;
  auto lastPublish = Clock::now();
  bool done = document_.solver().converged(settings_.converge), unpublished = false, failed = false;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      // Poses wait while an edit's powerful take-backs are being done: the display gets each
      // edit whole and relit (publish), and a drag's many poses come to the newest.
      const auto edit = [&] { return restart_ || (!requests_.empty() && relit(document_.solver())); };
      const auto ready = [&] { return stop_ || edit() || (!paused_ && !done && !failed); };
      // A pause (or its end) is shown by the thread once no shot is in flight, so a paused
      // snapshot shows every shot. After a failure the error snapshot stays.
      const auto pauseUnshown = [&] { return !failed && latest_->paused != paused_; };
      if (!ready() && (unpublished || pauseUnshown())) {
        // About to wait (paused): the shots since the last snapshot are shown first.
        lock.unlock();
        publish(done);
        unpublished = false;
        continue;  // the pause may have changed meanwhile
      }
      wake_.wait(lock, [&] { return ready() || pauseUnshown(); });
      if (stop_) return;
      if (!ready()) continue;  // woken to show a pause
      if (edit()) {
        try {
          applyRequests(lock);
          done = document_.solver().converged(settings_.converge);
          failed = unpublished = false;
        } catch (const std::exception& e) {
          failed = true;
          publishError(e.what());
        }
        continue;
      }
    }
    // A failed shot leaves the solver half-updated: it shoots no more until a restart.
    try {
      const SolveStep step = document_.step(settings_.converge);
      done = step == SolveStep::kDone;
      unpublished = true;
      const auto now = Clock::now();
      // A pass that changed meshes is shown at once: the display takes the new meshes with it.
      if (done || step == SolveStep::kAdapted ||
          std::chrono::duration<double>(now - lastPublish).count() >= settings_.publishSeconds) {
        publish(done);
        unpublished = false;
        lastPublish = now;
      }
    } catch (const std::exception& e) {
      failed = true;
      publishError(e.what());
    }
  }
}

void LightingThread::applyRequests(std::unique_lock<std::mutex>& lock) {
  const auto requests = std::exchange(requests_, {});
  const bool restart = std::exchange(restart_, false);
  const uint64_t requested = editsRequested_;
  lock.unlock();
  std::vector<PoseRefusal> refusals;
  for (const auto& [object, pose] : requests) {
    try {
      document_.setPose(object, pose);
    } catch (const SceneError& e) {
      refusals.push_back({object, pose, poseOf(document_.scene().objects[object]), e.what()});
    } catch (const std::invalid_argument& e) {
      refusals.push_back({object, pose, poseOf(document_.scene().objects[object]), e.what()});
    }
  }
  if (restart) document_.restart();
  {
    std::lock_guard relock(mutex_);
    editsApplied_ = requested;
  }
  publish(document_.solver().converged(settings_.converge), std::move(refusals));
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

LightingUpdate LightingThread::take() {
  LightingUpdate update;
  std::lock_guard lock(mutex_);
  update.snapshot = latest_;
  update.meshes.reserve(meshUpdates_.size());
  for (auto& [surface, mesh] : meshUpdates_) update.meshes.push_back(std::move(mesh));
  meshUpdates_.clear();
  update.refusals = std::exchange(refusals_, {});
  return update;
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

void LightingThread::requestPose(uint32_t object, const ObjectPose& pose) {
  {
    std::lock_guard lock(mutex_);
    if (!requests_.empty() && requests_.back().first == object) requests_.back().second = pose;
    else requests_.emplace_back(object, pose);
    ++editsRequested_;
  }
  wake_.notify_all();
}

void LightingThread::publish(bool converged, std::vector<PoseRefusal> refusals) {
  // Built outside the lock: the UI only ever waits for a pointer swap.
  auto snapshot = std::make_shared<LightingSnapshot>();
  const radiosity::Solver& solver = document_.solver();
  // While an edit's light is being taken back and sent again, surfaces it changed are dark: the
  // display keeps the light and meshes before the edit until its powerful part is done.
  const bool shown = relit(solver) || !latest_;
  if (shown) displayRadiance(solver, snapshot->radiance);
  else snapshot->radiance = latest_->radiance;
  const radiosity::Stats& stats = solver.stats();
  snapshot->shots = stats.shots;
  snapshot->unshotFraction = solver.unshotFraction();
  snapshot->pendingCorrections = solver.pendingCorrections();
  snapshot->solveSeconds = stats.seconds;
  snapshot->shotsPerSecond = stats.seconds > 0 ? static_cast<double>(stats.shots) / stats.seconds : 0;
  snapshot->elements = solver.elementCount();
  snapshot->patches = solver.patchCount();
  snapshot->converged = converged;
  snapshot->adaptive = settings_.adaptive.has_value();
  snapshot->adaptivePasses = document_.adaptivePasses();
  std::vector<SurfaceUpdate> meshes;
  if (shown) meshes = document_.takeUpdates();
  std::lock_guard lock(mutex_);
  for (SurfaceUpdate& m : meshes) meshUpdates_.insert_or_assign(m.surface, std::move(m));
  for (PoseRefusal& r : refusals) refusals_.push_back(std::move(r));
  snapshot->edits = editsApplied_;
  snapshot->paused = paused_;
  snapshot->version = ++version_;
  latest_ = std::move(snapshot);
}

}  // namespace engine

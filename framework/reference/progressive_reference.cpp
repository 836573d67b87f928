// The progressive reference (progressive_reference.h, docs/progressive-reference.md): one worker
// thread per instance waits for a job, builds or reuses the BVH, and accumulates batches of
// reference samples (reference_batch.h) in a TBB arena until the target is reached or the job is
// cancelled. The mutex guards the job queue (at most one pending job) and the published mean; it
// is never held while rays are cast, so start(), latest() and the status calls return at once.
#include "reference/progressive_reference.h"

#include "reference/estimators.h"
#include "reference/reference_batch.h"
#include "reference/sampling.h"
#include "util/error.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace rtlab {

// A named namespace, not an anonymous one: ProgressiveReference::State (external linkage) holds a
// Job, which GCC warns about (-Wsubobject-linkage) when a unity build batches this file.
namespace progressive_job {

struct Job {
  std::uint64_t generation = 0;
  std::shared_ptr<const PreparedReferenceScene> prepared; // null: build it from `scene`
  std::optional<Scene> scene;
  std::vector<Light> lights;
  glm::vec3 eye{0.0f};
  SurfaceData surfaces;
  reference::Quantity quantity = reference::Quantity::Ao;
  ProgressiveOptions options;
  int threads = 1;
};

} // namespace progressive_job

using progressive_job::Job;

struct ProgressiveReference::State {
  mutable std::mutex mutex;
  std::condition_variable wake; // the worker: a job is pending, or quit
  std::condition_variable idle; // stop(): the worker finished its job
  std::optional<Job> pending;
  bool quit = false, busy = false, running = false;
  std::atomic<bool> cancel{false}; // the job being refined is superseded or stopped
  std::uint64_t generation = 0;
  // The published mean (meanGeneration 0: none for the current generation).
  Image mean;
  int samples = 0;
  std::uint64_t meanGeneration = 0;
  bool converged = false;
  std::string error;
  std::shared_ptr<const PreparedReferenceScene> prepared;
  std::thread worker;

  void run(Job& job);
  void loop();
  // Under the lock: stops the job in progress and drops the pending one.
  void cancelLocked() {
    cancel.store(true);
    pending.reset();
    running = false;
  }
};

int progressiveBatchSpp(int k, int done, const ProgressiveOptions& options) {
  const int doubling = k <= 0 ? 1 : (k - 1 >= 30 ? options.batchMaxSpp : 1 << (k - 1));
  return std::max(1, std::min({doubling, options.batchMaxSpp, options.targetSpp - done}));
}

unsigned progressiveBatchSeed(unsigned seed, int k) {
  return reference::hashCombine(seed, std::uint32_t(k));
}

void ProgressiveReference::State::run(Job& job) {
  std::shared_ptr<const PreparedReferenceScene> scene = job.prepared;
  if (!scene) scene = std::make_shared<const PreparedReferenceScene>(std::move(*job.scene));
  {
    std::lock_guard lock(mutex);
    // The BVH does not depend on the view: one built for the last start() is kept even when its
    // job was cancelled meanwhile (the camera moved during the build), so the restart reuses it.
    if (generation == job.generation) prepared = scene;
    if (cancel.load()) return;
  }
  const reference::EstimatorContext ctx{scene->scene(), scene->tracer(), job.options.aoRadius, job.lights};
  const SurfaceData& surfaces = job.surfaces;
  const int tiles = reference::tileCount(surfaces.width, surfaces.height);
  Image batch(surfaces.width, surfaces.height, reference::channelCount(job.quantity));
  batch.mask.assign(surfaces.pixelCount(), 0.0f);
  std::vector<double> sum(batch.pixels.size(), 0.0);
  std::atomic<std::uint64_t> rays{0};
  tbb::task_arena arena(job.threads);

  int done = 0;
  for (int k = 0; done < job.options.targetSpp; ++k) {
    const int spp = progressiveBatchSpp(k, done, job.options);
    const reference::BatchSpec spec{job.quantity, spp, progressiveBatchSeed(job.options.seed, k), true, job.eye};
    const bool complete = arena.execute(
        [&] { return reference::renderBatch(ctx, surfaces, spec, batch, 0, tiles, &cancel, rays, nullptr); });
    if (!complete) return;
    done += spp;
    Image next(batch.width, batch.height, batch.channels);
    next.mask = batch.mask;
    for (std::size_t i = 0; i < sum.size(); ++i) {
      sum[i] += double(batch.pixels[i]) * spp;
      next.pixels[i] = float(sum[i] / done);
    }
    std::lock_guard lock(mutex);
    if (cancel.load()) return; // superseded while the mean was being formed: not this view any more
    mean = std::move(next);
    samples = done;
    meanGeneration = job.generation;
    converged = done == job.options.targetSpp;
    // running() is false once converged: cleared here, in the same critical section that publishes
    // the converged mean, so that no reader sees a converged snapshot while running() is true.
    if (converged && !pending) running = false;
  }
}

void ProgressiveReference::State::loop() {
  std::unique_lock lock(mutex);
  for (;;) {
    wake.wait(lock, [&] { return quit || pending.has_value(); });
    if (quit) return;
    Job job = std::move(*pending);
    pending.reset();
    cancel.store(false);
    busy = true;
    lock.unlock();
    std::string failure;
    try {
      run(job);
    } catch (const std::exception& e) {
      failure = e.what();
    } catch (...) {
      failure = "reference: unknown error";
    }
    lock.lock();
    if (!failure.empty() && !cancel.load()) error = failure;
    busy = false;
    if (!pending) running = false;
    idle.notify_all();
  }
}

ProgressiveReference::ProgressiveReference() : m_state(std::make_shared<State>()) {
  State* state = m_state.get();
  m_state->worker = std::thread([state] { state->loop(); });
}

ProgressiveReference::~ProgressiveReference() {
  {
    std::lock_guard lock(m_state->mutex);
    m_state->quit = true;
    m_state->cancelLocked();
  }
  m_state->wake.notify_all();
  m_state->worker.join();
}

std::uint64_t ProgressiveReference::start(const Scene& scene, SurfaceData surfaces, const std::string& aov,
                                          const ProgressiveOptions& options) {
  return start(nullptr, scene, std::move(surfaces), aov, options);
}

std::uint64_t ProgressiveReference::start(std::shared_ptr<const PreparedReferenceScene> prepared, const Scene& scene,
                                          SurfaceData surfaces, const std::string& aov,
                                          const ProgressiveOptions& options) {
  {
    std::lock_guard lock(m_state->mutex);
    m_state->cancelLocked();
  }
  Job job;
  job.quantity = reference::parseQuantity(aov);
  reference::checkReferenceJob(job.quantity, options.targetSpp, "reference targetSpp", options.aoRadius, scene.lights,
                               surfaces);
  if (options.batchMaxSpp < kReferenceMinSpp || options.batchMaxSpp > kReferenceMaxSpp)
    usageError("reference batchMaxSpp " + std::to_string(options.batchMaxSpp) + " is out of range " +
               std::to_string(kReferenceMinSpp) + ".." + std::to_string(kReferenceMaxSpp));
  if (options.threads < 0 || options.threads > 1024)
    usageError("reference threads " + std::to_string(options.threads) + " is out of range 0..1024");
  job.threads = options.threads > 0 ? options.threads : std::max(1, tbb::info::default_concurrency() - 1);
  job.options = options;
  job.prepared = std::move(prepared);
  if (!job.prepared) job.scene = scene;
  job.lights = scene.lights;
  job.eye = scene.camera.position;
  job.surfaces = std::move(surfaces);

  std::uint64_t generation = 0;
  {
    std::lock_guard lock(m_state->mutex);
    generation = ++m_state->generation;
    job.generation = generation;
    m_state->cancelLocked();
    m_state->prepared = job.prepared; // null until the worker has built this job's BVH
    m_state->pending = std::move(job);
    m_state->running = true;
    m_state->error.clear();
    m_state->mean = Image();
    m_state->samples = 0;
    m_state->meanGeneration = 0;
    m_state->converged = false;
  }
  m_state->wake.notify_one();
  return generation;
}

void ProgressiveReference::stop() {
  std::unique_lock lock(m_state->mutex);
  m_state->cancelLocked();
  m_state->idle.wait(lock, [&] { return !m_state->busy; });
}

void ProgressiveReference::cancel() {
  std::lock_guard lock(m_state->mutex);
  m_state->cancelLocked();
}

bool ProgressiveReference::latest(ProgressiveSnapshot& out) const {
  std::lock_guard lock(m_state->mutex);
  const State& s = *m_state;
  if (s.meanGeneration == 0 || (out.generation == s.meanGeneration && out.samples == s.samples)) return false;
  out.image = s.mean;
  out.samples = s.samples;
  out.generation = s.meanGeneration;
  out.converged = s.converged;
  return true;
}

int ProgressiveReference::samples() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->samples;
}

std::uint64_t ProgressiveReference::generation() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->generation;
}

bool ProgressiveReference::running() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->running;
}

std::string ProgressiveReference::error() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->error;
}

std::shared_ptr<const PreparedReferenceScene> ProgressiveReference::preparedScene() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->prepared;
}

} // namespace rtlab

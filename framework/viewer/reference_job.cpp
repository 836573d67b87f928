// One worker thread per ReferenceJob (reference_job.h): it waits for a pending job, runs the
// entry's compute function outside the lock, and publishes the image if its generation is still
// the current one. The mutex guards only the pending job and the published result, so start(),
// latest() and the status calls return at once while a computation runs. A computation that is
// superseded (start), cancelled or outlived (destructor) is told so through the frame's cancel flag
// (ReferenceFrame::cancelled), so it ends within a moment and the destructor can join the worker.
#include "viewer/reference_job.h"

#include "util/error.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace rtlab {

struct ReferenceJob::State {
  mutable std::mutex mutex;
  std::condition_variable wake; // the worker: a job is pending, or quit
  std::optional<ReferenceJobInput> pending;
  std::uint64_t pendingGeneration = 0;
  std::uint64_t generation = 0; // of the last start()
  bool quit = false;
  bool busy = false;    // the worker is computing (whatever the generation)
  bool running = false; // the current generation is pending or computing
  std::atomic<bool> cancel{false}; // the computation in progress is no longer wanted
  ReferenceJobResult result;       // the last published image (generation 0: none yet)
  std::string error;               // the last failure, and the generation it belongs to
  std::uint64_t errorGeneration = 0;
  std::thread worker;

  void loop();
};

void ReferenceJob::State::loop() {
  std::unique_lock lock(mutex);
  for (;;) {
    wake.wait(lock, [&] { return quit || pending.has_value(); });
    if (quit) return;
    ReferenceJobInput job = std::move(*pending);
    const std::uint64_t jobGeneration = pendingGeneration;
    pending.reset();
    busy = true;
    cancel = false;
    lock.unlock();

    ReferenceJobResult out;
    out.generation = jobGeneration;
    out.samples = job.spp;
    std::string failure;
    try {
      ReferenceFrame frame(job.entry, job.scene, job.params, job.spp, job.seed, false);
      frame.setCancel(&cancel);
      // Leave a core to the window's rasterizer (llvmpipe renders on the CPU too).
      const unsigned cores = std::thread::hardware_concurrency();
      frame.setThreads(cores > 1 ? cores - 1 : 1);
      if (job.surfaces) frame.setSurfaces(&*job.surfaces);
      if (job.prePostColor) frame.setPrePostColor(&*job.prePostColor);
      if (job.transparentFragments && job.opaqueColor) frame.setTransparentFragments(&*job.transparentFragments, &*job.opaqueColor);
      ReferenceStats stats;
      const auto begin = std::chrono::steady_clock::now();
      out.image = job.entry.compute(frame, stats);
      out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    } catch (const std::exception& e) {
      failure = e.what();
    } catch (...) {
      failure = "reference: unknown error";
    }

    lock.lock();
    busy = false;
    if (jobGeneration != generation || !running) continue; // superseded or cancelled meanwhile
    if (failure.empty()) {
      result = std::move(out);
    } else {
      error = failure;
      errorGeneration = jobGeneration;
    }
    running = false;
  }
}

ReferenceJob::ReferenceJob() : m_state(std::make_shared<State>()) {
  m_state->worker = std::thread([state = m_state] { state->loop(); });
}

ReferenceJob::~ReferenceJob() {
  {
    std::lock_guard lock(m_state->mutex);
    m_state->quit = true;
    m_state->pending.reset();
    m_state->running = false;
    m_state->cancel = true; // a computation in progress stops within a row of work
  }
  m_state->wake.notify_all();
  m_state->worker.join();
}

std::uint64_t ReferenceJob::start(ReferenceJobInput input) {
  const ReferenceEntry& e = input.entry;
  if (!e.compute) throw Error(ExitCode::Internal, "reference '" + e.aov + "' has no compute function");
  if (e.inputs.has(FrameInput::SurfacePoints) && !input.surfaces)
    throw Error(ExitCode::Internal, "reference '" + e.aov + "' needs the frame's surface points");
  if (e.inputs.has(FrameInput::PrePostColor) && !input.prePostColor)
    throw Error(ExitCode::Internal, "reference '" + e.aov + "' needs the frame's colour before post");
  if (e.inputs.has(FrameInput::TransparentFragments) && (!input.transparentFragments || !input.opaqueColor))
    throw Error(ExitCode::Internal, "reference '" + e.aov + "' needs the frame's transparent fragments and opaque colour");
  if (input.spp < e.minSpp || input.spp > e.maxSpp)
    usageError("spp " + std::to_string(input.spp) + " is out of range " + std::to_string(e.minSpp) + ".." +
               std::to_string(e.maxSpp) + " for the " + e.aov + " reference");
  std::uint64_t generation = 0;
  {
    std::lock_guard lock(m_state->mutex);
    generation = ++m_state->generation;
    m_state->pending = std::move(input);
    m_state->pendingGeneration = generation;
    m_state->running = true;
    m_state->cancel = true; // the computation in progress (if any) is superseded
  }
  m_state->wake.notify_all();
  return generation;
}

void ReferenceJob::cancel() {
  std::lock_guard lock(m_state->mutex);
  m_state->pending.reset();
  m_state->running = false;
  m_state->cancel = true;
}

bool ReferenceJob::latest(ReferenceJobResult& out) const {
  std::lock_guard lock(m_state->mutex);
  const ReferenceJobResult& r = m_state->result;
  if (r.generation == 0 || r.generation != m_state->generation || out.generation == r.generation) return false;
  out = r;
  return true;
}

std::uint64_t ReferenceJob::generation() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->generation;
}

bool ReferenceJob::running() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->running;
}

std::string ReferenceJob::error() const {
  std::lock_guard lock(m_state->mutex);
  return m_state->errorGeneration == m_state->generation ? m_state->error : std::string();
}

} // namespace rtlab

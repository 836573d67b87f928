#include "app/sweep_jobs.h"

#include "app/child_process.h"
#include "app/measure.h"
#include "app/reference_run.h"
#include "app/run_info.h"
#include "frame/registry.h"
#include "gl/debug.h"
#include "image/image.h"
#include "platform/context.h"
#include "render/renderer.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;

namespace rtlab {
namespace {

void makeDirectory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) outputError("cannot create '" + dir + "': " + ec.message());
}

void copyAtomically(const std::string& from, const std::string& to) {
  writeFileAtomically(to, [&](const std::string& tmp) {
    std::error_code ec;
    fs::copy_file(from, tmp, fs::copy_options::overwrite_existing, ec);
    if (ec) errno = ec.value();
    return !ec;
  });
}

std::string duration(double seconds) {
  const long long s = seconds < 0 ? 0 : (long long)(seconds + 0.5);
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%lld:%02lld", s / 60, s % 60);
  return buf;
}

// The child's own error line from its log, or its last line.
std::string childMessage(const std::string& log) {
  std::ifstream in(log);
  std::string line, error, last;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last = line;
    if (line.rfind("rtlab: error: ", 0) == 0) error = line.substr(14);
  }
  return !error.empty() ? error : !last.empty() ? last : "no output";
}

double unixSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

struct Job {
  bool point = false;
  int index = 0;
  std::string label; // "point 003 (pcf pcf.samples=4)"
  std::string log;
  std::vector<std::string> argv;
};

class Progress {
public:
  Progress(int references, int points) : m_refTotal(references), m_pointTotal(points), m_tty(::isatty(2)) {
    m_start = std::chrono::steady_clock::now();
  }
  void finished(const Job& job) {
    (job.point ? m_points : m_refs)++;
    if (m_tty) draw();
    else std::fprintf(stderr, "sweep: %d/%d done: %s, %s\n", m_points + m_refs, m_refTotal + m_pointTotal,
                      job.label.c_str(), timeText().c_str());
  }
  // Redraws at most once a second while jobs run.
  void tick() {
    const auto now = std::chrono::steady_clock::now();
    if (!m_tty || now - m_lastDraw < std::chrono::seconds(1)) return;
    draw();
  }
  void draw() {
    if (!m_tty) return;
    m_lastDraw = std::chrono::steady_clock::now();
    const int total = m_refTotal + m_pointTotal, done = m_points + m_refs;
    const int width = 24, filled = total ? done * width / total : width;
    std::string bar(std::size_t(filled), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r\033[K[%s] %d/%d points", bar.c_str(), m_points, m_pointTotal);
    if (m_refTotal) std::fprintf(stderr, ", %d/%d references", m_refs, m_refTotal);
    std::fprintf(stderr, ", %s", timeText().c_str());
    std::fflush(stderr);
  }
  void end() {
    if (m_tty) std::fputc('\n', stderr);
  }

private:
  std::string timeText() const {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const int total = m_refTotal + m_pointTotal, done = m_points + m_refs;
    std::string s = duration(elapsed) + " elapsed";
    if (done > 0 && done < total) s += ", ~" + duration(elapsed / done * (total - done)) + " left";
    return s;
  }
  int m_refTotal, m_pointTotal, m_refs = 0, m_points = 0;
  bool m_tty;
  std::chrono::steady_clock::time_point m_start, m_lastDraw;
};

pid_t spawn(const Job& job) {
  const int log = ::open(job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  ChildSpec spec{job.argv, in, log, log, SIGTERM, nullptr, "a sweep job"}; // a killed sweep takes its jobs with it
  pid_t pid = -1;
  try {
    pid = spawnSelf(spec);
  } catch (...) {
    if (log >= 0) ::close(log);
    if (in >= 0) ::close(in);
    throw;
  }
  if (log >= 0) ::close(log);
  if (in >= 0) ::close(in);
  return pid;
}

ExitCode childExitCode(int status, std::string& why) {
  if (WIFEXITED(status)) {
    const int code = WEXITSTATUS(status);
    switch (code) {
    case 2: case 3: case 4: case 5: case 6: case 130: return ExitCode(code);
    default: why = code == 127 ? "could not run /proc/self/exe" : ""; return ExitCode::Internal;
    }
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    why = "killed by signal " + std::to_string(sig);
    return sig == SIGINT || sig == SIGTERM ? ExitCode::Interrupted : ExitCode::Internal;
  }
  return ExitCode::Internal;
}

} // namespace

bool referenceFromCache(const SweepPlan& plan, int k) {
  const SweepReference& r = plan.references.at(std::size_t(k));
  const std::string dest = referencePath(plan, r.hash);
  std::error_code ec;
  if (fs::is_regular_file(dest, ec)) return true;
  const std::string cached = cachedReferencePath(r.hash);
  if (cached.empty() || !fs::is_regular_file(cached, ec)) return false;
  makeDirectory(fs::path(dest).parent_path().string());
  copyAtomically(cached, dest);
  logInfo("reference " + r.hash + " from the cache " + cached);
  return true;
}

void runReferenceJob(const SweepPlan& plan, int k) {
  if (k < 0 || k >= int(plan.references.size()))
    usageError("reference " + std::to_string(k) + " does not exist (the plan has " +
               std::to_string(plan.references.size()) + ")");
  if (referenceFromCache(plan, k)) return;
  const SweepReference& r = plan.references[std::size_t(k)];
  ResolvedFrame frame = resolvePointFrame(plan, plan.points.at(std::size_t(r.point)));
  if (referenceHash(plan, frame.params) != r.hash)
    throw Error(ExitCode::Internal, "reference " + std::to_string(k) + " of '" + plan.dir +
                                        "' does not match its plan (planned by another rtlab version?)");
  // The reference renders what its inputs need (app/reference_run.h): the G-buffer's surface
  // points; the other stages' techniques only for the colour before post.
  frame.options.frames = 1;
  const std::string dest = referencePath(plan, r.hash);
  makeDirectory(fs::path(dest).parent_path().string());

  auto context = createHeadlessContext(frame.options.backend);
  Renderer renderer(TechniqueRegistry::instance());
  renderer.setScene(frame.scene);
  ReferenceStats stats;
  const Image image = renderReferenceFrame(renderer, frame, sweepReference(plan), plan.spp, false, stats);

  const std::string cached = cachedReferencePath(r.hash);
  if (!cached.empty()) {
    std::error_code ec;
    fs::create_directories(fs::path(cached).parent_path(), ec);
    try {
      if (ec) outputError(ec.message());
      writeImage(cached, image);
    } catch (const Error& e) {
      logWarn(std::string("reference not cached: ") + e.what());
    }
  }
  writeImage(dest, image);
}

bool pointDone(const SweepPlan& plan, int n) {
  const fs::path dir = pointDir(plan, n);
  std::error_code ec;
  for (const char* f : {"aov.exr", "color.png", "stats.json", "done.json"})
    if (!fs::is_regular_file(dir / f, ec)) return false;
  try {
    const auto done = nlohmann::json::parse(readFileOrThrow((dir / "done.json").string()));
    return done.value("plan", std::string()) == plan.id && done.value("point", -1) == n;
  } catch (const std::exception&) {
    return false;
  }
}

void runPointJob(const SweepPlan& plan, int n) {
  if (n < 0 || n >= int(plan.points.size()))
    usageError("point " + std::to_string(n) + " does not exist (the plan has " + std::to_string(plan.points.size()) +
               ", 0.." + std::to_string(int(plan.points.size()) - 1) + ")");
  const SweepPoint& point = plan.points[std::size_t(n)];
  const ResolvedFrame frame = resolvePointFrame(plan, point);
  const fs::path dir = pointDir(plan, n);
  makeDirectory(dir.string());
  std::error_code ec;
  fs::remove(dir / "done.json", ec); // a re-run is not done until it has finished

  auto context = createHeadlessContext(frame.options.backend);
  const TimingMethod timing = resolveTiming(frame.options.timing, context->info().software);
  Renderer renderer(TechniqueRegistry::instance());
  renderer.setScene(frame.scene);
  FrameOutputs outputs;
  outputs.aovs = {plan.aov};
  outputs.displayColor = true;
  if (frame.options.frames == 1) {
    // Shaders compile and resources are allocated in an unmeasured frame, so that one measured
    // frame times the frame, not the shader compiler (docs/sweeps.md).
    renderer.setTechniques(frame.techniques);
    PassTimer warmup(timing);
    renderer.render(frame.params, frame.options.width, frame.options.height, outputs, warmup);
    drainGlErrors();
  }
  const double measuredFrom = unixSeconds();
  const FrameStats stats = renderMeasured(renderer, frame, outputs, timing, true);
  const double measuredTo = unixSeconds();
  writeImage((dir / "aov.exr").string(), renderer.readAov(plan.aov));
  writeImage((dir / "color.png").string(), renderer.readDisplayColor(), PngEncoding::Srgb);
  writeTextAtomically((dir / "stats.json").string(), statsJson(frame, *context, timing, stats).dump(2) + "\n");
  nlohmann::ordered_json done;
  done["schema"] = 1;
  done["plan"] = plan.id;
  done["point"] = n;
  done["technique"] = point.technique;
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  for (const auto& [k, v] : point.values) values[k] = v;
  done["values"] = values;
  done["reference"] = point.reference;
  // When the measured frames ran and on what: --collect finds points measured at the same time
  // on a software rasterizer, whose timings are not the technique's alone (docs/sweeps.md).
  done["measured"] = {measuredFrom, measuredTo};
  done["software"] = context->info().software;
  writeTextAtomically((dir / "done.json").string(), done.dump(2) + "\n");
}

void runSweepJobs(const SweepPlan& plan, const std::vector<int>& references, int jobs) {
  const fs::path logs = fs::path(plan.dir) / "logs";
  makeDirectory(logs.string());
  std::vector<Job> queue;
  for (int k : references) {
    Job j;
    j.index = k;
    j.label = "reference " + plan.references[std::size_t(k)].hash;
    j.log = (logs / ("reference-" + std::to_string(k) + ".log")).string();
    j.argv = {"rtlab", "sweep", "--run-reference", plan.dir, std::to_string(k)};
    queue.push_back(std::move(j));
  }
  for (const auto& p : plan.points) {
    Job j;
    j.point = true;
    j.index = p.index;
    j.label = "point " + pointName(p.index) + " (" + describePoint(p) + ")";
    j.log = (logs / ("point-" + pointName(p.index) + ".log")).string();
    j.argv = {"rtlab", "sweep", "--run-point", plan.dir, std::to_string(p.index)};
    queue.push_back(std::move(j));
  }
  std::fprintf(stderr, "sweep: %zu points, %zu of %zu references to render, %d job%s at a time, into %s\n",
               plan.points.size(), references.size(), plan.references.size(), jobs, jobs == 1 ? "" : "s",
               plan.dir.c_str());
  Progress progress(int(references.size()), int(plan.points.size()));
  progress.draw();

  std::map<pid_t, const Job*> running;
  std::size_t next = 0;
  const Job* failed = nullptr;
  ExitCode failedCode = ExitCode::Ok;
  std::string failedWhy;
  while (true) {
    while (!failed && next < queue.size() && int(running.size()) < jobs) {
      // References (Embree on every core) finish before points start, so that no point is timed
      // while a reference competes for the machine.
      const bool referenceRunning =
          std::any_of(running.begin(), running.end(), [](const auto& r) { return !r.second->point; });
      if (queue[next].point && referenceRunning) break;
      const Job& job = queue[next++];
      running[spawn(job)] = &job;
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw Error(ExitCode::Internal, std::string("waitpid: ") + std::strerror(errno));
    }
    if (pid == 0) { // none finished: keep the clock on the bar moving
      ::usleep(50 * 1000);
      progress.tick();
      continue;
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const Job* job = it->second;
    running.erase(it);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      fs::remove(job->log);
      progress.finished(*job);
      continue;
    }
    if (!failed) {
      failed = job;
      failedCode = childExitCode(status, failedWhy);
      for (const auto& [other, j] : running) ::kill(other, SIGTERM);
    }
  }
  progress.end();
  std::error_code ec;
  fs::remove(logs, ec); // only when empty: the logs of failed jobs stay
  if (failed) {
    std::string message = childMessage(failed->log);
    if (!failedWhy.empty()) message = failedWhy + ": " + message;
    throw Error(failedCode, failed->label + " failed: " + message + " (log: " + failed->log + ")");
  }
}

} // namespace rtlab

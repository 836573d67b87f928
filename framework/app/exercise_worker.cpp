#include "app/exercise_worker.h"

#include "app/args.h"
#include "app/exercise_option.h"
#include "app/frame_options.h"
#include "app/measure.h"
#include "app/reference_run.h"
#include "exercise/exercise_folder.h"
#include "frame/registry.h"
#include "image/raw_image.h"
#include "platform/context.h"
#include "reference/reference_registry.h"
#include "render/renderer.h"
#include "util/error.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <iterator>

namespace rtlab {
namespace {

const char* filesName(WorkerFiles f) {
  switch (f) {
  case WorkerFiles::Solution: return "solution";
  case WorkerFiles::Stub: return "stub";
  case WorkerFiles::Student: return "student";
  }
  return "solution";
}

void send(const nlohmann::json& header, const Image* image, const Image* reference) {
  std::string bytes = header.dump() + "\n";
  if (image) appendRawImage(bytes, *image);
  if (reference) appendRawImage(bytes, *reference);
  std::fwrite(bytes.data(), 1, bytes.size(), stdout);
  std::fflush(stdout);
}

} // namespace

std::string driverName(const Context& context) {
  const GlInfo& info = context.info();
  return context.backendName() + " | " + info.vendor + " | " + info.renderer + " | " + info.version;
}

nlohmann::json workerRequestJson(const WorkerRequest& r) {
  return {{"exercise", r.exercise}, {"files", filesName(r.files)}, {"dir", r.dir}, {"aov", r.aov},
          {"backend", r.backend}, {"references", r.references}, {"views", viewsToJson(r.views)}, {"first", r.first}};
}

WorkerRequest workerRequestFromJson(const nlohmann::json& j) {
  WorkerRequest r;
  r.exercise = j.at("exercise").get<std::string>();
  const std::string files = j.at("files").get<std::string>();
  r.files = files == "student" ? WorkerFiles::Student : files == "stub" ? WorkerFiles::Stub : WorkerFiles::Solution;
  r.dir = j.at("dir").get<std::string>();
  r.aov = j.at("aov").get<std::string>();
  r.backend = j.at("backend").get<std::string>();
  r.references = j.at("references").get<bool>();
  r.views = viewsFromJson(j.at("views"), "worker request");
  r.first = j.at("first").get<std::size_t>();
  return r;
}

ResolvedFrame resolveViewFrame(const ExerciseView& view, const std::string& technique, const std::string& backend) {
  std::vector<std::string> args = {"rtlab", "exercise", "--scene", view.scene, "--size", viewSize(view), "--seed", std::to_string(view.seed),
                                   "--backend", backend};
  for (const auto& t : view.techniques.empty() ? std::vector<std::string>{technique} : view.techniques) {
    args.push_back("-t");
    args.push_back(t);
  }
  for (const auto& [key, value] : view.set) {
    args.push_back("--set");
    args.push_back(key + "=" + value);
  }
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  return resolveFrame(Args("exercise", frameOptionSpecs(), int(argv.size()), argv.data(), 2));
}

int runExerciseWorker() {
  const std::string input((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  const WorkerRequest request = workerRequestFromJson(nlohmann::json::parse(input));
  const ExerciseDef& def = findExercise(request.exercise);
  if (request.files == WorkerFiles::Stub) installShaderReplacements(stubReplacements(def));
  if (request.files == WorkerFiles::Student) installShaderReplacements(folderReplacements(readExerciseFolder(request.dir)));

  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  std::unique_ptr<Context> context;
  // One renderer for every view: its program cache compiles each program once (Mesa's disk cache is
  // off in workers). It is made anew after a view that failed, whose frame may have stopped midway.
  std::unique_ptr<Renderer> renderer;
  for (std::size_t i = request.first; i < request.views.size(); ++i) {
    const ExerciseView& view = request.views[i];
    nlohmann::json header = {{"view", i}};
    const auto start = std::chrono::steady_clock::now();
    try {
      const ResolvedFrame frame = resolveViewFrame(view, def.technique, request.backend);
      if (!context) context = createHeadlessContext(frame.options.backend);
      const TimingMethod timing = resolveTiming(frame.options.timing, context->info().software);
      if (!renderer) renderer = std::make_unique<Renderer>(registry);
      renderer->setScene(frame.scene);
      FrameOutputs outputs;
      outputs.aovs = {request.aov};
      renderMeasured(*renderer, frame, outputs, timing, false);
      const Image image = renderer->readAov(request.aov);
      header["ms"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      header["status"] = "ok";
      header["image"] = rawImageShape(image);
      header["gl"] = driverName(*context);
      Image reference;
      if (request.references) {
        const ReferenceEntry& entry = ReferenceRegistry::instance().get(request.aov);
        reference = renderReferenceFrame(*renderer, frame, entry.aov, view.spp > 0 ? view.spp : entry.defaultSpp, false);
        header["reference"] = rawImageShape(reference);
      }
      send(header, &image, request.references ? &reference : nullptr);
    } catch (const Error& e) {
      header["status"] = e.code() == ExitCode::Shader ? "compile_error" : "error";
      header["message"] = e.what();
      header["code"] = int(e.code());
      header["ms"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      send(header, nullptr, nullptr);
      renderer.reset();
      if (e.code() == ExitCode::NoContext) return int(e.code());
    }
  }
  return 0;
}

} // namespace rtlab

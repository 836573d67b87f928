// The plan of a sweep (docs/sweeps.md): which points, which references, and everything a job
// needs to render one of them, in DIR/sweep.json (schema 1). Planning validates every option,
// key and value before anything is rendered; jobs and --collect read the plan back.
#pragma once
#include "app/args.h"
#include "app/frame_options.h"
#include "params/sweep_spec.h"
#include "reference/reference_registry.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace rtlab {

struct SweepPoint {
  int index = 0;
  std::string technique;
  std::vector<std::pair<std::string, std::string>> values; // (key, canonical text) of the axes that apply
  std::string reference;                                   // hash of its reference
};

struct SweepReference {
  std::string hash;
  int point = 0; // the first point that uses it: its frame defines the reference
};

struct SweepPlan {
  std::string dir;      // absolute
  std::string binary;   // absolute path of the rtlab that planned (the jobs run it)
  std::string id;       // content hash of the plan; each point's done.json repeats it
  std::string version, commit;
  std::string scene;    // built-in name, or an absolute file path
  std::string sceneHash;
  std::string stage, aov;
  int width = 640, height = 360, frames = 1;
  unsigned seed = 1;
  std::string backend = "auto", timing = "auto";
  int spp = 64;
  int jobs = 0;         // points run at a time by the direct sweep; 0: unknown (--emit-jobs)
  std::string command;  // the sweep's command line as given, shell-quoted ("rtlab sweep ..."): reproduces it
  std::string cwd;      // the working directory it was given in (relative paths in `command`)
  std::vector<std::string> baseTechniques; // active techniques of other stages (from --preset)
  nlohmann::ordered_json baseParams = nlohmann::ordered_json::object(); // resolved values that differ from the defaults
  std::vector<std::string> techniques;     // swept, in -t order
  std::vector<SweepAxis> axes;             // in --vary order
  std::vector<SweepReference> references;
  std::vector<SweepPoint> points;
};

struct SweepRequest {
  std::vector<std::string> techniques; // -t values, comma lists allowed
  std::vector<std::string> varies;     // --vary values
  int spp = 0;         // --spp; 0: the stage reference's default (64 for the ray-traced ones, 1 for bloom's)
  int jobs = 0;        // 0 with --emit-jobs
  std::string dir;
  std::string command; // shell-quoted command line
};

// Unmeasured frames a point renders before its measured ones: 2 when frames > 1 (as render), 1
// otherwise (docs/sweeps.md "What a point renders").
int sweepWarmupFrames(const SweepPlan& plan);

// Resolves and validates everything (exit 2/3 on bad input). `frameArgs` holds the scene and
// frame options only (no -t).
SweepPlan planSweep(const Args& frameArgs, const SweepRequest& request);

// DIR/sweep.json and DIR/jobs.txt, atomically. readSweepPlan: Error(Input) if missing or invalid.
void writeSweepPlan(const SweepPlan& plan);
SweepPlan readSweepPlan(const std::string& dir);
nlohmann::ordered_json sweepPlanToJson(const SweepPlan& plan);

// The frame of a point, rebuilt from the plan alone. Error(Input) if the scene changed since
// planning (its content hash differs).
ResolvedFrame resolvePointFrame(const SweepPlan& plan, const SweepPoint& point);

// Content hash of a scene as loaded (geometry, instances, materials, textures, lights, camera).
std::string sceneContentHash(const Scene& scene);
// The registered reference of the plan's stage (Error(Input) if the stage has none: a plan from
// another rtlab).
const ReferenceEntry& sweepReference(const SweepPlan& plan);
// The reference's identity: version, scene content, stage AOV, size, spp, seed, and the resolved
// values of exactly the keys the stage's registered reference declares (reference/reference_registry.h:
// light<N>.*, camera.*, and ao.radius for ao).
std::string referenceHash(const SweepPlan& plan, const ParamSet& params);

std::string pointDir(const SweepPlan& plan, int index);               // DIR/points/007
std::string pointName(int index);                                     // "007"
std::string referencePath(const SweepPlan& plan, const std::string& hash); // DIR/reference/<hash>.exr
// ${RTLAB_CACHE_DIR:-$HOME/.cache/rtlab}/reference/<hash>.exr, or "" without either variable.
std::string cachedReferencePath(const std::string& hash);

// One self-contained shell command per job: references first, then points.
std::vector<std::string> sweepJobLines(const SweepPlan& plan);
std::string shellQuote(const std::string& text);
// "shadow_map shadow.resolution=512 light0.angle=1"
std::string describePoint(const SweepPoint& point);

} // namespace rtlab

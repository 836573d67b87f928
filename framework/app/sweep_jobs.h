// The jobs of a sweep (docs/sweeps.md): rendering one reference or one point, each in its own
// process (`rtlab sweep --run-reference DIR K`, `rtlab sweep --run-point DIR N`), and running
// them N at a time with a progress bar for a direct sweep.
#pragma once
#include "app/sweep_plan.h"

namespace rtlab {

// Puts the reference into DIR/reference/<hash>.exr: copied from the cache when it is there,
// rendered (and cached) otherwise.
void runReferenceJob(const SweepPlan& plan, int reference);
// Copies a cached reference into DIR if there is one; true when DIR then holds it. No GL.
bool referenceFromCache(const SweepPlan& plan, int reference);

// Renders a point: DIR/points/<nnn>/{aov.exr, color.png, stats.json} then done.json.
void runPointJob(const SweepPlan& plan, int point);
// Whether a point's outputs are all there and belong to this plan.
bool pointDone(const SweepPlan& plan, int point);

// Runs the given reference and point jobs as child processes of this binary, `jobs` at a time,
// references first, with a progress bar on stderr (plain lines when stderr is not a terminal).
// The first failure stops new jobs and is thrown as the child's error (its exit code).
void runSweepJobs(const SweepPlan& plan, const std::vector<int>& references, int jobs);

} // namespace rtlab

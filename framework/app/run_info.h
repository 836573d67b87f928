// The description of a run that every JSON output repeats: schema, version, commit, renderer,
// backend, timing method, size, seed, techniques and resolved parameters.
#pragma once
#include "app/frame_options.h"
#include "frame/pass_timer.h"
#include "frame/stats.h"

#include <nlohmann/json.hpp>

namespace rtlab {

class Context;

// The --stats JSON of docs/contract.md.
nlohmann::ordered_json statsJson(const ResolvedFrame& frame, const Context& context, TimingMethod timing,
                                 const FrameStats& stats);

} // namespace rtlab

// Scripted viewer runs (`rtlab view --script FILE`, docs/contract.md): a JSON list of actions, parsed
// and validated before the window opens, so that a bad script exits 3 (unreadable or invalid
// JSON, an unknown action or field) or 2 (an unknown technique, key or out-of-range value) with
// a one-line message naming the action's index, and never half-runs. GL-free, unit-tested.
//
// Actions (objects with an "action" field):
//   {"action": "technique", "stage": "shadow", "id": "pcss"}      id "off" or "none" turns the stage off
//   {"action": "set", "key": "pcss.filter_samples", "value": 32}  value as in presets
//   {"action": "reset", "key": "pcss.filter_samples"}
//   {"action": "camera", "position": [x,y,z], "target": [x,y,z], "fov": 45}  each optional
//   {"action": "orbit", "yaw": 10, "pitch": 0}                   degrees about the target
//   {"action": "view", "aov": "visibility", "mode": "full"|"pip"|"off", "min": 0, "max": 1,
//    "false_color": true}                                          debug view
//   {"action": "compare", "mode": "reference"|"snapshot"|"difference"|"off", "divider": 0.5}
//   {"action": "snapshot"}                                         freeze the current frame as B
//   {"action": "wait", "frames": 5}
//   {"action": "wait_samples", "samples": 64, "timeout_s": 120}    until the reference has N spp
//        (an exact reference: until it is computed and measured against)
//   {"action": "screenshot", "file": "a.png"}                      the window, UI included
//   {"action": "save_preset", "file": "p.json"}
//   {"action": "load_preset", "file": "p.json"}
//   {"action": "report", "file": "r.json"}   writes the viewer's state: frame count, techniques,
//        compare mode, reference samples, live metrics (rmse, flip), timings, gl_errors,
//        shader_errors
//   {"action": "render_scale", "value": 0.5}
//   {"action": "lecture", "on": true}
//   {"action": "bookmark", "index": 0}                             jump to bookmark N
//   {"action": "panel", "on": false}                               hide (show) the side panel
//   {"action": "section", "name": "Debug view", "open": true}      open (close) a panel section
//   {"action": "ramp", "key": "pcf.radius", "from": 0, "to": 8, "frames": 30}  one step a frame
//   {"action": "record", "dir": "frames"} ... {"action": "stop"}   every frame drawn as DIR/frame_NNNNN.png
//   {"action": "quit"}
#pragma once
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rtlab {

struct ScriptAction {
  std::string action;   // one of the names above
  std::size_t index = 0; // position in the script (for messages), counted from 0
  nlohmann::json args;  // the object as written, validated against the action's fields
  std::string source;   // the script's name, for messages
  // "script 'demo.json' action 3 (\"wait\")": the prefix of every message about this action.
  std::string where() const;
};

// Defaults and limits of fields (docs/viewer-scripts.md).
inline constexpr double kScriptSampleTimeoutDefault = 600.0;          // wait_samples "timeout_s", seconds
inline constexpr double kRenderScaleMin = 0.1, kRenderScaleMax = 1.0; // render_scale "value"

// Every action name, in the order docs/viewer-scripts.md lists them.
const std::vector<std::string>& scriptActionNames();

// Parses the JSON text of a script. Throws Error(Input) for malformed JSON, a non-list, an
// object without "action", an unknown action, a missing or unknown field or a field of the
// wrong JSON type; Error(Usage) for a value out of its range or choices (a negative frame or
// sample count, a mode that does not exist, a divider outside [0, 1], ...). Keys, technique ids and
// parameter values are checked by the viewer against its ParamSet before the first frame
// (validateScript below), so errors still come before anything runs.
std::vector<ScriptAction> parseScript(const std::string& text, const std::string& sourceName);
std::vector<ScriptAction> loadScript(const std::string& path); // Error(Input) if unreadable
// The checks parseScript makes on one action (its name, fields, JSON types and ranges), for
// actions built in code; validateScript makes them too, so it never reads a missing field.
void checkScriptAction(const ScriptAction& action);

class ParamSet;
class TechniqueRegistry;
// The file "record" writes for the n-th recorded frame (from 0): DIR/frame_00000.png, ...
std::string recordedFramePath(const std::string& dir, long n);

// Checks every "technique", "set" and "reset" action against the registry and a copy of the
// parameters (values applied in order, so a later "set" may depend on an earlier one's key
// existing); Error(Usage) naming the action index and the key.
// Also checks that a "view" AOV is a built-in AOV or a registered technique's debug view, that
// "load_preset" files load and apply (unless an earlier "save_preset" of the script writes
// them), and that "screenshot", "report" and "save_preset" paths are writable (Error(Output)).
// A "ramp" needs a numeric (float or int) key and both ends in its range; a "record" an existing
// writable directory (Error(Output)) and no recording already running; a "stop" a running one.
void validateScript(const std::vector<ScriptAction>& script, const ParamSet& params,
                    const TechniqueRegistry& registry);
// Error(Usage) naming the action if a "bookmark" action's index is not below `bookmarkCount`.
void validateScriptBookmarks(const std::vector<ScriptAction>& script, std::size_t bookmarkCount);

} // namespace rtlab

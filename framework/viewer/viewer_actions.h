// The viewer's actions, shared by the UI panels, the keyboard, bookmarks and scripts, so a
// slider and a script's "set" change the state the same way. Every action validates its input as
// the command line does (Error(Usage) naming the key and range, Error(Input) for a bad file);
// the UI shows the message in its status line, a script run stops with the message's exit code.
#pragma once
#include "viewer/viewer_state.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace rtlab {

class TechniqueRegistry;

// Loads a scene (built-in name or .gltf/.glb file) keeping the techniques and every parameter
// that is not a light or camera key; the camera goes to the new scene's camera.
void loadSceneAction(ViewerState& state, const std::string& spec);
// Activates `id` in `stage` ("off" or "none": deactivates the stage's technique).
void selectTechniqueAction(ViewerState& state, const std::string& stage, const std::string& id);
// Switches one technique on or off by itself (a stack stage's checkbox; on in an exclusive stage
// replaces the stage's technique). Error(Usage) for an unknown id.
void setTechniqueActiveAction(ViewerState& state, const std::string& id, bool on);
void setParamAction(ViewerState& state, const std::string& key, const nlohmann::json& value);
void setParamValueAction(ViewerState& state, const std::string& key, const ParamValue& value);
void resetParamAction(ViewerState& state, const std::string& key);
// Moves the camera; each part optional. Values are checked against the camera.* keys.
void cameraAction(ViewerState& state, const std::optional<glm::vec3>& position, const std::optional<glm::vec3>& target,
                  const std::optional<float>& fov);
// The camera back to its home (the scene's camera, or --set camera.* at start) / framed on the
// scene's bounds (keys F and R, and their panel buttons); the camera.* keys follow.
void resetCameraAction(ViewerState& state);
void frameSceneAction(ViewerState& state);
// Applies a "view" object / a "compare" object (viewer/view_fields.h), fields optional.
void viewAction(ViewerState& state, const nlohmann::json& fields);
void compareAction(ViewerState& state, const nlohmann::json& fields);
// Shows or hides the side panel (the frame then fills the window).
void panelAction(ViewerState& state, bool shown);
// Opens or closes a panel section at the next panel draw (Error(Usage) for an unknown name).
void sectionAction(ViewerState& state, const std::string& name, bool open);
// The value a "ramp" sets at `step` of `frames` (1..frames): linear from `from` (step 0) to
// exactly `to` at the last step.
double rampValue(double from, double to, long step, long frames);
void renderScaleAction(ViewerState& state, double scale); // Error(Usage) outside [0.1, 1]
// Presets in the `--preset` format (docs/contract.md); loading keeps the current scene.
void savePresetAction(const ViewerState& state, const std::string& path);
void loadPresetAction(ViewerState& state, const std::string& path);
// Applies bookmark `index` (Error(Usage) if out of range).
void bookmarkAction(ViewerState& state, int index);

// The camera.* parameters follow the interactive camera (after mouse or keyboard moves) and the
// other way round (after a camera.* key was set).
void syncCameraToParams(ViewerState& state);
void syncCameraFromParams(ViewerState& state);

} // namespace rtlab

// The lecture viewer's window and main loop (`rtlab view`, docs/viewer.md): GLFW + Dear ImGui,
// the camera, the side panel, the frame at a render scale, debug views, compare modes against
// the progressive reference or a snapshot, hot reload, lecture mode, screenshots and scripts.
#pragma once
#include "app/frame_options.h"
#include "viewer/bookmarks.h"
#include "viewer/script.h"

#include <optional>
#include <string>
#include <vector>

namespace rtlab {

struct ViewerOptions {
  ResolvedFrame frame;
  std::string screenshot;                          // --screenshot: after frame.options.frames frames, then exit
  std::optional<std::vector<ScriptAction>> script; // --script, validated
  std::vector<Bookmark> bookmarks;                 // --bookmarks, validated
  std::string bookmarksSource;
  std::string exercise;                            // --exercise: "exercise ID (DIR)", in the title
};

// Opens the window (Error(NoContext) without a display) and runs until the window closes, Esc,
// a script's "quit" or the --screenshot frame. Returns the exit code (0).
int runViewer(ViewerOptions options);

} // namespace rtlab

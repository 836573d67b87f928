#include "ui/fonts.h"

#include "util/log.h"

#include <imgui.h>

#include <filesystem>

namespace rtlab {

ViewerFonts loadViewerFonts() {
  ImGuiIO& io = ImGui::GetIO();
  ViewerFonts fonts;
  std::error_code ec;
  if (std::filesystem::exists(kViewerFontPath, ec)) {
    fonts.normal = io.Fonts->AddFontFromFileTTF(kViewerFontPath, kViewerFontSize);
    fonts.lecture = io.Fonts->AddFontFromFileTTF(kViewerFontPath, kViewerFontSize * kLectureFontScale);
  }
  if (!fonts.normal) {
    logWarn(std::string("viewer: font ") + kViewerFontPath +
            " not found (install fonts-dejavu-core); using ImGui's built-in font");
    fonts.normal = io.Fonts->AddFontDefault();
    fonts.lecture = nullptr;
  }
  return fonts;
}

void useLectureFont(const ViewerFonts& fonts, bool lecture) {
  ImGuiIO& io = ImGui::GetIO();
  if (fonts.lecture) {
    io.FontDefault = lecture ? fonts.lecture : fonts.normal;
    io.FontGlobalScale = 1.0f;
  } else {
    io.FontDefault = fonts.normal;
    io.FontGlobalScale = lecture ? kLectureFontScale : 1.0f;
  }
}

} // namespace rtlab

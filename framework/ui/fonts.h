// The viewer's fonts: DejaVu Sans (Debian fonts-dejavu-core) rasterized at the normal and at the
// lecture size, so lecture mode's large text stays crisp (ImGui's built-in bitmap font blurs when
// scaled). Without the font file, ImGui's built-in font is used and lecture mode scales it.
#pragma once

struct ImFont;

namespace rtlab {

inline constexpr const char* kViewerFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr float kViewerFontSize = 15.0f, kLectureFontScale = 2.0f;

struct ViewerFonts {
  ImFont* normal = nullptr;
  ImFont* lecture = nullptr; // nullptr when the TrueType font is missing
};

// Adds the fonts to ImGui's atlas; call before the backend builds its font texture.
ViewerFonts loadViewerFonts();
// Makes the lecture (or the normal) font the default for the next frames.
void useLectureFont(const ViewerFonts& fonts, bool lecture);

} // namespace rtlab

#include "app/frame_option_specs.h"

#include "util/error.h"

#include <charconv>
#include <string_view>

namespace rtlab {

std::vector<OptionSpec> frameOptionSpecs() {
  return {
      {"--scene", "", true, "S", "scene file (.gltf/.glb) or built-in name (default contact)"},
      {"--technique", "-t", true, "ID[,ID]", "activate techniques (repeatable); 'none' deactivates all"},
      {"--set", "", true, "KEY=VALUE", "set any parameter (repeatable); see 'rtlab list'"},
      {"--preset", "", true, "FILE", "preset file, applied before -t and --set"},
      {"--save-preset", "", true, "FILE", "write the resolved state as a preset"},
      {"--size", "", true, "WxH", "frame size in pixels, each 1..8192 (default 640x360)"},
      {"--frames", "", true, "N", "measured frames, after 2 warm-up frames when N > 1 (default 1)"},
      {"--seed", "", true, "N", "seed of every stochastic part (default 1)"},
      {"--backend", "", true, "B", "headless context: auto|egl|osmesa (default auto)"},
      {"--timing", "", true, "M", "pass timing: auto|gpu-query|cpu-finish (default auto)"},
  };
}

void parseSize(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  auto parse = [&](std::string_view s, int& out) {
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && ptr == s.data() + s.size() && out >= 1 && out <= 8192;
  };
  if (x == std::string::npos || !parse(std::string_view(text).substr(0, x), width) ||
      !parse(std::string_view(text).substr(x + 1), height))
    usageError("invalid --size '" + text + "': expected WxH with each in 1..8192");
}

} // namespace rtlab

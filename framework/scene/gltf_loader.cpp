// glTF 2.0 loading: the file is read here, parsed by tinygltf (JSON, buffers, GLB chunks), images
// are decoded by our own stb_image callback (which also bounds-checks image buffer views), then
// validateModel checks everything else before any conversion reads buffer data.
#include "scene/gltf_loader.h"

#include "scene/gltf_internal.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

#include <stb_image.h>

#include <cctype>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <new>
#include <sstream>

namespace rtlab {
namespace gltf {

void fail(const std::string& file, const std::string& what) {
  inputError("scene '" + file + "': " + what);
}

void warn(const std::string& file, const std::string& what) {
  logWarn("scene '" + file + "': " + what);
}

} // namespace gltf

namespace {

constexpr size_t kMaxMessage = 200;

struct ImageContext {
  const tinygltf::Model* model = nullptr;
};

// tinygltf image callback: decodes any stb_image format to 8-bit RGBA. tinygltf hands over a
// pointer into the buffer for images stored in a buffer view without checking the view's byte
// range, so that is checked here before the bytes are touched.
bool decodeImage(tinygltf::Image* image, const int index, std::string* err, std::string* /*warn*/,
                 int /*reqWidth*/, int /*reqHeight*/, const unsigned char* bytes, int size, void* user) {
  const auto* ctx = static_cast<const ImageContext*>(user);
  if (image->bufferView >= 0) {
    const auto& views = ctx->model->bufferViews;
    const auto view = static_cast<size_t>(image->bufferView);
    const auto buffer = view < views.size() ? static_cast<size_t>(views[view].buffer) : SIZE_MAX;
    if (buffer >= ctx->model->buffers.size() ||
        views[view].byteOffset > ctx->model->buffers[buffer].data.size() ||
        views[view].byteLength > ctx->model->buffers[buffer].data.size() - views[view].byteOffset) {
      *err += "image " + std::to_string(index) + " uses bufferView " + std::to_string(view) +
              ", which lies outside its buffer\n";
      return false;
    }
  }
  int w = 0, h = 0, comp = 0;
  unsigned char* data = size > 0 ? stbi_load_from_memory(bytes, size, &w, &h, &comp, 4) : nullptr;
  if (data == nullptr || w <= 0 || h <= 0) {
    if (data) stbi_image_free(data);
    const char* reason = stbi_failure_reason();
    *err += "image " + std::to_string(index) + " could not be decoded (" +
            (reason ? reason : "no data") + ")\n";
    return false;
  }
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(data, data + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  stbi_image_free(data);
  return true;
}

// One line of tinygltf's message text, with embedded data URIs elided and a length limit.
std::string tidy(const std::string& text) {
  if (text.find("Failed to decode 'uri'") != std::string::npos && text.find("Buffer") != std::string::npos)
    return "a buffer's data URI cannot be decoded or its data is shorter or longer than its byteLength";
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && line.find_first_not_of(" \t\r") == std::string::npos) {
  }
  if (size_t p = line.find("data:"); p != std::string::npos) {
    size_t end = line.find_first_of(" '\"]", p);
    line.replace(p, end == std::string::npos ? std::string::npos : end - p, "<data URI>");
  }
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.')) line.pop_back();
  if (line.size() > kMaxMessage) line = line.substr(0, kMaxMessage) + "...";
  return line.empty() ? "unknown parse error" : line;
}

void logEachLine(const std::string& file, const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) gltf::warn(file, tidy(line));
}

bool endsWithGlb(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".glb";
}

tinygltf::Model parse(const std::string& path, const std::string& bytes) {
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (endsWithGlb(path) && !binary) gltf::fail(path, "not a binary glTF file (bad magic, expected 'glTF')");
  if (bytes.size() >= UINT_MAX) gltf::fail(path, "the file is too large (4 GiB or more)");
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string base = parent.empty() ? std::string(".") : parent.string();

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  ImageContext ctx{&model};
  loader.SetImageLoader(&decodeImage, &ctx);
  std::string err, warnings;
  bool ok = false;
  try {
    const auto size = static_cast<unsigned int>(bytes.size());
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warnings,
                                              reinterpret_cast<const unsigned char*>(bytes.data()), size, base)
                : loader.LoadASCIIFromString(&model, &err, &warnings, bytes.data(), size, base);
  } catch (const std::exception& e) {
    ok = false;
    err = std::string("exception: ") + e.what();
  }
  if (!ok) {
    const char* what = binary ? "not a valid binary glTF file: " : "not a valid glTF file: ";
    gltf::fail(path, what + tidy(err));
  }
  logEachLine(path, err); // non-fatal problems tinygltf reports as errors (e.g. chunk padding)
  logEachLine(path, warnings);
  return model;
}

} // namespace

Scene loadGltf(const std::string& path) {
  const std::string bytes = readFileOrThrow(path, "scene");
  if (bytes.empty()) gltf::fail(path, "the file is empty");
  Scene scene;
  try {
    const tinygltf::Model model = parse(path, bytes);
    gltf::validateModel(model, path);
    scene.name = std::filesystem::path(path).stem().string();
    gltf::convertMaterials(model, scene, path);
    const auto meshMap = gltf::convertMeshes(model, scene, path);
    gltf::convertNodes(model, meshMap, scene, path);
  } catch (const std::bad_alloc&) {
    gltf::fail(path, "out of memory while loading");
  } catch (const std::length_error&) {
    gltf::fail(path, "data too large to load");
  }
  if (scene.instances.empty()) gltf::fail(path, "the scene has no triangle meshes");
  const Bounds bounds = scene.worldBounds();
  if (!scene.hasFileCamera) scene.camera = frameBounds(bounds);
  fitClipPlanes(scene.camera, bounds);
  if (scene.lights.empty()) {
    scene.lights.push_back(defaultLight(bounds));
    scene.hasFileLights = false;
  }
  return scene;
}

} // namespace rtlab

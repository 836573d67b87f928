#include "exercise/grade_cache.h"

#include "image/raw_image.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/log.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace rtlab {
namespace fs = std::filesystem;
namespace {

constexpr const char* kFormat = "rtlab-grade-cache-1";
constexpr std::size_t kMaxHeader = 4096;

std::string payloadHash(const char* data, std::size_t size) { return Fnv1a64().bytes(data, size).hex(); }

// Why the entry's bytes are not a sound entry for `key`, or "" when they are (then `images` holds them).
std::string check(const std::string& bytes, const std::string& key, std::size_t count, int width, int height,
                  std::vector<Image>& images) {
  const std::size_t eol = bytes.find('\n');
  if (eol == std::string::npos || eol > kMaxHeader) return "no header line";
  nlohmann::json header;
  try {
    header = nlohmann::json::parse(bytes.substr(0, eol));
    if (header.value("format", "") != kFormat) return "not a " + std::string(kFormat) + " entry";
    if (header.value("key", "") != key) return "it holds another key";
    const nlohmann::json& shapes = header.at("images");
    if (!shapes.is_array() || shapes.size() != count) return "it holds " + shapes.dump() + ", not " + std::to_string(count) + " images";
    std::size_t size = 0;
    for (const auto& shape : shapes) {
      if (shape.at(0) != width || shape.at(1) != height) return "an image is not " + std::to_string(width) + "x" + std::to_string(height);
      size += rawImageBytes(shape);
    }
    if (bytes.size() - eol - 1 != size)
      return "truncated or padded: " + std::to_string(bytes.size() - eol - 1) + " bytes of images, not " + std::to_string(size);
    const char* data = bytes.data() + eol + 1;
    if (header.value("fnv1a64", "") != payloadHash(data, size)) return "its images do not match their hash";
    images.clear();
    for (const auto& shape : shapes) {
      images.push_back(rawImageFrom(shape, data));
      data += rawImageBytes(shape);
    }
  } catch (const nlohmann::json::exception& e) {
    return std::string("a bad header: ") + e.what();
  } catch (const std::invalid_argument& e) {
    return std::string("a bad header: ") + e.what();
  }
  return "";
}

} // namespace

GradeCache::GradeCache(std::string dir) : m_dir(std::move(dir)) {
  if (m_dir.empty()) outputError("--cache needs a folder");
  std::error_code ec;
  fs::create_directories(m_dir, ec);
  if (ec || !fs::is_directory(m_dir, ec))
    outputError("--cache " + m_dir + " cannot be created: " + (ec ? ec.message() : std::string("it exists and is not a folder")));
  // A real write, not access(2): it also catches read-only file systems and root's bypass of modes.
  const std::string probe = (fs::path(m_dir) / (".write-test-" + std::to_string(::getpid()))).string();
  errno = 0;
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) outputError("--cache " + m_dir + " is not writable: " + std::strerror(errno ? errno : EACCES));
  std::fclose(f);
  std::remove(probe.c_str());
}

std::string GradeCache::entryPath(const std::string& key) const { return (fs::path(m_dir) / (key + ".rgc")).string(); }

std::optional<std::vector<Image>> GradeCache::load(const std::string& key, std::size_t count, int width, int height) const {
  const std::string path = entryPath(key);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) {
    logWarn("grade cache entry " + path + " cannot be read; rendering it again");
    return std::nullopt;
  }
  std::vector<Image> images;
  const std::string why = check(bytes, key, count, width, height, images);
  if (why.empty()) return images;
  logWarn("grade cache entry " + path + " is corrupt (" + why + "); rendering it again");
  return std::nullopt;
}

void GradeCache::store(const std::string& key, const std::vector<Image>& images) const {
  std::string payload;
  nlohmann::json shapes = nlohmann::json::array();
  for (const auto& image : images) {
    shapes.push_back(rawImageShape(image));
    appendRawImage(payload, image);
  }
  const nlohmann::json header = {{"format", kFormat}, {"key", key}, {"images", shapes},
                                 {"fnv1a64", payloadHash(payload.data(), payload.size())}};
  try {
    writeTextAtomically(entryPath(key), header.dump() + "\n" + payload);
  } catch (const Error& e) {
    logWarn(std::string("grade cache entry not stored: ") + e.what());
  }
}

} // namespace rtlab

#include "techniques/common/arealight/ltc_table.h"

#include "util/atomic_file.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace rtlab {
namespace {

// The largest table the loader accepts: 1024^2 cells (a 4096 x 4 float texture is 64 MiB already).
constexpr long long kMaxLtcSize = 1024;

[[noreturn]] void ltcInputError(const std::string& path, const std::string& what) {
  throw Error(ExitCode::Input, "LTC table '" + path + "': " + what);
}

std::vector<float> readFloatArray(const nlohmann::json& j, const std::string& path, const char* key,
                                  std::size_t count) {
  const auto it = j.find(key);
  if (it == j.end()) ltcInputError(path, std::string("missing \"") + key + "\"");
  if (!it->is_array() || it->size() != count)
    ltcInputError(path, std::string("\"") + key + "\" must be an array of " + std::to_string(count) + " numbers");
  std::vector<float> out;
  out.reserve(count);
  for (const auto& v : *it) {
    if (!v.is_number()) ltcInputError(path, std::string("\"") + key + "\" holds a non-number " + v.dump());
    const double d = v.get<double>();
    // A double beyond float range would become inf: rejected like any non-finite value.
    if (!std::isfinite(d) || std::abs(d) > double(std::numeric_limits<float>::max()))
      ltcInputError(path, std::string("\"") + key + "\" holds a non-finite value");
    out.push_back(float(d));
  }
  return out;
}

long long readInteger(const nlohmann::json& j, const std::string& path, const char* key, long long min, long long max) {
  const auto it = j.find(key);
  if (it == j.end()) ltcInputError(path, std::string("missing \"") + key + "\"");
  // get<long long>, not get<int>: 4294967298 must not wrap to 2.
  if (!it->is_number_integer() || it->get<long long>() < min || it->get<long long>() > max)
    ltcInputError(path, std::string("\"") + key + "\" must be an integer in " + std::to_string(min) + ".." +
                            std::to_string(max) + " (got " + it->dump() + ")");
  return it->get<long long>();
}

// The shortest decimal that reads back as the same float (std::to_chars' guarantee).
void appendFloat(std::string& out, float v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), v);
  out.append(buffer, result.ptr);
}

void appendArray(std::string& out, const char* key, const std::vector<float>& values) {
  out += ",\n  \"";
  out += key;
  out += "\": [";
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k > 0) out += ',';
    appendFloat(out, values[k]);
  }
  out += ']';
}

} // namespace

double LtcTable::cosThetaAt(int j, int n) {
  const double s = double(j) / double(n - 1);
  return std::max(1.0 - s * s, 1e-4);
}

LtcTable LtcTable::withSize(int n) {
  LtcTable t;
  t.size = n;
  const std::size_t cells = std::size_t(n) * std::size_t(n);
  t.mInv.assign(4 * cells, 0.0f);
  t.magnitude.assign(cells, 0.0f);
  t.fresnel.assign(cells, 0.0f);
  t.diffuseFresnel.assign(std::size_t(n), 0.0f);
  t.sphere.assign(cells, 0.0f);
  t.error.assign(cells, 0.0f);
  return t;
}

std::array<float, 4> LtcTable::mInvAt(int i, int j) const {
  const std::size_t k = 4 * std::size_t(cell(i, j));
  return {mInv[k], mInv[k + 1], mInv[k + 2], mInv[k + 3]};
}

LtcTable LtcTable::load(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) ltcInputError(path, "it is a directory");
  const std::string text = readFileOrThrow(path, "LTC table");
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) ltcInputError(path, "not valid JSON");
  if (!j.is_object()) ltcInputError(path, "must be a JSON object");
  const long long schema = readInteger(j, path, "schema", 0, std::numeric_limits<int>::max());
  if (schema != kSchema)
    ltcInputError(path, "unsupported schema " + std::to_string(schema) + " (expected " + std::to_string(kSchema) + ")");
  const auto brdf = j.find("brdf");
  if (brdf == j.end() || !brdf->is_string() || brdf->get<std::string>() != kBrdf)
    ltcInputError(path, std::string("\"brdf\" must be \"") + kBrdf + "\"");
  LtcTable t;
  t.size = int(readInteger(j, path, "size", 2, kMaxLtcSize));
  t.seed = std::uint64_t(readInteger(j, path, "seed", 0, std::numeric_limits<long long>::max()));
  t.samples = int(readInteger(j, path, "samples", 1, std::numeric_limits<int>::max()));
  t.threads = int(readInteger(j, path, "threads", 1, std::numeric_limits<int>::max()));
  const auto seconds = j.find("fit_seconds");
  if (seconds == j.end() || !seconds->is_number() || !std::isfinite(seconds->get<double>()) || seconds->get<double>() < 0.0)
    ltcInputError(path, "\"fit_seconds\" must be a number >= 0");
  t.fitSeconds = seconds->get<double>();
  const std::size_t n = std::size_t(t.size), cells = n * n;
  t.mInv = readFloatArray(j, path, "m_inv", 4 * cells);
  t.magnitude = readFloatArray(j, path, "magnitude", cells);
  t.fresnel = readFloatArray(j, path, "fresnel", cells);
  t.diffuseFresnel = readFloatArray(j, path, "diffuse_fresnel", n);
  t.sphere = readFloatArray(j, path, "sphere", cells);
  t.error = readFloatArray(j, path, "error", cells);
  return t;
}

void LtcTable::save(const std::string& path) const {
  const std::size_t n = std::size_t(size), cells = n * n;
  if (size < 2 || mInv.size() != 4 * cells || magnitude.size() != cells || fresnel.size() != cells ||
      diffuseFresnel.size() != n || sphere.size() != cells || error.size() != cells)
    throw Error(ExitCode::Internal, "LTC table of size " + std::to_string(size) + " has arrays of the wrong length");
  for (const auto* values : {&mInv, &magnitude, &fresnel, &diffuseFresnel, &sphere, &error})
    for (float v : *values)
      if (!std::isfinite(v)) throw Error(ExitCode::Internal, "LTC table holds a non-finite value; not written");
  // Scalars through nlohmann (escaping, number formats); the arrays one line each, so the file
  // stays readable and diffs stay local.
  const nlohmann::ordered_json header = {{"schema", kSchema}, {"brdf", kBrdf},        {"size", size},
                                         {"seed", seed},      {"samples", samples},   {"fit_seconds", fitSeconds},
                                         {"threads", threads}};
  std::string out = header.dump(2);
  out.pop_back(); // the closing brace
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  appendArray(out, "m_inv", mInv);
  appendArray(out, "magnitude", magnitude);
  appendArray(out, "fresnel", fresnel);
  appendArray(out, "diffuse_fresnel", diffuseFresnel);
  appendArray(out, "sphere", sphere);
  appendArray(out, "error", error);
  out += "\n}\n";
  writeTextAtomically(path, out);
}

} // namespace rtlab

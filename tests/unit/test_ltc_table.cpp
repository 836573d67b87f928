// LtcTable (techniques/common/arealight/ltc_table.h, assets/ltc/README.md): an exact save/load
// round trip, and every missing or malformed file rejected by load with exit 3 and one line naming
// the file and what is wrong.
#include "techniques/common/arealight/ltc_table.h"

#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace fs = std::filesystem;
using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::checkCaught;

namespace {

// A small table whose values exercise the float encoding (tiny, huge, negative, non-terminating).
LtcTable sampleTable() {
  LtcTable t = LtcTable::withSize(3);
  t.seed = 0x123456789abcull;
  t.samples = 64;
  t.threads = 2;
  t.fitSeconds = 1.25;
  float x = 0.1f;
  for (auto* values : {&t.mInv, &t.magnitude, &t.fresnel, &t.diffuseFresnel, &t.sphere, &t.error})
    for (float& v : *values) {
      v = x;
      x = -x * 3.7f + 1e-7f;
      if (std::abs(x) > 1e30f) x = 3.3e-30f;
    }
  return t;
}

std::string writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

// The sample table's JSON with one key replaced (or removed when value is discarded).
std::string editedTable(const fs::path& dir, const std::string& key, const nlohmann::json& value) {
  const std::string good = (dir / "good.json").string();
  sampleTable().save(good);
  std::ifstream in(good);
  nlohmann::json j = nlohmann::json::parse(in);
  if (value.is_discarded()) j.erase(key);
  else j[key] = value;
  // A file per edit: the cases below are all written before any is loaded.
  static int count = 0;
  return writeText(dir / ("edited_" + key + "_" + std::to_string(++count) + ".json"), j.dump());
}

} // namespace

TEST(LtcTable, SaveLoadRoundTripIsExact) {
  const fs::path dir = test::freshTestDir("ltc_table");
  const LtcTable t = sampleTable();
  const std::string path = (dir / "t.json").string();
  t.save(path);
  const LtcTable back = LtcTable::load(path);
  EXPECT_EQ(back.size, t.size);
  EXPECT_EQ(back.seed, t.seed);
  EXPECT_EQ(back.samples, t.samples);
  EXPECT_EQ(back.threads, t.threads);
  EXPECT_DOUBLE_EQ(back.fitSeconds, t.fitSeconds);
  // Bit-identical floats: save writes each as the shortest decimal that reads back as itself.
  EXPECT_EQ(back.mInv, t.mInv);
  EXPECT_EQ(back.magnitude, t.magnitude);
  EXPECT_EQ(back.fresnel, t.fresnel);
  EXPECT_EQ(back.diffuseFresnel, t.diffuseFresnel);
  EXPECT_EQ(back.sphere, t.sphere);
  EXPECT_EQ(back.error, t.error);
  EXPECT_EQ(back.mInvAt(2, 1)[3], t.mInv[4 * (1 * 3 + 2) + 3]);
  // Nothing but the table is left in the folder (the temporary was renamed).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(LtcTable, GridCoordinates) {
  EXPECT_DOUBLE_EQ(LtcTable::roughnessAt(0, 64), 0.0);
  EXPECT_DOUBLE_EQ(LtcTable::roughnessAt(63, 64), 1.0);
  EXPECT_DOUBLE_EQ(LtcTable::cosThetaAt(0, 64), 1.0);
  EXPECT_DOUBLE_EQ(LtcTable::cosThetaAt(21, 64), 1.0 - (21.0 / 63.0) * (21.0 / 63.0));
  EXPECT_DOUBLE_EQ(LtcTable::cosThetaAt(63, 64), 1e-4); // brdf.glsl's n.v clamp, not 0
  EXPECT_DOUBLE_EQ(LtcTable::sphereZAt(0, 64), -1.0);
  EXPECT_DOUBLE_EQ(LtcTable::sphereZAt(63, 64), 1.0);
  EXPECT_DOUBLE_EQ(LtcTable::sphereLengthAt(63, 64), 1.0);
}

TEST(LtcTable, MissingOrUnreadableFileIsAnInputError) {
  const fs::path dir = test::freshTestDir("ltc_table");
  const std::string missing = (dir / "none.json").string();
  checkCaught(catchError([&] { LtcTable::load(missing); }), ExitCode::Input, {missing});
  checkCaught(catchError([&] { LtcTable::load(dir.string()); }), ExitCode::Input, {dir.string(), "directory"});
}

TEST(LtcTable, MalformedFilesAreInputErrorsNamingTheProblem) {
  const fs::path dir = test::freshTestDir("ltc_table");
  const nlohmann::json remove = nlohmann::json(nlohmann::json::value_t::discarded);
  struct Case {
    std::string path, expected;
  };
  const Case cases[] = {
      {writeText(dir / "bad.json", "{\"schema\": 1,"), "not valid JSON"},
      {writeText(dir / "array.json", "[1, 2]"), "must be a JSON object"},
      {editedTable(dir, "schema", 2), "unsupported schema 2"},
      {editedTable(dir, "brdf", "beckmann"), "\"brdf\""},
      {editedTable(dir, "size", 1), "\"size\""},
      {editedTable(dir, "size", 4294967299ll), "\"size\""}, // must not wrap to 3
      {editedTable(dir, "size", 4), "\"m_inv\" must be an array of 64"},
      {editedTable(dir, "magnitude", remove), "missing \"magnitude\""},
      {editedTable(dir, "fresnel", nlohmann::json::array({1, 2})), "\"fresnel\" must be an array of 9"},
      {editedTable(dir, "error", nlohmann::json::array({0, 0, 0, 0, "x", 0, 0, 0, 0})), "non-number"},
      {editedTable(dir, "sphere", nlohmann::json::array({0, 0, 0, 0, 1e39, 0, 0, 0, 0})), "non-finite"},
      {editedTable(dir, "diffuse_fresnel", nlohmann::json::object()), "\"diffuse_fresnel\""},
      {editedTable(dir, "fit_seconds", -1), "\"fit_seconds\""},
      {editedTable(dir, "samples", 0), "\"samples\""},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    const test::Caught caught = catchError([&] { LtcTable::load(c.path); });
    checkCaught(caught, ExitCode::Input, {c.path, c.expected});
    EXPECT_EQ(caught.message.find('\n'), std::string::npos) << "one line";
  }
}

TEST(LtcTable, SaveRefusesAnInconsistentTableAndWritesNothing) {
  const fs::path dir = test::freshTestDir("ltc_table");
  LtcTable t = sampleTable();
  t.error.pop_back();
  const std::string path = (dir / "t.json").string();
  checkCaught(catchError([&] { t.save(path); }), ExitCode::Internal, {"wrong length"});
  t = sampleTable();
  t.magnitude[4] = std::numeric_limits<float>::quiet_NaN();
  checkCaught(catchError([&] { t.save(path); }), ExitCode::Internal, {"non-finite"});
  EXPECT_FALSE(fs::exists(path));
  checkCaught(catchError([&] { sampleTable().save((dir / "no" / "t.json").string()); }), ExitCode::Output, {});
}

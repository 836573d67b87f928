// The grade cache (`rtlab exercise grade --cache DIR`, docs/exercises.md "The grade cache"): the
// solution's image and reference and the stub's image of a view, stored in DIR under a key that
// hashes everything they depend on (app/exercise_grade_cache.h computes it). One file per key:
// a JSON header line (format, key, the images' shapes, the FNV-1a hash of the bytes), then the
// images' raw floats (image/raw_image.h). Files are written under a temporary name and renamed, so
// graders sharing DIR never read a half-written entry; an entry that does not check out (truncated,
// altered, another key's) is reported in one warning line and counts as missing, so it is rendered
// again and overwritten.
#pragma once
#include "image/image.h"

#include <optional>
#include <string>
#include <vector>

namespace rtlab {

class GradeCache {
public:
  // Creates DIR if needed and checks that a file can be written in it: Error(Output) (exit 6),
  // one line naming DIR, when it cannot.
  explicit GradeCache(std::string dir);

  const std::string& dir() const { return m_dir; }
  std::string entryPath(const std::string& key) const;

  // The entry's images, if there is a sound entry for `key` holding `count` images of
  // width x height; std::nullopt when there is none, or (after a warning) when it is corrupt.
  std::optional<std::vector<Image>> load(const std::string& key, std::size_t count, int width, int height) const;
  // Writes the entry atomically. A failure is a warning (the grade does not depend on the cache).
  void store(const std::string& key, const std::vector<Image>& images) const;

private:
  std::string m_dir;
};

} // namespace rtlab

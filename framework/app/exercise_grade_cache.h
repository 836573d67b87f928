// The keys of the grade cache (exercise/grade_cache.h, docs/exercises.md "The grade cache"): a
// hash of everything a cached render depends on. Renders read the rtlab executable and, at run
// time, every file under shaders/ and assets/ of the data folder (includes and tables reach
// across techniques), so all of them are hashed by content: an edited shader or a rebuild misses
// the cache. Then the exercise, its technique and AOV, the backend asked for, the view as the
// worker receives it (all but its name, note and hidden flag), the scene as loaded (a view may
// name a scene file outside the data folder), the GL driver that renders (vendor, renderer and
// version, reported by the workers), and what is stored: the solution with its reference, or the
// stub. The tolerance and the time limit are not in the key: they do not change a render.
#pragma once
#include "exercise/exercise_def.h"

#include <string>

namespace rtlab {

// The part shared by every view of one grade. Hashing costs a read of the executable and of the
// data folder (docs/performance.md "Test suite and CI" gives the time).
std::string gradeCacheBase(const ExerciseDef& def, const std::string& backend);

// The key of one view's entry; `what` is "solution" or "stub".
std::string gradeCacheKey(const std::string& base, const ExerciseDef& def, const ExerciseView& view,
                          const std::string& backend, const std::string& driver, const char* what);

} // namespace rtlab

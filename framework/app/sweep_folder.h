// The rule for planning a sweep into a folder (docs/contract.md, docs/sweeps.md "The folder"): a new
// or empty folder is used as it is; a folder that holds a sweep (nothing but a sweep's own
// entries) is refused unless --force, which removes those entries first; a folder that holds
// anything else is refused, --force or not, so that --force never deletes what is not a sweep's.
#pragma once
#include <string>

namespace rtlab {

// Whether `name`, an entry directly inside a sweep folder, is one a sweep writes: sweep.json,
// jobs.txt, results.csv, report.html, points/, reference/, logs/, or a temporary of one of the
// files (util/atomic_file.h names them "<stem>.tmp-<pid>-<n><ext>").
bool isSweepEntry(const std::string& name);

// Checks DIR before anything is written: Error(Output, exit 6) naming DIR when it is not a
// directory, when it holds a sweep and `force` is false, or when it holds an entry that is not a
// sweep's (naming that entry). With `force`, removes the earlier sweep's entries, so that nothing
// of it (stale points/ included) survives into the new one.
void prepareSweepFolder(const std::string& dir, bool force);

} // namespace rtlab

// Ctrl-C and SIGTERM for rtlab's programs (rtlab, rtlab_ltc_fit): remove the temporary files of
// outputs being written (util/atomic_file.h), so no half-written file is left, print
// "rtlab: error: interrupted" and exit with ExitCode::Interrupted (docs/contract.md "Exit codes").
#pragma once

namespace rtlab {

void installInterruptHandler();

} // namespace rtlab

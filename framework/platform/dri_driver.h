#pragma once

namespace rtlab {

// Keeps every Mesa DRI driver loaded in this process (".../dri/*_dri.so", which Mesa's EGL and GLX
// dlopen when a display is initialised) mapped until the process exits. Call it once a context
// exists. Mesa dlcloses its driver in eglTerminate (and when GLFW closes its X display), but the
// driver's once-per-process state (allocated under pthread_once, pointed to from the driver's own
// globals) outlives the unload: unmapped, that memory is unreachable and LeakSanitizer reports it
// as a leak in an "<unknown module>", which no suppression can name (docs/testing.md,
// "Sanitizers"). Resident, the memory stays reachable, as in any process that exits without
// terminating its display; a later context reuses the mapped driver instead of loading it again.
void keepDriDriversResident();

} // namespace rtlab

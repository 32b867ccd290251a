// Ctrl-C (SIGINT) and SIGTERM as a request to stop long work cleanly.
//
// The first signal only sets a flag (an async-signal-safe store) that long loops poll; they stop
// early and the caller writes what is done. A second signal removes the temporary output file
// being written, if any, and ends the process at once by that signal. A signal that was ignored
// when the process started (a background job of a non-interactive shell, nohup) stays ignored.
#pragma once
#include <atomic>

namespace objektiv {

void InstallInterruptHandlers();
// True once SIGINT or SIGTERM has arrived (after InstallInterruptHandlers).
const std::atomic<bool>& InterruptRequested();
// The first signal received, 0 if none; the conventional exit status is 128 + it.
int InterruptSignal();

}  // namespace objektiv

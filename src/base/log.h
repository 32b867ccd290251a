// Logging through spdlog: one stderr logger, quiet in CI or with --quiet.
#pragma once
#include <spdlog/spdlog.h>

namespace objektiv {

// Verbosity: 0 = warnings and errors only, 1 = info, 2 = debug.
void SetupLogging(int verbosity);
// True when progress bars may be drawn: stderr is a terminal and CI is not set.
bool InteractiveTerminal();

}  // namespace objektiv

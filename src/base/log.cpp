#include "base/log.h"

#include <unistd.h>

#include <cstdlib>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace objektiv {

void SetupLogging(int verbosity) {
  static bool created = false;
  if (!created) {
    auto logger = spdlog::stderr_color_mt("objektiv");
    logger->set_pattern("%^[%l]%$ %v");
    spdlog::set_default_logger(logger);
    created = true;
  }
  spdlog::set_level(verbosity <= 0 ? spdlog::level::warn : verbosity == 1 ? spdlog::level::info : spdlog::level::debug);
}

bool InteractiveTerminal() {
  const char* ci = std::getenv("CI");
  if (ci && *ci && std::string(ci) != "0" && std::string(ci) != "false") return false;
  return isatty(STDERR_FILENO) != 0;
}

}  // namespace objektiv

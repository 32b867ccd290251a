// Errors in user input: carry "file:line: message", reported by the app with exit code 1.
#pragma once
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace objektiv {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

// "file:line: message" (line omitted when 0).
template <typename... Args>
InputError MakeInputError(const std::string& file, int line, fmt::format_string<Args...> f, Args&&... args) {
  std::string msg = fmt::format(f, std::forward<Args>(args)...);
  if (line > 0) return InputError(fmt::format("{}:{}: {}", file, line, msg));
  if (!file.empty()) return InputError(fmt::format("{}: {}", file, msg));
  return InputError(msg);
}

}  // namespace objektiv

// The subcommands of the `objektiv` command line.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>

namespace objektiv {

// Each Add* registers a subcommand and returns the action to run when it was chosen;
// the action returns the process exit code.
std::function<int()> AddRenderCommand(CLI::App& app);
std::function<int()> AddImgtoolCommand(CLI::App& app);
std::function<int()> AddLensCommand(CLI::App& app);
std::function<int()> AddMergeCommand(CLI::App& app);
std::function<int()> AddViewCommand(CLI::App& app);

}  // namespace objektiv

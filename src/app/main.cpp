// objektiv: renders scenes through real camera lenses. See README.md for the commands.
#include <cstdio>

#include "app/commands.h"
#include "base/error.h"
#include "base/log.h"

int main(int argc, char** argv) {
  using namespace objektiv;
  CLI::App app{"Objektiv: a spectral renderer whose camera is a real lens"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "objektiv " OBJEKTIV_VERSION);
  auto render = AddRenderCommand(app);
  auto imgtool = AddImgtoolCommand(app);
  auto lens = AddLensCommand(app);
  auto merge = AddMergeCommand(app);
  auto view = AddViewCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad command-line values
  }
  SetupLogging(1);
  try {
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("imgtool")) return imgtool();
    if (app.got_subcommand("lens")) return lens();
    if (app.got_subcommand("merge")) return merge();
    if (app.got_subcommand("view")) return view();
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 2;
}

#include "base/interrupt.h"

#include <unistd.h>

#include <csignal>

#include "base/output_file.h"

namespace objektiv {

namespace {
std::atomic<bool> requested{false};
std::atomic<int> first_signal{0};

void OnSignal(int sig) {
  int expected = 0;
  if (first_signal.compare_exchange_strong(expected, sig)) {
    requested.store(true);
    static const char msg[] =
        "\ninterrupted: finishing the pixels in progress, then writing what is done (Ctrl-C again aborts at once)\n";
    ssize_t ignored = write(STDERR_FILENO, msg, sizeof(msg) - 1);
    (void)ignored;
    return;
  }
  RemovePendingTemporaryFile();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void Install(int sig) {
  struct sigaction old {};
  sigaction(sig, nullptr, &old);
  if (old.sa_handler == SIG_IGN) return;
  struct sigaction sa {};
  sa.sa_handler = OnSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(sig, &sa, nullptr);
}
}  // namespace

void InstallInterruptHandlers() {
  Install(SIGINT);
  Install(SIGTERM);
}

const std::atomic<bool>& InterruptRequested() { return requested; }

int InterruptSignal() { return first_signal.load(); }

}  // namespace objektiv

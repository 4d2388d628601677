#include "mpi_driver/parallel/signals.hpp"

#include <csignal>

namespace blockfrag {
namespace {

volatile std::sig_atomic_t requested_signal = 0;

extern "C" void record_interrupt(int signal_number) { requested_signal = signal_number; }

}  // namespace

void install_interrupt_handlers() {
  requested_signal = 0;
  struct sigaction action {};
  action.sa_handler = record_interrupt;
  sigemptyset(&action.sa_mask);
  // No SA_RESTART: a blocking call returns early, so the stop is noticed without delay.
  action.sa_flags = 0;
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGUSR1, &action, nullptr);
}

bool interrupt_requested() { return requested_signal != 0; }

int interrupt_signal() { return requested_signal; }

}  // namespace blockfrag

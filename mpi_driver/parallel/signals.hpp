// SIGTERM (Slurm's time limit, scancel, mpirun forwarding it) and SIGINT (Ctrl-C) ask a study to
// stop at the next sample boundary, write its checkpoint and exit; the handler only sets a flag.
#pragma once

namespace blockfrag {

// Installs the handlers (idempotent) and clears any earlier request.
void install_interrupt_handlers();

bool interrupt_requested();

// The signal that asked for the stop (0 when none), for the message.
int interrupt_signal();

}  // namespace blockfrag

// SIGTERM (Slurm's time limit, scancel), SIGINT (Ctrl-C) and SIGUSR1 ask a study to stop at the
// next sample boundary, write its checkpoint and exit; the handler only sets a flag. SIGUSR1 is
// for mpirun: Open MPI's mpirun forwards it to the ranks and then returns their exit code (4),
// where after a SIGTERM or SIGINT of its own it returns 1 whatever the ranks return.
#pragma once

namespace blockfrag {

// Installs the handlers (idempotent) and clears any earlier request.
void install_interrupt_handlers();

bool interrupt_requested();

// The signal that asked for the stop (0 when none), for the message.
int interrupt_signal();

}  // namespace blockfrag

// Ctrl-C and SIGTERM during a long command: the first asks it to stop at the next frame or step,
// so that it can remove what it half wrote and say how far it got; another one within 2 s is the
// same request (`timeout` sends two), one after that kills as usual.
#pragma once

namespace tumble::sys {

// Catches SIGINT and SIGTERM for a command that checks interrupt_signal() as it goes.
void install_interrupt_handlers();

// The signal that asked to stop (SIGINT or SIGTERM), or 0.
int interrupt_signal();

// "SIGINT", "SIGTERM", or "a signal" for any other.
const char* signal_name(int signal);

}  // namespace tumble::sys

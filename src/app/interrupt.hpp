// Ctrl-C and SIGTERM during a long command: the first asks it to stop at the next frame or step,
// so that it can remove what it half wrote and say how far it got; a second one kills as usual.
#pragma once

namespace tumble::app {

// Ignores SIGXFSZ and SIGPIPE, so that a file-size limit (ulimit -f) or a closed pipe (`tumble
// render ... 2>&1 | head -1`) fails a write with an error tumble reports, as a full disk does,
// instead of killing it half way through a render. For every command, at start.
void ignore_write_signals();

// Catches SIGINT and SIGTERM for a command that checks interrupt_signal() as it goes.
void install_interrupt_handlers();

// The signal that asked to stop (SIGINT or SIGTERM), or 0.
int interrupt_signal();

// "SIGINT", "SIGTERM", or "a signal" for any other.
const char* signal_name(int signal);

}  // namespace tumble::app

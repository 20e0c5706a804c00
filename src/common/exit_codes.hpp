// Exit codes shared by every command.
#pragma once

namespace tumble {

// kExitMismatch: the command ran but its check failed (e.g. `tumble diff` found differences).
// kExitBadInput: bad usage, a bad scene or image, or a failure to write the output.
// kExitInterrupted + N: stopped cleanly by signal N (130 for SIGINT, 143 for SIGTERM), as a
// shell reports a program killed by it.
enum ExitCode : int { kExitOk = 0, kExitMismatch = 1, kExitBadInput = 2, kExitInterrupted = 128 };

// The exit code of a command stopped cleanly by signal N.
inline ExitCode interrupted_by(int signal) {
  return static_cast<ExitCode>(kExitInterrupted + signal);
}

}  // namespace tumble

// Exit codes shared by every command.
#pragma once

namespace tumble::app {

// kExitMismatch: the command ran but its check failed (e.g. `tumble diff` found differences).
enum ExitCode : int { kExitOk = 0, kExitMismatch = 1, kExitBadInput = 2 };

}  // namespace tumble::app

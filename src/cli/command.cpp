#include "cli/command.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace tumble::cli {

CommandResult run_parsed(const Commands& commands) {
  for (const Command& command : commands) {
    if (!command.app->parsed()) continue;
    const CommandResult code = command.run();
    // A command that failed has said why (or will, through main) already.
    const bool flushed = std::fflush(stdout) == 0;
    const int reason = errno;
    if (code && (!flushed || std::ferror(stdout)) && (*code == kExitOk || *code == kExitMismatch)) {
      return Error{std::string("error writing to standard output") +
                   (flushed ? "" : std::string(": ") + std::strerror(reason))};
    }
    return code;
  }
  return kExitBadInput;
}

}  // namespace tumble::cli

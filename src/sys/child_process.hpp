// Another program run by tumble, its standard output read line by line as it comes (`tumble bench
// contact` runs contact_bench for Bullet's column this way, so that tumble never links Bullet).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"

namespace tumble::sys {

// Runs the executable at `program` (a path; PATH is not searched) with `arguments`, and hands
// each line of its standard output, without the '\n', to `on_line` as it arrives. Its standard
// input and error are tumble's. When `on_line` returns false the program is stopped (SIGTERM)
// and waited for; the caller knows why.
//
// Succeeds when the program ran and exited with status 0; else the error says why not, naming
// `program`.
Result<void> run_reading_lines(const std::string& program,
                               const std::vector<std::string>& arguments,
                               const std::function<bool(std::string_view line)>& on_line);

// A program to run and its arguments (argv[1..]).
struct ProgramRun {
  std::string program;  // a path; PATH is not searched
  std::vector<std::string> arguments;
};

// Runs every program at once, each with tumble's standard streams, and waits for them all
// (`tumble render --jobs N` runs its chunks this way). Looks at `stop_requested` every 50 ms:
// once it is true, or once one program has failed, each program still running gets SIGTERM.
// Calls `on_done(i)` as program i exits with status 0.
//
// Succeeds when every program exited with status 0; else the error of the first that failed,
// naming it.
Result<void> run_together(const std::vector<ProgramRun>& runs,
                          const std::function<bool()>& stop_requested,
                          const std::function<void(std::size_t index)>& on_done);

}  // namespace tumble::sys

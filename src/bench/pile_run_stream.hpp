// A PileRun as lines of text, written as the run goes: how `contact_bench --stream` hands its
// Bullet column to `tumble bench contact`, which may not link Bullet and so runs it as a child
// process. One line per step lets the reader show progress while the peer runs.
//
//   tumble-pile-run 1
//   engine bullet 3.24 float64
//   pile <the pile's summary, pile.hpp>
//   step <ms> <cpu ms> <contacts> <depth m> <top speed m/s>      (one per step, in order)
//   escaped <boxes out of the bin>
//   largest_penetration_m <m>
//   largest_final_speed <m/s>
//   position <x> <y> <z>                                          (one per box, world frame, m)
//   end
//
// Numbers are printed with 17 significant digits, so a run read back has the bits it was
// written with.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"
#include "common/result.hpp"

namespace tumble::bench {

// The writer's three parts: before the first step, after each step (the last step in `so_far`),
// and after the last. Each returns false when writing failed (a reader that went away).
bool write_run_start(std::FILE* out, const std::string& engine, const Pile& pile);
bool write_run_step(std::FILE* out, const PileRun& so_far);
bool write_run_end(std::FILE* out, const PileRun& run);

// Reads the lines back one at a time and checks them against the pile the reader expects (the
// same summary, pile.steps steps and one position per box), so that a peer built from other
// sources, or one that stopped half way, is an error and not a column of wrong figures.
class PileRunReader {
 public:
  explicit PileRunReader(const Pile& pile) : pile_(pile) {}

  // Takes one line without its '\n': an error saying why ("line N: ...") when the line is not
  // what the format allows next; every later call is then that error too.
  Result<void> read(std::string_view line);
  // Whether the "end" line has been read, after all the rest, without an error.
  bool complete() const { return part_ == Part::done && error_.empty(); }
  const PileRun& run() const { return run_; }  // what has been read so far

 private:
  // Where in the format the next line belongs.
  enum class Part {
    header,
    engine,
    pile,
    steps,
    escaped,
    penetration,
    final_speed,
    positions,
    done
  };

  bool take(std::string_view line);
  bool fail(const std::string& why);
  bool read_step(std::string_view values);
  bool read_position(std::string_view values);

  const Pile& pile_;
  Part part_ = Part::header;
  PileRun run_;
  std::string error_;
  int line_number_ = 0;
};

}  // namespace tumble::bench

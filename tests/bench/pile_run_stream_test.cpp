// The lines by which contact_bench hands a run to `tumble bench contact`: read back, a run has
// the bits it was written with; a run of another pile, a short run or a garbled line is an error.
#include "bench/pile_run_stream.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/tumble_pile.hpp"

namespace tumble::bench {
namespace {

// What `write` printed, line by line.
std::vector<std::string> lines_written(const std::function<void(std::FILE*)>& write) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&buffer, &size);
  write(memory);
  std::fclose(memory);
  std::vector<std::string> lines;
  std::istringstream in(std::string(buffer, size));
  std::free(buffer);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A run written as contact_bench --stream writes it: the start, each step as it is done, the end.
std::vector<std::string> stream_of(const PileRun& run, const Pile& pile) {
  return lines_written([&](std::FILE* out) {
    EXPECT_TRUE(write_run_start(out, run.engine, pile));
    PileRun so_far;
    for (std::size_t n = 0; n < run.step_ms.size(); ++n) {
      so_far.step_ms.push_back(run.step_ms[n]);
      so_far.step_cpu_ms.push_back(run.step_cpu_ms[n]);
      so_far.contacts.push_back(run.contacts[n]);
      so_far.depth_m.push_back(run.depth_m[n]);
      so_far.top_speed.push_back(run.top_speed[n]);
      EXPECT_TRUE(write_run_step(out, so_far));
    }
    EXPECT_TRUE(write_run_end(out, run));
  });
}

// Feeds every line to a reader of `pile`; the reader as it is after the last or the first bad one.
struct ReadBack {
  bool all_read = true;
  bool complete = false;
  std::string error;
  PileRun run;
};
ReadBack read_back(const std::vector<std::string>& lines, const Pile& pile) {
  PileRunReader reader(pile);
  ReadBack out;
  for (const std::string& line : lines) {
    if (const Result<void> read = reader.read(line); !read) {
      out.all_read = false;
      out.error = read.error();
      break;
    }
  }
  out.complete = reader.complete();
  out.run = reader.run();
  return out;
}

// Three steps (0.05 s) of two boxes, with figures whose shortest decimal forms are long.
PileRun awkward_run(const Pile& pile) {
  PileRun run;
  run.engine = "bullet 3.24 float64";
  run.step_ms = {0.1 + 0.2, 1e-300, 12.5};
  run.step_cpu_ms = {1.0 / 3.0, 0.0, 5e-324};
  run.contacts = {0, 7, 2147483647};
  run.depth_m = {0.0, 0.15092842, 2.0 / 7.0};
  run.top_speed = {29.000000000000004, 1.7, 0.086};
  run.largest_penetration_m = 2.0 / 7.0;
  run.escaped = 1;
  run.largest_final_speed = 0.086;
  run.final_positions = {{1.0 / 3.0, -0.0, 44.1}, {3.0000000000000004, 0.1, -2.5}};
  EXPECT_EQ(pile.steps, 3);
  EXPECT_EQ(pile.boxes.size(), 2u);
  return run;
}

void expect_same_bits(const PileRun& read, const PileRun& written) {
  EXPECT_EQ(read.engine, written.engine);
  EXPECT_EQ(read.step_ms, written.step_ms);
  EXPECT_EQ(read.step_cpu_ms, written.step_cpu_ms);
  EXPECT_EQ(read.contacts, written.contacts);
  EXPECT_EQ(read.depth_m, written.depth_m);
  EXPECT_EQ(read.top_speed, written.top_speed);
  EXPECT_EQ(read.largest_penetration_m, written.largest_penetration_m);
  EXPECT_EQ(read.escaped, written.escaped);
  EXPECT_EQ(read.largest_final_speed, written.largest_final_speed);
  ASSERT_EQ(read.final_positions.size(), written.final_positions.size());
  for (std::size_t i = 0; i < read.final_positions.size(); ++i) {
    EXPECT_EQ(read.final_positions[i], written.final_positions[i]) << "box " << i;
  }
}

TEST(PileRunStream, ARunReadBackHasTheBitsItWasWrittenWith) {
  const Pile pile = make_pile(2, 7, 0.05);
  const PileRun written = awkward_run(pile);
  const std::vector<std::string> lines = stream_of(written, pile);
  ASSERT_EQ(lines.size(), 3 + 3 + 3 + 2 + 1u);
  EXPECT_EQ(lines[0], "tumble-pile-run 1");
  EXPECT_EQ(lines[3], "step 0.30000000000000004 0.33333333333333331 0 0 29.000000000000004");
  const ReadBack read = read_back(lines, pile);
  EXPECT_TRUE(read.all_read) << read.error;
  EXPECT_TRUE(read.complete);
  expect_same_bits(read.run, written);
}

TEST(PileRunStream, TumblesOwnRunReadsBackWhole) {
  const Pile pile = make_pile(12, 3, 0.5);
  const PileRun written = run_pile_in_tumble(pile);
  const ReadBack read = read_back(stream_of(written, pile), pile);
  EXPECT_TRUE(read.complete) << read.error;
  expect_same_bits(read.run, written);
  EXPECT_EQ(read.run.step_ms.size(), 30u);
}

TEST(PileRunStream, ARunOfAnotherPileIsAnError) {
  const Pile pile = make_pile(2, 7, 0.05);
  const ReadBack read = read_back(stream_of(awkward_run(pile), pile), make_pile(2, 8, 0.05));
  EXPECT_FALSE(read.all_read);
  EXPECT_FALSE(read.complete);
  EXPECT_NE(read.error.find("line 3: the peer ran another pile: \"2 boxes (seed 7)"),
            std::string::npos)
      << read.error;
}

TEST(PileRunStream, AStepTooFewIsAnError) {
  const Pile pile = make_pile(2, 7, 0.05);
  std::vector<std::string> lines = stream_of(awkward_run(pile), pile);
  lines.erase(lines.begin() + 5);  // the third step
  const ReadBack read = read_back(lines, pile);
  EXPECT_FALSE(read.complete);
  EXPECT_EQ(read.error, "line 6: 2 steps, not the pile's 3");
}

TEST(PileRunStream, AMissingPositionIsAnError) {
  const Pile pile = make_pile(2, 7, 0.05);
  std::vector<std::string> lines = stream_of(awkward_run(pile), pile);
  lines.erase(lines.end() - 2);  // the second box's position
  const ReadBack read = read_back(lines, pile);
  EXPECT_FALSE(read.complete);
  EXPECT_EQ(read.error, "line 11: 1 positions, not one for each of the pile's 2 boxes");
}

// A peer that stopped (killed, or crashed) part way wrote no "end": not complete, and no line
// was wrong, so the caller says that the stream ended early.
TEST(PileRunStream, AStreamCutShortIsIncompleteWithoutAnError) {
  const Pile pile = make_pile(2, 7, 0.05);
  std::vector<std::string> lines = stream_of(awkward_run(pile), pile);
  lines.resize(4);
  const ReadBack read = read_back(lines, pile);
  EXPECT_TRUE(read.all_read);
  EXPECT_FALSE(read.complete);
  EXPECT_EQ(read.error, "");
  EXPECT_EQ(read.run.step_ms.size(), 1u);
}

TEST(PileRunStream, AGarbledLineIsAnErrorNamingIt) {
  const Pile pile = make_pile(2, 7, 0.05);
  std::vector<std::string> lines = stream_of(awkward_run(pile), pile);
  lines[4] = "step 1.0 2.0 three 0 0";
  const ReadBack read = read_back(lines, pile);
  EXPECT_FALSE(read.all_read);
  EXPECT_EQ(read.error, "line 5: not a step's numbers: 1.0 2.0 three 0 0");
  lines[0] = "Segmentation fault";
  EXPECT_EQ(read_back(lines, pile).error,
            "line 1: expected \"tumble-pile-run 1\", got \"Segmentation fault\"");
}

TEST(PileRunStream, NothingMayFollowTheEnd) {
  const Pile pile = make_pile(2, 7, 0.05);
  std::vector<std::string> lines = stream_of(awkward_run(pile), pile);
  lines.push_back("step 1 1 1 1 1");
  const ReadBack read = read_back(lines, pile);
  EXPECT_FALSE(read.complete);
  EXPECT_EQ(read.error, "line 13: more after \"end\"");
}

}  // namespace
}  // namespace tumble::bench

// The table that `contact_bench` and `tumble bench contact` both print.
#include "bench/pile_table.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace tumble::bench {
namespace {

std::string table_of(const std::vector<PileRun>& runs, double dt) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&buffer, &size);
  print_pile_table(memory, runs, dt);
  std::fclose(memory);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

PileRun run_named(const std::string& engine, double ms) {
  PileRun run;
  run.engine = engine;
  run.step_ms = {ms, ms, 9.0 * ms};
  run.step_cpu_ms = {ms, ms, ms};
  run.contacts = {4, 8, 8};
  run.depth_m = {0.0, 0.25, 0.125};
  run.top_speed = {3.0, 2.0, 1.0};
  run.largest_penetration_m = 0.25;
  run.escaped = 2;
  run.largest_final_speed = 1.0;
  return run;
}

TEST(PileTable, OneColumnPerEngineAndTheRatiosOfTwo) {
  const std::string table = table_of({run_named("tumble", 2.0), run_named("bullet", 4.0)}, 0.5);
  EXPECT_NE(table.find("  tumble                bullet"), std::string::npos) << table;
  // The mean counts the costly third step in full: (2 + 2 + 18) / 3 ms.
  EXPECT_NE(table.find("mean ms/step (whole run)        7.33                  14.67"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("median ms/step                  2.00                  4.00"),
            std::string::npos)
      << table;
  // The peak (8 points) is first at the second step, t = 1 s; the steps at it take ms and 9 ms.
  EXPECT_NE(table.find("ms/step at peak contacts        10.00                 20.00"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("peak at t (s)                   1.00"), std::string::npos) << table;
  EXPECT_NE(table.find("boxes out of the bin            2                     2"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("tumble / bullet, mean ms/step: 0.50 (cpu 0.50); median ms/step: 0.50 (cpu "
                       "0.50), at peak contacts: 0.50\n"),
            std::string::npos)
      << table;
}

TEST(PileTable, OneEngineHasNoRatio) {
  const std::string table = table_of({run_named("tumble", 2.0)}, 0.5);
  EXPECT_NE(table.find("median ms/step                  2.00"), std::string::npos) << table;
  EXPECT_EQ(table.find("tumble / bullet"), std::string::npos) << table;
}

}  // namespace
}  // namespace tumble::bench

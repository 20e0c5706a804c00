// The figures `contact_bench` reports from a run, on runs whose answers are known.
#include "bench/pile_run.hpp"

#include <gtest/gtest.h>

namespace tumble::bench {
namespace {

TEST(PileRun, MedianOfAnOddAndAnEvenCount) {
  PileRun run;
  EXPECT_EQ(median_step_ms(run), 0.0);
  run.step_ms = {5.0, 1.0, 3.0};
  EXPECT_EQ(median_step_ms(run), 3.0);
  run.step_ms = {4.0, 1.0, 3.0, 2.0};
  EXPECT_EQ(median_step_ms(run), 2.5);
  run.step_cpu_ms = {0.5, 0.25, 9.0};
  EXPECT_EQ(median_step_cpu_ms(run), 0.5);
}

TEST(PileRun, PeakContactsIsTheFirstStepWithTheMost) {
  PileRun run;
  EXPECT_EQ(peak_contact_step(run), 0u);
  EXPECT_EQ(ms_at_peak_contacts(run), 0.0);
  run.contacts = {0, 7, 9, 9, 4};
  run.step_ms = {1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_EQ(peak_contact_step(run), 2u);
  EXPECT_EQ(ms_at_peak_contacts(run), 3.0);
}

}  // namespace
}  // namespace tumble::bench

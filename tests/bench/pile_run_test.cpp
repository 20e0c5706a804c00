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

TEST(PileRun, MeanIsTheWholeRunsTimeOverItsSteps) {
  PileRun run;
  EXPECT_EQ(mean_step_ms(run), 0.0);
  run.step_ms = {1.0, 1.0, 10.0};  // a pour's costly step counts in full
  EXPECT_EQ(mean_step_ms(run), 4.0);
  run.step_cpu_ms = {0.5, 0.5, 2.0};
  EXPECT_EQ(mean_step_cpu_ms(run), 1.0);
}

TEST(PileRun, PeakContactsIsTheFirstStepWithTheMost) {
  PileRun run;
  EXPECT_EQ(peak_contact_step(run), 0u);
  EXPECT_EQ(ms_at_peak_contacts(run), 0.0);
  run.contacts = {0, 7, 9, 9, 4};
  run.step_ms = {1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_EQ(peak_contact_step(run), 2u);
  EXPECT_EQ(peak_contact_time(run, 0.5), 1.5);  // s: the end of the third step
  EXPECT_EQ(ms_at_peak_contacts(run), 3.5);     // the two steps of 9
}

// 96 and 95 are within 5% of 100, 94 is not: the median of 7, 8 and 30 ms.
TEST(PileRun, MsAtPeakIsTheMedianOfTheStepsNearThePeak) {
  PileRun run;
  run.contacts = {10, 94, 95, 100, 96};
  run.step_ms = {1.0, 2.0, 7.0, 30.0, 8.0};
  EXPECT_EQ(ms_at_peak_contacts(run), 8.0);
}

}  // namespace
}  // namespace tumble::bench

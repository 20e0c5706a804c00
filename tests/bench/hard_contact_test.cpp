// The hard contact cases of issue "Contact III" that the solver holds, each to the bound
// (src/bench/hard_contact.cpp says how each is set up and measured; bench/contact_hard prints
// every case, held or not).
#include "bench/hard_contact.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tumble::bench {
namespace {

void expect_holds(const std::string& name) {
  const HardContactCase result = run_hard_contact_case(name);
  ASSERT_FALSE(result.figures.empty()) << name;
  for (const HardContactFigure& figure : result.figures) {
    EXPECT_LE(figure.value, figure.bound) << name << ": " << figure.measure;
  }
}

// Uniform pressure over the face: a cube at 50 rad/s, μ = 0.5, stops at 4.44 s ± 2 %
// (t = I ω / (μ m g r̄), r̄ = 0.3826 × side), and its centre moves less than 1 mm.
TEST(HardContact, ASpinningCubeStopsWhenUniformPressureOverItsFaceSays) {
  expect_holds("twist");
}

// A 1 kg cube on the floor pushed down by 1e4, 1e5 and 1e6 N stays at y = 0.5 m within 1 mm at
// every step (its free step alone falls 1.4 to 139 m through the floor).
TEST(HardContact, ACubeUnderAHeavyLoadStaysOnTheFloor) {
  for (const char* name : {"load_1e+03", "load_1e+04", "load_1e+05", "load_1e+06"}) {
    expect_holds(name);
  }
}

TEST(HardContact, EveryCaseHasAFigure) {
  for (const std::string& name : hard_contact_case_names()) {
    EXPECT_FALSE(run_hard_contact_case(name).figures.empty()) << name;
  }
  EXPECT_TRUE(run_hard_contact_case("no such case").figures.empty());
}

}  // namespace
}  // namespace tumble::bench

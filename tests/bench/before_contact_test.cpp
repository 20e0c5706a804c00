// The world step with no planes must run exactly the code that ran before contact existed: every
// hard case, with every integrator, through sim::Simulation, gives the bytes recorded then
// (tests/data/before_contact/hard_cases.csv, written by this test with
// TUMBLE_WRITE_BEFORE_CONTACT=1 on the last commit before contact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/hard_cases.hpp"
#include "sim/simulation.hpp"

namespace tumble::bench {
namespace {

constexpr double kStep = 1.0 / 60.0;  // s
constexpr double kLongest = 20.0;     // s of each case (the long ones are cut short)
constexpr int kStepsPerRow = 60;

std::string run_every_case() {
  std::string out = "case,integrator,t,x,y,z,qw,qx,qy,qz,px,py,pz,Lx,Ly,Lz\n";
  for (const HardCase& c : hard_cases()) {
    for (const physics::Integrator integrator : physics::kAllIntegrators) {
      sim::Simulation simulation({c.model}, {c.initial}, integrator, kStep);
      const auto steps = static_cast<std::int64_t>(std::min(c.duration, kLongest) / kStep);
      while (simulation.step_count() < steps && !simulation.blow_up()) {
        simulation.step();
        if (simulation.step_count() % kStepsPerRow != 0) continue;
        const physics::BodyState& s = simulation.current().front();
        char row[1024];
        std::snprintf(row, sizeof row,
                      "%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                      "%.17g,%.17g,%.17g\n",
                      c.name.c_str(), std::string(physics::integrator_name(integrator)).c_str(),
                      simulation.time(), s.position().x(), s.position().y(), s.position().z(),
                      s.orientation().w(), s.orientation().x(), s.orientation().y(),
                      s.orientation().z(), s.momentum().x(), s.momentum().y(), s.momentum().z(),
                      s.angular_momentum().x(), s.angular_momentum().y(), s.angular_momentum().z());
        out += row;
      }
    }
  }
  return out;
}

TEST(BeforeContact, HardCasesThroughTheWorldStepGiveTheRecordedBytes) {
  const std::string path =
      std::string(TUMBLE_SOURCE_DIR) + "/tests/data/before_contact/hard_cases.csv";
  const std::string now = run_every_case();
  if (std::getenv("TUMBLE_WRITE_BEFORE_CONTACT")) {
    std::ofstream(path, std::ios::binary) << now;
    GTEST_SKIP() << "wrote " << path;
  }
  std::ifstream file(path, std::ios::binary);
  ASSERT_TRUE(file) << "cannot read " << path;
  std::stringstream recorded;
  recorded << file.rdbuf();
  // Compared line by line so that a failure names the first row that changed.
  std::istringstream a(recorded.str()), b(now);
  std::string expected_line, actual_line;
  int line = 0;
  while (std::getline(a, expected_line)) {
    ++line;
    ASSERT_TRUE(std::getline(b, actual_line)) << "ends early at line " << line;
    ASSERT_EQ(actual_line, expected_line) << "line " << line;
  }
  EXPECT_FALSE(std::getline(b, actual_line)) << "longer than recorded";
}

}  // namespace
}  // namespace tumble::bench

// End-to-end tests of `tumble bench accuracy`, run as a separate process the way users run it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/accuracy.hpp"
#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;

using tumble::testing::Outcome;
using tumble::testing::read_file;

class BenchAccuracyCommand : public tumble::testing::CommandTest {};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Each hard case once, each contact case with both contact methods, each joint case once.
std::size_t quick_row_count() {
  const tumble::bench::AccuracySettings quick = tumble::bench::quick_accuracy_settings();
  return (quick.cases.size() + 2 * quick.contact_cases.size() + quick.joint_cases.size()) *
         std::size(tumble::physics::kAllIntegrators) * quick.steps.size();
}

TEST_F(BenchAccuracyCommand, QuickWritesTheCsvTheMarkdownAndTheChart) {
  const Outcome run = tumble("bench accuracy --quick --out " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> csv = lines_of(read_file(dir_ / "out" / "accuracy.csv"));
  ASSERT_FALSE(csv.empty());
  EXPECT_EQ(csv[0],
            "case,contact,integrator,dt,steps,blew_up,measure,error,second_measure,second_error,"
            "orientation_error_rad,position_error_m,angular_momentum_error,energy_error,"
            "ns_per_step,ns_per_simulated_second");
  EXPECT_EQ(csv.size(), 1 + quick_row_count());
  // Explicit Euler at k dt = 10 on the stiff decay: blown up, and said so. Penalty contact at
  // 1/30 (ω_n dt = 26 rocking) likewise; its rows leave the final-state errors empty.
  const auto has_line_starting = [&](const std::string& start) {
    for (const std::string& line : csv) {
      if (line.rfind(start, 0) == 0) return true;
    }
    return false;
  };
  EXPECT_TRUE(has_line_starting(
      "stiff_linear_damping,none,euler,0.033333333333333333,30,1,position_error_m,nan,,,nan,nan"))
      << read_file(dir_ / "out" / "accuracy.csv");
  EXPECT_TRUE(
      has_line_starting("bounce,penalty,rk4,0.033333333333333333,30,1,apex_error_m,nan,,,,,,,"))
      << read_file(dir_ / "out" / "accuracy.csv");
  EXPECT_TRUE(has_line_starting("rest,impulse,rk4,0.016666666666666666,360,0,penetration_m,"))
      << read_file(dir_ / "out" / "accuracy.csv");

  const std::string markdown = read_file(dir_ / "out" / "accuracy.md");
  EXPECT_NE(markdown.find("# Speed against error"), std::string::npos);
  EXPECT_NE(markdown.find("## article_cube"), std::string::npos);
  EXPECT_NE(markdown.find("| rk4 | 1/60 |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("blew up"), std::string::npos);
  EXPECT_NE(markdown.find("## bounce"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| contact | integrator | dt (s) | apex error (m) |"), std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| penalty | rk4 | 1/30 | blew up |"), std::string::npos) << markdown;

  const std::string png = read_file(dir_ / "out" / "accuracy.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_TRUE(fs::exists(dir_ / "out" / "accuracy.gp"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "accuracy.dat"));
  for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
  }
  EXPECT_NE(run.err.find("tumble: bench accuracy: [1/"), std::string::npos) << run.err;
}

// Sets an environment variable for one test's lifetime.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST_F(BenchAccuracyCommand, WithoutGnuplotSaysSoAndStillWritesTheTables) {
  fs::create_directories(dir_ / "empty_path");
  const ScopedEnvironment no_gnuplot("PATH", path("empty_path"));
  const Outcome run = tumble("bench accuracy --quick --out " + path("out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("gnuplot not found"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("gnuplot-nox"), std::string::npos) << run.err;
  EXPECT_EQ(lines_of(read_file(dir_ / "out" / "accuracy.csv")).size(), 1 + quick_row_count());
  EXPECT_TRUE(fs::exists(dir_ / "out" / "accuracy.md"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "accuracy.png"));
}

TEST_F(BenchAccuracyCommand, NeedsASubcommand) {
  const Outcome run = tumble("bench");
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace

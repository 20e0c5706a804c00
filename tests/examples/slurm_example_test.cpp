// examples/slurm/submit.sh run against a real single-host Slurm cluster that the test starts
// (munged, slurmctld, slurmd as its child processes): the array of chunks, the dependent join and
// the cleanup, the joined render checked against a whole render of the same scene.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "examples/chunked_render.hpp"
#include "examples/slurm_cluster.hpp"
#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::shell_quoted;
using tumble::testing::SlurmCluster;

// How long the jobs may take, queueing included: 10 to 20 s here (3 tasks, a join, a cleanup).
constexpr double kJobsBound = 120;  // s

class SlurmExample : public tumble::testing::CommandTest {
 protected:
  // One cluster for the suite: starting it takes a few seconds.
  static void SetUpTestSuite() {
    missing_ = SlurmCluster::missing_programs();
    if (!missing_.empty()) {
      return;
    }
    folder_ = fs::path(::testing::TempDir()) / ("tumble_slurm_" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    cluster_ = std::make_unique<SlurmCluster>();
    start_error_ = cluster_->start(folder_);
  }
  static void TearDownTestSuite() {
    cluster_.reset();
    if (!folder_.empty()) {
      fs::remove_all(folder_);
    }
  }

  void SetUp() override {
    CommandTest::SetUp();
    if (!missing_.empty()) {
      GTEST_SKIP() << "not installed: " << missing_
                   << " (scripts/install-deps installs Debian's slurm-wlm and munge)";
    }
    ASSERT_EQ(start_error_, "") << "the single-host Slurm cluster did not start";
  }

  // submit.sh SCENE CHUNKS OUTPUT from the test's folder (where Slurm writes the jobs' logs), with
  // `tumble` as the executable and `environment` (NAME=VALUE ...) added to its environment.
  Outcome run_submit(const std::string& scene, int chunks, const std::string& output,
                     const std::string& tumble = TUMBLE_EXECUTABLE,
                     const std::string& environment = "") {
    const std::string prefix = "cd " + shell_quoted(dir_.string()) +
                               " && SLURM_CONF=" + shell_quoted(cluster_->config()) +
                               " TUMBLE=" + shell_quoted(tumble) + " " + environment + " exec ";
    return wait(
        start(shell_quoted(scene) + " " + std::to_string(chunks) + " " + shell_quoted(output),
              prefix, shell_quoted(TUMBLE_SOURCE_DIR "/examples/slurm/submit.sh")));
  }

  // submit.sh as run_submit() runs it, expected to succeed; the job ids it prints, by name.
  std::map<std::string, std::string> submit(const std::string& scene, int chunks,
                                            const std::string& output,
                                            const std::string& tumble = TUMBLE_EXECUTABLE) {
    const Outcome run = run_submit(scene, chunks, output, tumble);
    EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
    std::map<std::string, std::string> jobs;
    std::istringstream lines(run.out);
    for (std::string name, id; lines >> name >> id;) {
      jobs[name] = id;
    }
    return jobs;
  }

  // Waits for every job to end (a failure with the queue and the jobs' logs if some did not), and
  // keeps the jobs' logs for the messages of later checks.
  void wait_for_jobs() {
    const bool idle = cluster_->wait_until_idle(kJobsBound);
    std::string logs;
    for (const std::string& name : tumble::testing::names_in(dir_)) {
      if (name.starts_with("slurm-")) {
        logs += name + ":\n" + tumble::testing::read_file(dir_ / name);
      }
    }
    ASSERT_TRUE(idle) << "jobs still queued after " << kJobsBound << " s:\n"
                      << cluster_->client("squeue") << logs;
    logs_ = logs;
  }

  static inline std::string missing_;
  static inline std::string start_error_;
  static inline fs::path folder_;
  static inline std::unique_ptr<SlurmCluster> cluster_;
  std::string logs_;  // the jobs' standard output and error, for failure messages
};

TEST_F(SlurmExample, ArrayAndDependentJoinGiveTheWholeRender) {
  const std::string scene = write("tiny.toml", tumble::testing::kTinyScene).string();
  std::map<std::string, std::string> jobs = submit(scene, 3, path("out"));
  ASSERT_EQ(jobs.size(), 3u);
  ASSERT_NO_FATAL_FAILURE(wait_for_jobs());

  EXPECT_EQ(cluster_->job_state(jobs["array"]), "COMPLETED None, COMPLETED None, COMPLETED None")
      << logs_;
  EXPECT_EQ(cluster_->job_state(jobs["join"]), "COMPLETED None") << logs_;
  EXPECT_EQ(cluster_->job_state(jobs["cleanup"]), "COMPLETED None") << logs_;
  ASSERT_EQ(tumble("render -q " + scene + " -o " + path("whole")).exit_code, 0);
  tumble::testing::expect_joined_equals_whole(dir_ / "out/tiny", dir_ / "whole/tiny");
  // The cleanup job removed the chunk folders: OUTPUT holds the render folder alone.
  EXPECT_EQ(tumble::testing::names_in(dir_ / "out"), std::vector<std::string>{"tiny"});
}

// Without --kill-on-invalid-dep=yes the join would stay PENDING for ever and the wait time out.
TEST_F(SlurmExample, AFailedChunkCancelsTheJoinAndTheCleanupLeavesNothing) {
  const std::string scene = write("tiny.toml", tumble::testing::kTinyScene).string();
  // tumble for every call but chunk 2's render, which fails as a crashed node would.
  const fs::path failing =
      write("failing-tumble", "#!/bin/sh\ncase \"$*\" in *'--chunk 2/3'*) exit 3;; esac\nexec " +
                                  shell_quoted(TUMBLE_EXECUTABLE) + " \"$@\"\n");
  fs::permissions(failing, fs::perms::owner_all);
  std::map<std::string, std::string> jobs = submit(scene, 3, path("out"), failing.string());
  ASSERT_EQ(jobs.size(), 3u);
  ASSERT_NO_FATAL_FAILURE(wait_for_jobs());

  EXPECT_NE(cluster_->job_state(jobs["array"]).find("FAILED NonZeroExitCode"), std::string::npos)
      << logs_;
  EXPECT_EQ(cluster_->job_state(jobs["join"]), "CANCELLED DependencyNeverSatisfied") << logs_;
  EXPECT_EQ(cluster_->job_state(jobs["cleanup"]), "COMPLETED None") << logs_;
  EXPECT_EQ(tumble::testing::names_in(dir_ / "out"), std::vector<std::string>{});
}

// sbatch refuses the array (a partition that does not exist, through sbatch's own
// SBATCH_PARTITION): submit.sh fails with sbatch's message, queues nothing and removes what it
// made.
TEST_F(SlurmExample, ARefusedSubmissionLeavesNothingQueuedOrWritten) {
  const std::string scene = write("tiny.toml", tumble::testing::kTinyScene).string();
  const Outcome run =
      run_submit(scene, 3, path("out"), TUMBLE_EXECUTABLE, "SBATCH_PARTITION=nowhere");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("Invalid partition name specified"), std::string::npos) << run.err;
  EXPECT_EQ(cluster_->client("squeue -h -o %i"), "");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace

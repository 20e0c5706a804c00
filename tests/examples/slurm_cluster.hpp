// A single-host Slurm cluster for tests: munged, slurmctld and slurmd (Debian's `munge` and
// `slurm-wlm`) started as child processes of the test, with a fresh munge key, a minimal
// slurm.conf for localhost and every file in one folder; stopped by stop() or the destructor.
// Nothing needs systemd, cgroups or a network beyond loopback.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::testing {

class SlurmCluster {
 public:
  SlurmCluster() = default;
  SlurmCluster(const SlurmCluster&) = delete;
  SlurmCluster& operator=(const SlurmCluster&) = delete;
  ~SlurmCluster() { stop(); }

  // The programs the cluster needs that are not installed, space-separated; "" when all are.
  static std::string missing_programs();

  // Starts the daemons with their files in `folder` (made if need be) and waits, at most 30 s,
  // until the node takes jobs. "" then; otherwise why not, with the daemon's own error text.
  std::string start(const std::filesystem::path& folder);

  // Stops every daemon that start() started (SIGTERM, then SIGKILL after 10 s) and waits for it.
  void stop();

  // The slurm.conf that client commands (sbatch, squeue, scontrol) need in SLURM_CONF.
  std::string config() const { return (folder_ / "slurm.conf").string(); }

  // Runs a Slurm client command line (sh -c) against this cluster; its standard output and error.
  std::string client(const std::string& command) const;

  // Waits, at most `seconds`, until no job is queued or running; false if some still are.
  bool wait_until_idle(double seconds) const;

  // JobState and Reason of a job, as `scontrol show job` gives them, e.g. "CANCELLED
  // DependencyNeverSatisfied"; of each task for an array, in scontrol's order, separated by ", "
  // (slurmctld keeps ended jobs for MinJobAge, 300 s). scontrol's own text if it knows no such job.
  std::string job_state(const std::string& job_id) const;

 private:
  // Starts `program` with `arguments`, standard output and error into `log`; its process id.
  pid_t spawn(const std::string& program, const std::vector<std::string>& arguments,
              const std::filesystem::path& log);
  // "" while every daemon runs, else which one ended and what it said.
  std::string daemon_exited();
  std::string write_config() const;

  std::filesystem::path folder_;
  struct Daemon {
    std::string name;
    pid_t pid;
    std::filesystem::path log;
  };
  std::vector<Daemon> daemons_;
};

}  // namespace tumble::testing

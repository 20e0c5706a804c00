#include "examples/slurm_cluster.hpp"

#include <fcntl.h>
#include <netinet/in.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "support/command_test.hpp"

namespace tumble::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kDaemons[] = {"munged", "slurmctld", "slurmd"};
constexpr const char* kClients[] = {"sbatch", "squeue", "sinfo", "scontrol", "scancel"};

// The executable `name` on PATH or in the sbin folders (where Debian puts the daemons, and which a
// user's PATH may lack); "" if none.
std::string find_program(const std::string& name) {
  std::string folders = std::getenv("PATH") ? std::getenv("PATH") : "";
  folders += ":/usr/sbin:/sbin:/usr/local/sbin";
  std::stringstream list(folders);
  for (std::string folder; std::getline(list, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0) {
      return candidate.string();
    }
  }
  return "";
}

// A TCP port nobody listens on now. Both ports are asked for before either socket is closed, so
// the two differ.
std::vector<int> free_ports(int count) {
  std::vector<int> sockets;
  std::vector<int> ports;
  for (int i = 0; i < count; ++i) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    address.sin_port = 0;
    socklen_t size = sizeof address;
    ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
    sockets.push_back(fd);
    ports.push_back(ntohs(address.sin_port));
  }
  for (const int fd : sockets) {
    ::close(fd);
  }
  return ports;
}

// A fresh 1024-byte munge key, readable by its owner alone as munged demands.
void write_munge_key(const fs::path& path) {
  std::random_device random;
  std::string key(1024, '\0');
  for (char& byte : key) {
    byte = static_cast<char>(random() & 0xff);
  }
  std::ofstream(path, std::ios::binary) << key;
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
}

// Polls `ready` every 0.2 s for at most `seconds`; false if it never held.
template <typename Predicate>
bool poll(double seconds, Predicate ready) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (!ready()) {
    if (Clock::now() > end) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return true;
}

std::string user_name() {
  const passwd* entry = ::getpwuid(::geteuid());
  return entry ? entry->pw_name : std::to_string(::geteuid());
}

}  // namespace

std::string SlurmCluster::missing_programs() {
  std::string missing;
  for (const char* name : kDaemons) {
    missing += find_program(name).empty() ? std::string(missing.empty() ? "" : " ") + name : "";
  }
  for (const char* name : kClients) {
    missing += find_program(name).empty() ? std::string(missing.empty() ? "" : " ") + name : "";
  }
  return missing;
}

std::string SlurmCluster::write_config() const {
  const std::vector<int> ports = free_ports(2);
  const std::string d = folder_.string();
  const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
  std::ofstream conf(folder_ / "slurm.conf");
  // Plugins that need neither systemd nor cgroups: processes tracked through /proc, no task
  // binding, no accounting (that would need slurmdbd and a database).
  conf << "ClusterName=tumbletest\nSlurmctldHost=localhost\nSlurmUser=" << user_name()
       << "\nSlurmdUser=" << user_name() << "\nSlurmctldPort=" << ports[0]
       << "\nSlurmdPort=" << ports[1] << "\nAuthType=auth/munge\nAuthInfo=socket=" << d
       << "/munge.socket"
       << "\nProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\nMpiDefault=none"
       << "\nJobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none"
       << "\nJobCompType=jobcomp/none\nSelectType=select/cons_tres\nSelectTypeParameters=CR_Core"
       << "\nReturnToService=2\nMinJobAge=300\nStateSaveLocation=" << d << "/state"
       << "\nSlurmdSpoolDir=" << d << "/spool\nSlurmctldPidFile=" << d << "/slurmctld.pid"
       << "\nSlurmdPidFile=" << d << "/slurmd.pid\nSlurmctldLogFile=" << d << "/slurmctld.log"
       << "\nSlurmdLogFile=" << d << "/slurmd.log\nNodeName=localhost CPUs=" << cpus
       << " State=UNKNOWN\nPartitionName=tumble Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n";
  return conf ? "" : "cannot write " + config();
}

pid_t SlurmCluster::spawn(const std::string& program, const std::vector<std::string>& arguments,
                          const fs::path& log) {
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    // A test killed on a timeout takes its daemons with it instead of leaving them running.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = ::open("/dev/null", O_RDONLY);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(out, 2);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  daemons_.push_back({fs::path(program).filename().string(), pid, log});
  return pid;
}

std::string SlurmCluster::daemon_exited() {
  for (Daemon& daemon : daemons_) {
    int status = 0;
    if (daemon.pid > 0 && ::waitpid(daemon.pid, &status, WNOHANG) == daemon.pid) {
      daemon.pid = 0;
      return daemon.name + " exited (status " + std::to_string(status) + "), saying:\n" +
             read_file(daemon.log);
    }
  }
  return "";
}

std::string SlurmCluster::start(const fs::path& folder) {
  folder_ = folder;
  fs::create_directories(folder_ / "state");
  fs::create_directories(folder_ / "spool");
  // munged refuses a socket in a folder that others cannot enter.
  fs::permissions(folder_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                               fs::perms::others_read | fs::perms::others_exec);
  write_munge_key(folder_ / "munge.key");
  const std::string d = folder_.string();
  spawn(find_program("munged"),
        {"--foreground", "--socket=" + d + "/munge.socket", "--key-file=" + d + "/munge.key",
         "--pid-file=" + d + "/munged.pid", "--log-file=" + d + "/munged.log",
         "--seed-file=" + d + "/munged.seed"},
        folder_ / "munged.out");
  std::string exited;
  const bool socket = poll(10, [&] {
    exited = daemon_exited();
    return !exited.empty() || fs::exists(folder_ / "munge.socket");
  });
  if (!exited.empty() || !socket) {
    return exited.empty() ? "munged made no socket in 10 s:\n" + read_file(folder_ / "munged.out")
                          : exited;
  }
  if (std::string error = write_config(); !error.empty()) {
    return error;
  }
  spawn(find_program("slurmctld"), {"-D", "-f", config()}, folder_ / "slurmctld.out");
  spawn(find_program("slurmd"), {"-D", "-f", config(), "-N", "localhost"}, folder_ / "slurmd.out");
  const bool idle = poll(30, [&] {
    exited = daemon_exited();
    return !exited.empty() || client("sinfo -h -o %T").find("idle") != std::string::npos;
  });
  if (!exited.empty()) {
    return exited;
  }
  return idle ? ""
              : "the node was not idle after 30 s; sinfo says: " + client("sinfo -h") +
                    "slurmctld.log:\n" + read_file(folder_ / "slurmctld.log") + "slurmd.log:\n" +
                    read_file(folder_ / "slurmd.log");
}

void SlurmCluster::stop() {
  // slurmd before slurmctld before munged: each needs the next one while it shuts down.
  for (auto daemon = daemons_.rbegin(); daemon != daemons_.rend(); ++daemon) {
    if (daemon->pid <= 0) {
      continue;
    }
    ::kill(daemon->pid, SIGTERM);
    int status = 0;
    if (!poll(10, [&] { return ::waitpid(daemon->pid, &status, WNOHANG) == daemon->pid; })) {
      ::kill(daemon->pid, SIGKILL);
      ::waitpid(daemon->pid, &status, 0);
    }
    daemon->pid = 0;
  }
  daemons_.clear();
}

std::string SlurmCluster::client(const std::string& command) const {
  const std::string line = "SLURM_CONF=" + shell_quoted(config()) + " " + command + " 2>&1";
  std::string out;
  if (FILE* pipe = ::popen(line.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
      out.append(buffer, n);
    }
    ::pclose(pipe);
  }
  return out;
}

bool SlurmCluster::wait_until_idle(double seconds) const {
  return poll(seconds, [&] { return client("squeue -h -o %i").empty(); });
}

std::string SlurmCluster::job_state(const std::string& job_id) const {
  const std::string text = client("scontrol show job -o " + shell_quoted(job_id));
  // "JobState=STATE Reason=REASON" of each job listed (one a line with -o). Read by hand: GCC 12
  // warns inside std::regex under the sanitizer build (maybe-uninitialized), an error there.
  const auto word_at = [&](std::size_t from) {
    return text.substr(from, text.find_first_of(" \t\n", from) - from);
  };
  std::string states;
  for (std::size_t at = text.find("JobState="); at != std::string::npos;
       at = text.find("JobState=", at + 1)) {
    const std::string state = word_at(at + 9);
    const std::size_t reason = at + 9 + state.size();
    if (text.compare(reason, 8, " Reason=") != 0) continue;
    states += (states.empty() ? "" : ", ") + state + " " + word_at(reason + 8);
  }
  return states.empty() ? text : states;
}

}  // namespace tumble::testing

#include "sys/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace tumble::sys {
namespace {

// How reading a child's output ended.
enum class ReadEnd { end_of_output, stopped, failed };

// Reads `fd` to its end, passing each line to `on_line` (a last line without its '\n' too), until
// `on_line` returns false. After `failed`, errno says why.
ReadEnd read_lines(int fd, const std::function<bool(std::string_view)>& on_line) {
  std::string pending;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return ReadEnd::failed;
    if (got == 0) break;
    pending.append(buffer, static_cast<std::size_t>(got));
    std::size_t start = 0;
    for (std::size_t end; (end = pending.find('\n', start)) != std::string::npos; start = end + 1) {
      if (!on_line(std::string_view(pending).substr(start, end - start))) return ReadEnd::stopped;
    }
    pending.erase(0, start);
  }
  return pending.empty() || on_line(pending) ? ReadEnd::end_of_output : ReadEnd::stopped;
}

// "exited with status 3", "was killed by signal 11 (Segmentation fault)": from waitpid's status.
std::string how_it_ended(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    return "was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
           ::strsignal(WTERMSIG(status)) + ")";
  }
  return "ended with wait status " + std::to_string(status);
}

// posix_spawn of `program` with `arguments` and the file actions (or none), into `pid`: 0 or the
// error number. tumble ignores SIGPIPE and SIGXFSZ (process.hpp), and an ignored signal stays
// ignored across exec: the child gets the defaults back, so that it ends when its reader stops.
int spawn(pid_t& pid, const std::string& program, const std::vector<std::string>& arguments,
          const posix_spawn_file_actions_t* actions) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  sigaddset(&defaults, SIGXFSZ);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  const int spawned =
      ::posix_spawn(&pid, program.c_str(), actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  return spawned;
}

}  // namespace

Result<void> run_reading_lines(const std::string& program,
                               const std::vector<std::string>& arguments,
                               const std::function<bool(std::string_view line)>& on_line) {
  int pipe_ends[2];
  // Close-on-exec, so that no other child inherits them; dup2 onto the child's standard output
  // clears the flag on that copy only.
  if (::pipe2(pipe_ends, O_CLOEXEC) != 0) {
    return Error{"cannot run " + program + ": pipe: " + std::strerror(errno)};
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  pid_t pid = 0;
  const int spawned = spawn(pid, program, arguments, &actions);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_ends[1]);  // else the read below would never see the end of the child's output
  if (spawned != 0) {
    ::close(pipe_ends[0]);
    return Error{"cannot run " + program + ": " + std::strerror(spawned)};
  }

  const ReadEnd read = read_lines(pipe_ends[0], on_line);
  const std::string read_error = read == ReadEnd::failed ? std::strerror(errno) : "";
  if (read != ReadEnd::end_of_output) ::kill(pid, SIGTERM);
  ::close(pipe_ends[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return Error{"waiting for " + program + " failed: " + std::strerror(errno)};
  }
  if (read == ReadEnd::failed)
    return Error{"reading the output of " + program + " failed: " + read_error};
  if (read == ReadEnd::stopped) return Error{program + " was stopped"};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return Result<void>::success();
  return Error{program + " " + how_it_ended(status)};
}

Result<void> run_together(const std::vector<ProgramRun>& runs,
                          const std::function<bool()>& stop_requested,
                          const std::function<void(std::size_t index)>& on_done) {
  std::vector<pid_t> running(runs.size(), 0);  // 0 once waited for (or never started)
  std::string failure;
  const auto stop_all = [&] {
    for (const pid_t pid : running) {
      if (pid != 0) ::kill(pid, SIGTERM);
    }
  };
  for (std::size_t i = 0; i < runs.size() && failure.empty(); ++i) {
    const int spawned = spawn(running[i], runs[i].program, runs[i].arguments, nullptr);
    if (spawned != 0) {
      running[i] = 0;
      failure = "cannot run " + runs[i].program + ": " + std::strerror(spawned);
    }
  }
  bool stopping = !failure.empty();
  if (stopping) stop_all();
  for (;;) {
    bool any = false;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (running[i] == 0) continue;
      int status = 0;
      const pid_t ended = ::waitpid(running[i], &status, WNOHANG);
      if (ended == 0 || (ended < 0 && errno == EINTR)) {
        any = true;
        continue;
      }
      running[i] = 0;
      if (ended > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        on_done(i);
      } else if (failure.empty()) {
        failure = ended < 0 ? "waiting for " + runs[i].program + " failed: " + std::strerror(errno)
                            : runs[i].program + " " + how_it_ended(status);
      }
    }
    if (!any) break;
    if (!stopping && (!failure.empty() || stop_requested())) {
      stopping = true;
      stop_all();
    }
    ::usleep(50 * 1000);
  }
  if (!failure.empty()) return Error{failure};
  return Result<void>::success();
}

}  // namespace tumble::sys

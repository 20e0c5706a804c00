// A fixture for end-to-end tests that run the real `tumble` executable in a fresh folder, the way
// users and scripts run it, and look at its exit code, output and files.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tumble::testing {

namespace fs = std::filesystem;

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// `text` as one word for sh -c, whatever characters it holds.
inline std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return out + "'";
}

struct Outcome {
  int exit_code;    // -1 if the process died by a signal (never expected of tumble)
  std::string out;  // standard output
  std::string err;  // standard error
};

class CommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    // The process id keeps two test runs on one machine (two checkouts) out of each other's way.
    dir_ = fs::path(::testing::TempDir()) / ("tumble_" + std::string(test->test_suite_name()) +
                                             "_" + test->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }

  // Runs `tumble ARGUMENTS` with standard output and error captured. `prefix` is the shell text
  // before the executable's path, such as "ulimit -f 100; exec ".
  Outcome tumble(const std::string& arguments, const std::string& prefix = "exec ") const {
    return wait(start(arguments, prefix));
  }

  // Starts `tumble ARGUMENTS` (as tumble() does) without waiting for it. `executable` is the
  // built tumble unless a test runs a copy of it elsewhere.
  pid_t start(const std::string& arguments, const std::string& prefix = "exec ",
              const std::string& executable = TUMBLE_EXECUTABLE) const {
    const std::string command =
        prefix + executable + " " + arguments + " >" + path("stdout") + " 2>" + path("stderr");
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    return pid;
  }

  // Waits for a command from start() and collects what it printed.
  Outcome wait(pid_t pid) const {
    int status = 0;
    ::waitpid(pid, &status, 0);
    Outcome outcome{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(dir_ / "stdout"),
                    read_file(dir_ / "stderr")};
    fs::remove(dir_ / "stdout");
    fs::remove(dir_ / "stderr");
    return outcome;
  }

  fs::path dir_;
};

}  // namespace tumble::testing

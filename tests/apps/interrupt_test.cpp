// A run stopped by SIGINT or SIGTERM leaves no output behind, not even PATH.partial, and exits
// 130 or 143 (docs/cli.md "Exit codes"; apps/interrupt_cleanup).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/run_command.hpp"

extern char** environ;

namespace mdrsim::test {
namespace {

namespace fs = std::filesystem;

struct Stopped {
  int exit_code;    ///< -1: the run ended by itself first; -2: it never started its output
  std::string err;  ///< standard error
};

/// Starts a run of 1e9 springs (about half a minute) writing --json PATH,
/// waits until its temporary output exists, sends `signal_number` and waits for the exit.
Stopped stop_a_long_run(const std::string& dir, int signal_number) {
  const std::string json = dir + "/out.json";
  const std::string err = dir + "/err";
  std::vector<std::string> args{MDRSIM_BINARY,
                                "run",
                                std::string(MDRSIM_SOURCE_DIR) + "/scenes/fig2_fixed_load.toml",
                                "--set",
                                "discretization.springs=1e9",
                                "--json",
                                json,
                                "--log-level",
                                "off"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  // The child starts with SIGINT and SIGTERM at their defaults, whatever this process has.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, MDRSIM_BINARY, &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) return {-2, "posix_spawn failed"};
  int status = 0;
  bool started = false;
  for (int i = 0; i < 1000 && !started; ++i) {
    started = fs::exists(json + ".partial");
    if (!started) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  // Well inside the run: the springs are being let go.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const bool running = waitpid(pid, &status, WNOHANG) == 0;
  if (running) {
    kill(pid, signal_number);
    waitpid(pid, &status, 0);
  }
  std::ifstream in(err);
  const std::string text(std::istreambuf_iterator<char>(in), {});
  if (!started) return {-2, text};
  if (!running) return {-1, text};
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), text};
}

class Interrupt : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_temp_dir(); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  /// Nothing of the output is left: no out.json, no out.json.partial.
  bool nothing_left() const {
    return !fs::exists(dir_ + "/out.json") && !fs::exists(dir_ + "/out.json.partial");
  }
  std::string dir_;
};

TEST_F(Interrupt, SigintRemovesThePartialFileAndExits130) {
  const Stopped r = stop_a_long_run(dir_, SIGINT);
  EXPECT_EQ(r.exit_code, 130) << r.err;
  EXPECT_EQ(r.err, "mdrsim: stopped by SIGINT; unfinished output files removed\n");
  EXPECT_TRUE(nothing_left());
}

TEST_F(Interrupt, SigtermRemovesThePartialFileAndExits143) {
  const Stopped r = stop_a_long_run(dir_, SIGTERM);
  EXPECT_EQ(r.exit_code, 143) << r.err;
  EXPECT_EQ(r.err, "mdrsim: stopped by SIGTERM; unfinished output files removed\n");
  EXPECT_TRUE(nothing_left());
}

}  // namespace
}  // namespace mdrsim::test

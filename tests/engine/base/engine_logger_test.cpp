// The engine logs to standard error or to the logger a program gives spdlog, never to
// standard output, where a program that links the engine writes its own JSON or CSV.
#include "engine/base/engine_logger.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>

#include "engine/events/log_observer.hpp"
#include "engine/events/observer.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

// G*/E* = 0.1 is outside an isotropic half-space's [2/3, 4/3]: built with a warning.
constexpr std::string_view kWarningScene = R"([material]
effective_modulus = 1.0e6
effective_shear_modulus = 1.0e5
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.0e-4 }
normal = { control = "fixed-load" }
)";

constexpr std::string_view kWarning =
    "scene.toml:3:27: material.effective_shear_modulus: G*/E* = 0.1 is outside [2/3, 4/3], the "
    "range of an isotropic half-space (G*/E* = 2(1-nu)/(2-nu), -1 < nu <= 0.5)";

void run_warning_scene() {
  const Scene scene =
      SceneDocument::from_text(kWarningScene, "scene.toml").build(Registries::builtin());
  LogObserver log;
  ObserverList observers;
  observers.add(log);
  run_scene(scene, observers);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Runs `body` in a child process with standard output and error in files; its exit code.
template <class Body>
int in_child(const std::string& out, const std::string& err, Body body) {
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0) _exit(126);
    const int code = body();
    std::fflush(nullptr);
    _exit(code);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(EngineLogger, AProgramThatSetsNoLoggerGetsTheEngineLogsOnStandardError) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string out = (dir / fmt::format("engine_logger_{}.out", getpid())).string();
  const std::string err = (dir / fmt::format("engine_logger_{}.err", getpid())).string();
  // spdlog's built-in default logger writes to standard output: the engine leaves it to the
  // program (its own line below still goes there) and logs on standard error.
  ASSERT_EQ(in_child(out, err,
                     [] {
                       spdlog::logger* before = spdlog::default_logger_raw();
                       run_warning_scene();
                       spdlog::info("the program's own line");
                       return spdlog::default_logger_raw() == before ? 0 : 3;
                     }),
            0)
      << slurp(err);
  const std::string own = slurp(out);
  EXPECT_EQ(std::count(own.begin(), own.end(), '\n'), 1) << own;
  EXPECT_NE(own.find("[info] the program's own line\n"), std::string::npos) << own;
  const std::string logs = slurp(err);
  EXPECT_NE(logs.find(fmt::format("[mdrsim warning] {}\n", kWarning)), std::string::npos) << logs;
  EXPECT_EQ(logs.find("[mdrsim info] preload: "), 0u) << logs;

  // spdlog::set_level reaches the engine's logger: at warn, the warning alone.
  ASSERT_EQ(in_child(out, err,
                     [] {
                       spdlog::set_level(spdlog::level::warn);
                       run_warning_scene();
                       return 0;
                     }),
            0);
  EXPECT_EQ(slurp(out), "");
  EXPECT_EQ(slurp(err), fmt::format("[mdrsim warning] {}\n", kWarning));
  std::filesystem::remove(out);
  std::filesystem::remove(err);
}

TEST(EngineLogger, AProgramsOwnDefaultLoggerGetsTheEngineLogs) {
  std::ostringstream lines;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(lines);
  auto mine = std::make_shared<spdlog::logger>("mine", sink);
  mine->set_pattern("<%l> %v");
  const std::shared_ptr<spdlog::logger> saved = spdlog::default_logger();
  spdlog::set_default_logger(mine);
  EXPECT_EQ(&engine_logger(), mine.get());
  run_warning_scene();
  spdlog::set_default_logger(saved);
  EXPECT_NE(lines.str().find(fmt::format("<warning> {}\n", kWarning)), std::string::npos)
      << lines.str();
  EXPECT_NE(&engine_logger(), saved.get());
}

}  // namespace
}  // namespace mdrsim

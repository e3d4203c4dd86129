// The mdrsim binary on bad input: exit code 2, one exact line on stderr, nothing on stdout and
// no output file left behind; and on good input: exit 0, clean JSON on stdout, help texts.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "engine/scene/registries.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

namespace fs = std::filesystem;

// Line numbers in the messages below refer to this scene.
constexpr std::string_view kScene = R"([material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.0e-4 }
normal = { control = "fixed-load" }
[discretization]
springs = 100
)";

constexpr const char* kMaterialKeys =
    "adhesive_stress, approach_work_of_adhesion, effective_modulus, effective_shear_modulus, "
    "grading, maugis_parameter, poisson_ratio, relaxation, work_of_adhesion, youngs_modulus";

/// `text` as one single-quoted shell word.
std::string shell_word(std::string_view text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir();
    scene_ = write("scene.toml", kScene);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }

  /// Writes `text` to a file in the test's folder; returns its path.
  std::string write(const std::string& name, std::string_view text) const {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  /// kScene with the one occurrence of `from` replaced, written to bad.toml.
  std::string bad_scene(std::string_view from, std::string_view to) const {
    std::string text(kScene);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return write("bad.toml", text.replace(at, from.size(), to));
  }
  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  std::string dir_;
  std::string scene_;
};

/// Exit code 2, exactly `message` as the one line on stderr, nothing on stdout.
::testing::AssertionResult bad_input(const CommandResult& r, const std::string& message) {
  if (r.exit_code == 2 && r.err == message + "\n" && r.out.empty()) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "exit code " << r.exit_code << " (want 2)\nstderr: [" << r.err << "]\nwant:   ["
         << message << "\n]\nstdout: [" << r.out << "]";
}

/// Neither PATH nor PATH.partial exists.
::testing::AssertionResult nothing_at(const std::string& path) {
  for (const std::string& p : {path, path + ".partial"}) {
    if (fs::exists(p)) return ::testing::AssertionFailure() << p << " was left behind";
  }
  return ::testing::AssertionSuccess();
}

// ---- the scene file ----

TEST_F(Cli, MissingSceneFile) {
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", path("none.toml"), json));
  EXPECT_TRUE(
      bad_input(r, path("none.toml") + ": cannot read the scene file (no such file or directory)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, DirectoryAsSceneFile) {
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", dir_, json));
  EXPECT_TRUE(bad_input(r, dir_ + ": cannot read the scene file (it is a directory)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, UnreadableSceneFile) {
  fs::permissions(scene_, fs::perms::none);
  if (geteuid() == 0 || std::ifstream(scene_).good()) {
    GTEST_SKIP() << "running as root (or with CAP_DAC_OVERRIDE): chmod 000 cannot make a file "
                    "unreadable";
  }
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene_, json));
  EXPECT_TRUE(bad_input(r, scene_ + ": cannot read the scene file (permission denied)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SceneFileBelowAFile) {
  // Runs as root too, unlike the chmod case: the OS reason is named, lowercase.
  const auto r = run_mdrsim(fmt::format("run {}/x.toml", scene_));
  EXPECT_TRUE(bad_input(r, scene_ + "/x.toml: cannot read the scene file (not a directory)"));
}

// An output that cannot be written (a full disk) is a failure of the run's output, exit 1 with
// one line naming the flag: not an "internal error".
TEST_F(Cli, AnOutputThatCannotBeWrittenNamesItsFlag) {
  const auto full = run_mdrsim(fmt::format("run {} --json /dev/full --log-level off", scene_));
  EXPECT_EQ(full.exit_code, 1);
  EXPECT_EQ(full.err, "mdrsim: --json: writing '/dev/full' failed\n");
  const auto sweep = run_mdrsim(fmt::format(
      "sweep {} --vary material.poisson_ratio=0:0.4:3 --csv /dev/full --log-level off", scene_));
  EXPECT_EQ(sweep.exit_code, 1);
  EXPECT_EQ(sweep.err, "mdrsim: --csv: writing '/dev/full' failed (no space left on device)\n");
}

// A reader that closes standard output (`| head`) wants no more: mdrsim ends as `seq | head`
// does, without a message, exit 141 (128 + SIGPIPE). Each output is far beyond a pipe's 64 KiB
// (a sweep of 2000 rows, a trajectory of 4 MB), so that head closes it before it is written.
TEST_F(Cli, StandardOutputClosedByItsReaderEndsQuietly) {
  const auto read = [](const std::string& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string out = path("head.out");
  const std::string err = path("mdrsim.err");
  const std::string status = path("status.txt");
  for (const std::string& command :
       {fmt::format("sweep {} --vary material.poisson_ratio=0:0.4:2000 --log-level off", scene_),
        fmt::format("sweep {} --vary material.poisson_ratio=0:0.4:2000 --threads 2 --csv -",
                    scene_),
        fmt::format("run {} --json {} --trajectory - --set discretization.springs=100000", scene_,
                    path("out.json"))}) {
    // bash for PIPESTATUS: mdrsim's own exit code, not head's.
    const std::string pipeline =
        fmt::format("cd '{}' && '{}' {} 2>'{}' | head -n 3 >'{}'; echo ${{PIPESTATUS[0]}} >'{}'",
                    MDRSIM_SOURCE_DIR, MDRSIM_BINARY, command, err, out, status);
    ASSERT_EQ(std::system(fmt::format("bash -c {}", shell_word(pipeline)).c_str()), 0);
    const std::string head = read(out);
    EXPECT_EQ(std::count(head.begin(), head.end(), '\n'), 3) << command << "\n" << head;
    EXPECT_EQ(read(err).find("mdrsim:"), std::string::npos) << command << "\n" << read(err);
    EXPECT_EQ(read(err).find("[error]"), std::string::npos) << command << "\n" << read(err);
    EXPECT_EQ(read(status), "141\n") << command << "\n" << read(err);
  }
}

TEST_F(Cli, EndlessSceneFile) {
  const auto r = run_mdrsim("run /dev/zero");
  EXPECT_TRUE(bad_input(r, "/dev/zero: cannot read the scene file (it is larger than 16 MiB)"));
}

/// run_mdrsim with the memory of the run bounded (1 GiB of address space; under AddressSanitizer,
/// which needs its address space, a 1 GiB resident limit), so that a read that never ends fails
/// in seconds instead of taking the machine's memory.
CommandResult run_mdrsim_bounded(const std::string& args, const std::string& dir) {
#if defined(__SANITIZE_ADDRESS__)
  const std::string limit = "export ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:hard_rss_limit_mb=1024\"; ";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  const std::string limit = "export ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:hard_rss_limit_mb=1024\"; ";
#else
  const std::string limit = "ulimit -v 1048576; ";
#endif
#else
  const std::string limit = "ulimit -v 1048576; ";
#endif
  const std::string command = limit +
                              "cd '" MDRSIM_SOURCE_DIR "' && timeout 120 '" MDRSIM_BINARY "' " +
                              args + " >'" + dir + "/out' 2>'" + dir + "/err' </dev/null";
  const int status = std::system(command.c_str());
  const auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), slurp(dir + "/out"),
          slurp(dir + "/err")};
}

// A tabulated profile read from an endless device must fail like an endless scene file: at the
// size limit, with exit code 2, not after the run has taken all memory (it once read /dev/zero
// into one line until allocation failed: 4 GB and 14 s, then "cannot read").
TEST_F(Cli, TabulatedProfileFromAnEndlessDevice) {
  const std::string scene = bad_scene("type = \"parabolic\"\nradius = 0.01",
                                      "type = \"tabulated\"\nfile = \"/dev/zero\"");
  const auto r = run_mdrsim_bounded("run " + scene, dir_);
  EXPECT_TRUE(bad_input(r, scene + ":7:8: profile.file: '/dev/zero' is larger than 64 MiB"));
}

TEST_F(Cli, TypoInAKey) {
  const std::string scene = bad_scene("youngs_modulus", "youngs_modulu");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(bad_input(
      r,
      fmt::format(
          "{}:2:1: material.youngs_modulu: unknown key; did you mean 'youngs_modulus'? (known: {})",
          scene, kMaterialKeys)));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, PoissonRatioOutOfRange) {
  const std::string scene = bad_scene("poisson_ratio = 0.0", "poisson_ratio = 0.7");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(bad_input(r, scene + ":3:17: material.poisson_ratio = 0.7 is outside (-1, 0.5]"));
  EXPECT_TRUE(nothing_at(json));
}

// The continuum route has no springs: a scene that names them is refused, as are the programs
// the route does not answer yet (docs/continuum.md).
TEST_F(Cli, ContinuumRefusesSprings) {
  const std::string scene =
      bad_scene("springs = 100\n", "springs = 100\n[solver]\nmethod = \"continuum\"\n");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(bad_input(r, scene + ":12:11: discretization.springs: the continuum route has no "
                                   "springs; give rtol (default 1e-10) or use solver.method = "
                                   "\"event\""));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, ContinuumRefusesAProgramThatShears) {
  const std::string scene = bad_scene(
      "[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { control = \"fixed-load\" }\n"
      "[discretization]\nsprings = 100\n",
      "[[loading.stage]]\ntangential = { control = \"fixed-grips\", by = 1e-6 }\n"
      "until = \"separation\"\n[solver]\nmethod = \"continuum\"\n");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(bad_input(r, scene + ":12:10: solver.method: stage 'stage 1' shears until "
                                   "separation: a front receding under a moving tangential "
                                   "load is the row's, not the continuum route's; use method = "
                                   "\"event\" (docs/continuum.md)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, ContinuumRunsWithoutSprings) {
  const std::string scene =
      bad_scene("springs = 100\n", "rtol = 1e-10\n[solver]\nmethod = \"continuum\"\n");
  const auto r = run_mdrsim(fmt::format("run {} --json -", scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["resolution"]["route"], "continuum");
  EXPECT_FALSE(j.contains("springs"));
  // The parabola's fixed-load pull-off, -F0 (paper eq. 19's minimum), to rtol.
  EXPECT_NEAR(j["dimensionless"]["normal_force"].get<double>(), -1.0, 1e-10);
}

// --plan prints the route (engine, driver and why) on one line and runs nothing: no JSON is
// written though one is asked for.
TEST_F(Cli, PlanPrintsTheRouteAndRunsNothing) {
  const std::string json = dir_ + "/plan.json";
  const auto row =
      run_mdrsim(fmt::format("run scenes/fig2_fixed_load.toml --plan --json {}", json));
  ASSERT_EQ(row.exit_code, 0) << row.err;
  EXPECT_EQ(row.out,
            "route: pull-off row (event method), richardson over rows of 5000, 10000 and 20000 "
            "springs: the shorthand (preload, tangential load, pull-off); where a first row "
            "finds the glue let go with the indenter pressed in, the shorthand runs as its three "
            "stages on the program row\n");
  EXPECT_FALSE(std::filesystem::exists(json));
  const std::string scene =
      bad_scene("springs = 100\n", "rtol = 1e-10\n[solver]\nmethod = \"continuum\"\n");
  const auto continuum = run_mdrsim(fmt::format("run {} --plan", scene));
  ASSERT_EQ(continuum.exit_code, 0) << continuum.err;
  EXPECT_EQ(continuum.out, "route: continuum route, rtol 1e-10: solver.method = \"continuum\"\n");
}

// The summary of a continuum run counts no springs: it has none (a row's says how many).
TEST_F(Cli, ContinuumSummaryNamesTheRouteNotSprings) {
  const std::string scene =
      bad_scene("springs = 100\n", "rtol = 1e-10\n[solver]\nmethod = \"continuum\"\n");
  const auto r = run_mdrsim(fmt::format("run {} --log-level off", scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("continuum route)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("springs"), r.out.find("no springs") + 3) << r.out;  // only there
}

// --trajectory on the continuum route: --samples rows of kind `sample`, evenly in the contact
// radius from the glued radius (5e-4 m) to the critical point (a0 = 1.6e-4 m, paper eq. 17:
// the fixed-load pull-off), with no springs to count.
TEST_F(Cli, ContinuumTrajectorySamplesTheBranch) {
  const std::string scene =
      bad_scene("springs = 100\n", "rtol = 1e-10\n[solver]\nmethod = \"continuum\"\n");
  const std::string csv = path("t.csv");
  const auto r =
      run_mdrsim(fmt::format("run {} --json - --trajectory {} --samples 11", scene, csv));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double critical = nlohmann::json::parse(r.out)["critical"]["contact_radius"].get<double>();
  std::ifstream in(csv);
  std::string line;
  std::vector<double> radii;
  while (std::getline(in, line)) {
    if (line.find(",sample,") == std::string::npos) continue;
    EXPECT_EQ(line.back(), ',') << line;  // springs_in_contact empty
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    radii.push_back(std::stod(cells.at(5)));
  }
  ASSERT_EQ(radii.size(), 11u);
  EXPECT_DOUBLE_EQ(radii.front(), 5e-4);
  EXPECT_DOUBLE_EQ(radii.back(), critical);
  for (std::size_t k = 1; k < radii.size(); ++k) {
    // Even steps of (a_g - a_c) / 10, to rounding.
    EXPECT_NEAR(radii[k - 1] - radii[k], (5e-4 - critical) / 10.0, 1e-15);
  }
}

TEST_F(Cli, NegativeModulus) {
  const std::string scene = bad_scene("youngs_modulus = 1.0e6", "youngs_modulus = -1.0e6");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(
      bad_input(r, scene + ":2:18: material.youngs_modulus = -1000000 is outside (0, inf)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, NotANumber) {
  const std::string scene = bad_scene("radius = 0.01", R"(radius = "1 cm")");
  const std::string csv = path("out.csv");
  const auto r = run_mdrsim(
      fmt::format("sweep {} --vary material.poisson_ratio=0:0.3:2 --csv {}", scene, csv));
  EXPECT_TRUE(
      bad_input(r, scene + R"(:7:10: profile.radius: expected a number, got string "1 cm")"));
  EXPECT_TRUE(nothing_at(csv));
}

TEST_F(Cli, MalformedToml) {
  const std::string scene = bad_scene("springs = 100", "springs = 100\nsprings = 200");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(bad_input(r, scene + ":13:11: malformed TOML: error while parsing key-value pair: "
                                   "cannot redefine existing integer 'springs'"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, NewlineInAValueStaysOnOneLine) {
  const std::string scene = bad_scene(R"(type = "parabolic")", "type = \"\"\"para\nbolic\"\"\"");
  std::string known;
  for (const auto& name : Registries::builtin().profiles.names()) {
    known += (known.empty() ? "" : ", ") + name;
  }
  const auto r = run_mdrsim("run " + scene);
  EXPECT_TRUE(bad_input(
      r,
      fmt::format(
          R"({}:6:8: profile.type: unknown 'para\nbolic'; did you mean 'parabolic'? (known: {}))",
          scene, known)));
}

TEST_F(Cli, SceneFileThatIsADanglingLink) {
  // Unreadable as root too: the link points nowhere.
  fs::create_symlink("nowhere.toml", path("dangling.toml"));
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", path("dangling.toml"), json));
  EXPECT_TRUE(bad_input(
      r, path("dangling.toml") + ": cannot read the scene file (no such file or directory)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SceneFileInALinkLoop) {
  fs::create_symlink("loop2", path("loop1"));
  fs::create_symlink("loop1", path("loop2"));
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", path("loop1"), json));
  EXPECT_TRUE(bad_input(
      r, path("loop1") + ": cannot read the scene file (too many levels of symbolic links)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, EmptySceneFile) {
  const std::string scene = write("empty.toml", "");
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene, json));
  EXPECT_TRUE(bad_input(r, scene + ": material: missing, expected a table"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SceneFileThatIsNotUtf8OrHasANulByte) {
  const std::string json = path("out.json");
  const std::string latin1 = write("latin1.toml", "title = \"\xff\xfe\"\n");
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --json {}", latin1, json)),
                        latin1 + ":1:9: malformed TOML: encountered invalid utf-8 sequence"));
  const std::string nul = write("nul.toml", std::string("title = \"a\0b\"\n", 14));
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --json {}", nul, json)),
                        nul + ":1:11: malformed TOML: error while parsing string: unescaped "
                              "control characters other than TAB (U+0009) are explicitly "
                              "prohibited"));
  EXPECT_TRUE(nothing_at(json));
}

// ---- --set ----

TEST_F(Cli, SetWithoutEquals) {
  const std::string json = path("out.json");
  const auto r =
      run_mdrsim(fmt::format("run {} --set material.poisson_ratio --json {}", scene_, json));
  EXPECT_TRUE(bad_input(r, "--set: 'material.poisson_ratio' is not KEY=VALUE"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SetWithEmptyKey) {
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --set =0.3 --json {}", scene_, json));
  EXPECT_TRUE(bad_input(r, "--set: '=0.3' is not KEY=VALUE"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SetWithEmptyValue) {
  const auto r = run_mdrsim(fmt::format("run {} --set material.poisson_ratio=", scene_));
  EXPECT_TRUE(bad_input(r, "--set: material.poisson_ratio: the value is empty"));
}

TEST_F(Cli, SetOutOfRange) {
  const std::string json = path("out.json");
  const auto r =
      run_mdrsim(fmt::format("run {} --set material.poisson_ratio=0.7 --json {}", scene_, json));
  EXPECT_TRUE(bad_input(r, "--set: material.poisson_ratio = 0.7 is outside (-1, 0.5]"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SetNotANumber) {
  const auto r = run_mdrsim(fmt::format("run {} --set profile.radius=big", scene_));
  EXPECT_TRUE(bad_input(r, R"(--set: profile.radius: expected a number, got string "big")"));
}

TEST_F(Cli, SetUnknownKey) {
  const std::string json = path("out.json");
  const auto r =
      run_mdrsim(fmt::format("run {} --set material.poisson=0.3 --json {}", scene_, json));
  EXPECT_TRUE(bad_input(
      r,
      fmt::format("--set: material.poisson: unknown key; did you mean 'poisson_ratio'? (known: {})",
                  kMaterialKeys)));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, SetThroughAValue) {
  const auto r = run_mdrsim(fmt::format("run {} --set profile.radius.x=1", scene_));
  EXPECT_TRUE(bad_input(r, "--set: profile.radius.x: 'radius' is not a table"));
}

TEST_F(Cli, SetWithoutArgument) {
  const auto r = run_mdrsim(fmt::format("run {} --set", scene_));
  EXPECT_TRUE(bad_input(r, "--set: 1 required TEXT missing"));
}

/// `names` joined by ", ": the known-names lists come from the registries, so that a newly
/// registered part does not break the cases below.
std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Every key of the scene file of docs/scene.md through --set, each way a value can be wrong: of the
// wrong type, out of range, missing (a --set table without it) and unknown (a typo in each table).
// The file itself is checked key by key in tests/engine/scene/scene_loading_test.cpp; this checks
// that the command line turns each into exit code 2, exactly one line naming --set and the
// key, nothing on standard output and no JSON file left behind.
TEST_F(Cli, EveryKeyOfTheSceneWrongThroughSet) {
  const auto registries = Registries::builtin();
  const std::string profiles = joined(registries.profiles.names());
  const std::string criteria = joined(registries.criteria.names());
  const std::string controllers = joined(registries.controllers.names());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"title=[1]", "--set: title: expected a string, got an array"},
      {"x=1",
       "--set: x: unknown key (known: detachment, discretization, friction, loading, material, "
       "profile, solver, title)"},
      {"material.youngs_modulus=true",
       "--set: material.youngs_modulus: expected a number, got true"},
      {"material.youngs_modulus=-1", "--set: material.youngs_modulus = -1 is outside (0, inf)"},
      {"material.poisson_ratio=[0.3]",
       "--set: material.poisson_ratio: expected a number, got an array"},
      {"material.poisson_ratio=-1", "--set: material.poisson_ratio = -1 is outside (-1, 0.5]"},
      {"material.work_of_adhesion=abc",
       R"(--set: material.work_of_adhesion: expected a number, got string "abc")"},
      {"material.work_of_adhesion=-1", "--set: material.work_of_adhesion = -1 is outside [0, inf)"},
      {"material={ youngs_modulus = 1e6, poisson_ratio = 0.0 }",
       "--set: material.work_of_adhesion: missing, expected a number (work of adhesion dgamma "
       "[J/m^2], >= 0)"},
      {"material={ effective_modulus = \"x\", work_of_adhesion = 0.05 }",
       R"(--set: material.effective_modulus: expected a number, got string "x")"},
      {"material={ effective_modulus = 0, work_of_adhesion = 0.05 }",
       "--set: material.effective_modulus = 0 is outside (0, inf)"},
      {"material={ effective_modulus = 1e6, effective_shear_modulus = true, work_of_adhesion = "
       "0.05 }",
       "--set: material.effective_shear_modulus: expected a number, got true"},
      {"material={ effective_modulus = 1e6, effective_shear_modulus = -1, work_of_adhesion = "
       "0.05 }",
       "--set: material.effective_shear_modulus = -1 is outside (0, inf)"},
      {"material.youngs_modulu=1",
       fmt::format(
           "--set: material.youngs_modulu: unknown key; did you mean 'youngs_modulus'? (known: {})",
           kMaterialKeys)},
      {"profile.type=3", "--set: profile.type: expected a string, got 3"},
      {"profile.type=cone2",
       fmt::format("--set: profile.type: unknown 'cone2'; did you mean 'cone'? (known: {})",
                   profiles)},
      {"profile={ radius = 0.01 }",
       fmt::format("--set: profile.type: missing, expected a string (one of: {})", profiles)},
      {"profile.radius=[1]", "--set: profile.radius: expected a number, got an array"},
      {"profile.radius=0", "--set: profile.radius = 0 is outside (0, inf)"},
      {"profile.radus=1",
       "--set: profile.radus: unknown key; did you mean 'radius'? (known: radius, type)"},
      {"loading.x=1", "--set: loading.x: unknown key (known: normal, preload, tangential)"},
      {"loading.preload={}",
       "--set: loading.preload: give exactly one of depth [m], force [N] or contact_radius [m]"},
      {"loading.preload={ radius = 1 }",
       "--set: loading.preload.radius: unknown key (known: contact_radius, depth, force)"},
      {"loading.preload={ depth = \"deep\" }",
       R"(--set: loading.preload.depth: expected a number, got string "deep")"},
      {"loading.preload={ depth = 0 }", "--set: loading.preload.depth = 0 is outside (0, inf)"},
      {"loading.preload={ force = true }",
       "--set: loading.preload.force: expected a number, got true"},
      {"loading.preload={ force = -1 }", "--set: loading.preload.force = -1 is outside (0, inf)"},
      {"loading.preload={ contact_radius = [1] }",
       "--set: loading.preload.contact_radius: expected a number, got an array"},
      {"loading.preload={ contact_radius = -1 }",
       "--set: loading.preload.contact_radius = -1 is outside (0, inf)"},
      {"loading.tangential={ control = 1, displacement = 0 }",
       "--set: loading.tangential.control: expected a string, got 1"},
      {"loading.tangential={ control = \"fixed-grips\" }",
       "--set: loading.tangential.displacement: missing, expected a number (the held "
       "displacement [m])"},
      {"loading.tangential={ control = \"fixed-grips\", displacement = \"x\" }",
       R"(--set: loading.tangential.displacement: expected a number, got string "x")"},
      {"loading.tangential={ control = \"fixed-load\", force = \"x\" }",
       R"(--set: loading.tangential.force: expected a number, got string "x")"},
      {"loading.tangential={ control = \"fixed-load\", force = 1e308 }",
       "--set: loading.tangential.force = 1e+308 overflows F/F0 (the JKR scale is "
       "0.0023561944901923453 N)"},
      {"loading.tangential={ control = \"fixed-grips\", displacement = 0, x = 1 }",
       "--set: loading.tangential.x: unknown key (known: control, displacement, force)"},
      {"loading.normal.control=1", "--set: loading.normal.control: expected a string, got 1"},
      {"loading.normal.control=grips",
       fmt::format("--set: loading.normal.control: unknown 'grips' (known: {})", controllers)},
      {"loading.normal={ control = \"compliant\" }",
       "--set: loading.normal.stiffness: missing, expected a number (machine stiffness k "
       "[N/m])"},
      {"loading.normal={ control = \"compliant\", stiffness = \"k\" }",
       R"(--set: loading.normal.stiffness: expected a number, got string "k")"},
      {"loading.normal={ control = \"compliant\", stiffness = 0 }",
       "--set: loading.normal.stiffness = 0 is outside (0, inf)"},
      {"loading.normal={ control = \"compliant\", stiffness = 1, x = 1 }",
       "--set: loading.normal.x: unknown key (known: control, stiffness)"},
      {"detachment.criterion=2", "--set: detachment.criterion: expected a string, got 2"},
      {"detachment.criterion=stres",
       fmt::format(
           "--set: detachment.criterion: unknown 'stres'; did you mean 'stress'? (known: {})",
           criteria)},
      {"detachment.x=1", "--set: detachment.x: unknown key (known: criterion, front_speed_law)"},
      {"detachment={ criterion = \"mode-dependent\" }",
       "--set: detachment.lambda: missing, expected a number (mode sensitivity: 0 = "
       "normal-only, 1 = mode-mixed)"},
      {"detachment={ criterion = \"mode-dependent\", lambda = \"half\" }",
       R"(--set: detachment.lambda: expected a number, got string "half")"},
      {"detachment={ criterion = \"mode-dependent\", lambda = 2 }",
       "--set: detachment.lambda = 2 is outside [0, 1]"},
      {"discretization.springs=x",
       R"(--set: discretization.springs: expected a whole number, got string "x")"},
      {"discretization.springs=1.5", "--set: discretization.springs = 1.5 is not a whole number"},
      {"discretization.springs=0", "--set: discretization.springs = 0 is outside [1, 1000000000]"},
      {"discretization={ rtol = \"x\" }",
       R"(--set: discretization.rtol: expected a number, got string "x")"},
      {"discretization={ rtol = 1 }", "--set: discretization.rtol = 1 is outside [1e-12, 0.1]"},
      {"discretization.x=1",
       "--set: discretization.x: unknown key (known: extrapolation, rtol, springs)"},
      {"solver.method=1", "--set: solver.method: expected a string, got 1"},
      {"solver.method=events",
       "--set: solver.method: unknown 'events'; did you mean 'event'? (known: event, stepping, "
       "continuum)"},
      {"solver={ method = \"stepping\", step = \"s\" }",
       R"(--set: solver.step: expected a number, got string "s")"},
      {"solver={ method = \"stepping\", step = 0 }", "--set: solver.step = 0 is outside (0, inf)"},
      {"solver={ method = \"stepping\", max_halvings = \"3\" }",
       R"(--set: solver.max_halvings: expected a whole number, got string "3")"},
      {"solver={ method = \"stepping\", max_halvings = 61 }",
       "--set: solver.max_halvings = 61 is outside [0, 60]"},
      {"solver={ method = \"stepping\", max_steps = \"x\" }",
       R"(--set: solver.max_steps: expected a whole number, got string "x")"},
      {"solver={ method = \"stepping\", max_steps = 0 }",
       "--set: solver.max_steps = 0 is outside [1, 1000000000000000]"},
      {"solver.max_events=\"x\"",
       R"(--set: solver.max_events: expected a whole number, got string "x")"},
      {"solver.max_events=0", "--set: solver.max_events = 0 is outside [1, 1000000000000000]"},
      {"solver.max_events_per_spring=2.5",
       "--set: solver.max_events_per_spring = 2.5 is not a whole number"},
      {"solver.max_events_per_spring=2e9",
       "--set: solver.max_events_per_spring = 2000000000 is outside [1, 1000000000]"},
      {"solver={ method = \"continuum\", max_events = 10 }",
       "--set: solver.max_events: applies to method = \"event\" or \"stepping\" only"},
      {"solver.x=1",
       "--set: solver.x: unknown key (known: max_events, max_events_per_spring, max_halvings, "
       "max_steps, method, step)"},
  };
  const std::string json = path("out.json");
  for (const auto& [set, message] : cases) {
    const auto r =
        run_mdrsim(fmt::format("run {} --set {} --json {}", scene_, shell_word(set), json));
    EXPECT_TRUE(bad_input(r, message)) << "--set " << set;
    EXPECT_TRUE(nothing_at(json)) << "--set " << set;
  }
}

// ---- --vary ----

TEST_F(Cli, VaryBadSpecs) {
  const std::string csv = path("out.csv");
  const auto sweep = [&](const std::string& vary) {
    return run_mdrsim(fmt::format("sweep {} --vary {} --csv {}", scene_, shell_word(vary), csv));
  };
  const std::string forms = "KEY=FROM:TO:COUNT, KEY=FROM:TO:COUNT:log or KEY=V1,V2,...";
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=0:0.3"),
                        "--vary: 'material.poisson_ratio=0:0.3' is not " + forms));
  EXPECT_TRUE(bad_input(sweep("0:0.3:2"), "--vary: '0:0.3:2' is not " + forms));
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=0:0.3:1"),
                        "--vary: material.poisson_ratio: COUNT 1 gives one value, but FROM 0 and "
                        "TO 0.3 differ (give a COUNT of 2 or more, or one value)"));
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=0:0.3:3:log"),
                        "--vary: material.poisson_ratio: a log range needs FROM and TO of the "
                        "same sign and not zero, not 0 and 0.3"));
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=low:0.3:2"),
                        "--vary: material.poisson_ratio: FROM 'low' is not a finite number"));
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=0:high:2"),
                        "--vary: material.poisson_ratio: TO 'high' is not a finite number"));
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=0:0.3:0"),
                        "--vary: material.poisson_ratio: COUNT '0' is not a whole number from 1 "
                        "to 1000000"));
  EXPECT_TRUE(bad_input(sweep("material.poisson_ratio=0:0.3:2.5"),
                        "--vary: material.poisson_ratio: COUNT '2.5' is not a whole number from "
                        "1 to 1000000"));
  EXPECT_TRUE(bad_input(
      sweep("material.poisson=0:0.3:2"),
      fmt::format(
          "--vary: material.poisson: unknown key; did you mean 'poisson_ratio'? (known: {})",
          kMaterialKeys)));
  EXPECT_TRUE(bad_input(sweep("material..poisson_ratio=0:0.3:2"),
                        "--vary: 'material..poisson_ratio' is not a dotted scene key like "
                        "material.poisson_ratio"));
  EXPECT_TRUE(nothing_at(csv));
}

TEST_F(Cli, VaryValueOutOfRangeInsideTheSweep) {
  // The third of four values is outside; no run starts and no CSV appears.
  const std::string csv = path("out.csv");
  const auto r = run_mdrsim(
      fmt::format("sweep {} --vary material.poisson_ratio=0.2:0.8:4 --csv {}", scene_, csv));
  EXPECT_TRUE(bad_input(r,
                        "--vary: material.poisson_ratio = 0.6 is outside (-1, "
                        "0.5]"));
  EXPECT_TRUE(nothing_at(csv));
}

TEST_F(Cli, VaryWholeNumberKey) {
  const auto r =
      run_mdrsim(fmt::format("sweep {} --vary discretization.springs=10:20:4 --csv -", scene_));
  EXPECT_TRUE(bad_input(r,
                        "--vary: discretization.springs = 13.333333333333334 is not a whole "
                        "number"));
  const auto good =
      run_mdrsim(fmt::format("sweep {} --vary discretization.springs=10:20:3 --csv -", scene_));
  EXPECT_EQ(good.exit_code, 0) << good.err;
}

TEST_F(Cli, VaryMissing) {
  const auto r = run_mdrsim("sweep " + scene_);
  EXPECT_TRUE(bad_input(r, "mdrsim: --vary is required"));
}

// ---- flags ----

TEST_F(Cli, UnknownFlag) {
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --jsn {}", scene_, json));
  EXPECT_TRUE(bad_input(
      r, fmt::format("mdrsim: the following arguments were not expected: {} --jsn", json)));
  EXPECT_TRUE(nothing_at(json));
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --bogus", scene_)),
                        "mdrsim: the following argument was not expected: --bogus"));
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("sweep {} --vary a=0:1:2 --json -", scene_)),
                        "mdrsim: the following arguments were not expected: - --json"));
}

TEST_F(Cli, MissingOrUnknownSubcommand) {
  const std::string hint =
      "mdrsim: a command is required (run, sweep, merge, fit, list), e.g. mdrsim run SCENE.toml; "
      "see "
      "mdrsim --help";
  EXPECT_TRUE(bad_input(run_mdrsim(""), hint));
  EXPECT_TRUE(bad_input(run_mdrsim("--json -"), hint));
  EXPECT_TRUE(bad_input(run_mdrsim("simulate " + scene_),
                        "mdrsim: unknown command 'simulate' (known: "
                        "run, sweep, merge, fit, list; see mdrsim --help)"));
  EXPECT_TRUE(bad_input(run_mdrsim("run"), "mdrsim: scene is required"));
}

TEST_F(Cli, FlagGivenTwiceTakesTheLater) {
  // Every single-valued option of run and sweep: a command line appended to overrides.
  const auto r = run_mdrsim(fmt::format(
      "run {} --json {} --json {} --trajectory {} --trajectory {} --trajectory-stride 1 "
      "--trajectory-stride 2 --log-level off --log-level error",
      scene_, path("a.json"), path("b.json"), path("a.csv"), path("b.csv")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(nothing_at(path("a.json")));
  EXPECT_TRUE(nothing_at(path("a.csv")));
  EXPECT_TRUE(fs::exists(path("b.json")));
  EXPECT_TRUE(fs::exists(path("b.csv")));
  const auto s = run_mdrsim(
      fmt::format("sweep {} --vary material.poisson_ratio=0,0.3 --csv {} --csv {} --threads 1024 "
                  "--threads 1 --shard 1/2 --shard 0/1 --log-level off --log-level info",
                  scene_, path("a.csv"), path("c.csv")));
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_TRUE(nothing_at(path("a.csv")));
  EXPECT_TRUE(fs::exists(path("c.csv")));
  // The later --threads (1) and --shard (0/1: both rows) and --log-level (info) won.
  EXPECT_NE(s.err.find("sweep: 2 rows on 1 thread in"), std::string::npos) << s.err;
}

TEST_F(Cli, TrajectoryStrideWithoutTrajectory) {
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --trajectory-stride 10", scene_)),
                        "--trajectory-stride: thins --trajectory, which is not given"));
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --trajectory-stride 0", scene_)),
                        "--trajectory-stride: value 0 not in range 1 to 9223372036854775807"));
}

TEST_F(Cli, SweepThreadsFollowTheAffinityMask) {
  // As `taskset -c N` does: a mask of one CPU, which the command started from this thread
  // inherits. The default is then 1 thread however many the machine has.
  CommandResult r{};
  std::thread([&] {
    cpu_set_t mask;
    CPU_ZERO(&mask);
    ASSERT_EQ(sched_getaffinity(0, sizeof mask, &mask), 0);
    int first = 0;
    while (first < CPU_SETSIZE && !CPU_ISSET(first, &mask)) ++first;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    r = run_mdrsim(fmt::format("sweep {} --vary material.poisson_ratio=0,0.3 --csv {}", scene_,
                               path("out.csv")));
  }).join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("sweep: 2 rows on 1 thread in"), std::string::npos) << r.err;
}

TEST_F(Cli, FlagWithoutValue) {
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --log-level", scene_)),
                        "--log-level: 1 required TEXT:{trace,debug,info,warn,error,off} missing"));
}

TEST_F(Cli, EmptySceneFilePath) {
  EXPECT_TRUE(bad_input(run_mdrsim("run ''"), "mdrsim: the scene file path is empty"));
}

TEST_F(Cli, ThreadsZero) {
  const std::string csv = path("out.csv");
  const auto r = run_mdrsim(fmt::format(
      "sweep {} --vary material.poisson_ratio=0:0.3:2 --threads 0 --csv {}", scene_, csv));
  EXPECT_TRUE(bad_input(r, "--threads: value 0 not in range 1 to 1024"));
  EXPECT_TRUE(nothing_at(csv));
}

TEST_F(Cli, LogLevelLoud) {
  const std::string json = path("out.json");
  const auto r = run_mdrsim(fmt::format("run {} --log-level loud --json {}", scene_, json));
  EXPECT_TRUE(bad_input(r, "--log-level: loud not in {trace,debug,info,warn,error,off}"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, JsonIntoAMissingDirectory) {
  const std::string json = path("missing/out.json");
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene_, json));
  EXPECT_TRUE(bad_input(r, "--json: cannot write '" + json + "' (no such file or directory)"));
  EXPECT_TRUE(nothing_at(json));
}

TEST_F(Cli, TrajectoryIntoAMissingDirectoryLeavesNoJson) {
  // The JSON output is opened first; the failing trajectory must take it away again.
  const std::string json = path("out.json");
  const std::string trajectory = path("missing/trajectory.csv");
  const auto r =
      run_mdrsim(fmt::format("run {} --json {} --trajectory {}", scene_, json, trajectory));
  EXPECT_TRUE(
      bad_input(r, "--trajectory: cannot write '" + trajectory + "' (no such file or directory)"));
  EXPECT_TRUE(nothing_at(json));
  EXPECT_TRUE(nothing_at(trajectory));
}

TEST_F(Cli, JsonIntoADirectory) {
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene_, dir_));
  EXPECT_TRUE(bad_input(r, "--json: cannot write '" + dir_ + "' (it is a directory)"));
}

TEST_F(Cli, JsonAndTrajectoryBothOnStandardOutput) {
  const auto r = run_mdrsim(fmt::format("run {} --json - --trajectory -", scene_));
  EXPECT_TRUE(bad_input(r, "--trajectory: cannot share standard output with --json -"));
}

TEST_F(Cli, JsonAndTrajectoryInTheSameFile) {
  const std::string out = path("out.json");
  const auto r =
      run_mdrsim(fmt::format("run {} --json {} --trajectory {}/./out.json", scene_, out, dir_));
  EXPECT_TRUE(bad_input(r, "--trajectory: '" + dir_ + "/./out.json' is the --json output as well"));
  EXPECT_TRUE(nothing_at(out));
}

TEST_F(Cli, OutputOverTheSceneFile) {
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene_, scene_));
  EXPECT_TRUE(bad_input(r, "--json: '" + scene_ + "' is the scene file"));
  std::ifstream in(scene_);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), kScene);
}

TEST_F(Cli, EmptyOutputPath) {
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --json ''", scene_)),
                        "--json: needs a file path or -"));
  EXPECT_TRUE(bad_input(run_mdrsim(fmt::format("run {} --trajectory ''", scene_)),
                        "--trajectory: needs a file path or -"));
  EXPECT_TRUE(bad_input(
      run_mdrsim(fmt::format("sweep {} --vary material.poisson_ratio=0:0.3:2 --csv ''", scene_)),
      "--csv: needs a file path or -"));
}

// ---- good input ----

TEST_F(Cli, GoodRunExitsZero) {
  const auto r = run_mdrsim(fmt::format("run {}", scene_));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("status: "), std::string::npos) << r.out;
}

TEST_F(Cli, JsonOnStandardOutputIsOnlyJson) {
  const auto r = run_mdrsim(fmt::format("run {} --json - --log-level debug", scene_));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json json;
  ASSERT_NO_THROW(json = nlohmann::json::parse(r.out)) << r.out;
  EXPECT_TRUE(json.is_object());
  EXPECT_TRUE(json.contains("status"));
  EXPECT_TRUE(json.contains("critical"));
}

TEST_F(Cli, OutputFilesAppearWholeWithNoPartialLeft) {
  const std::string json = path("out.json");
  const std::string trajectory = path("trajectory.csv");
  const auto r =
      run_mdrsim(fmt::format("run {} --json {} --trajectory {} --set {}", scene_, json, trajectory,
                             shell_word("loading.normal.control=fixed-grips")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  std::ifstream in(json);
  EXPECT_TRUE(nlohmann::json::accept(in));
  EXPECT_TRUE(fs::exists(trajectory));
  EXPECT_FALSE(fs::exists(json + ".partial"));
  EXPECT_FALSE(fs::exists(trajectory + ".partial"));
}

TEST_F(Cli, GoodSweepWritesOneRowPerValue) {
  const std::string csv = path("out.csv");
  const auto r = run_mdrsim(fmt::format(
      "sweep {} --vary material.poisson_ratio=0:0.5:3 --threads 2 --csv {}", scene_, csv));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(csv);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 5);  // the identity line, the header and 3 rows
  EXPECT_FALSE(fs::exists(csv + ".partial"));
}

TEST_F(Cli, FifoIsWrittenInPlaceNotReplaced) {
  // Renaming a finished file over a device or pipe would replace it (as root even /dev/null).
  const std::string fifo = path("fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo);
    received.assign(std::istreambuf_iterator<char>(in), {});
  });
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene_, fifo));
  // Unblocks the reader if mdrsim never opened the fifo.
  if (const int fd = open(fifo.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) close(fd);
  reader.join();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::accept(received)) << received;
  EXPECT_EQ(fs::status(fifo).type(), fs::file_type::fifo);
  EXPECT_FALSE(fs::exists(fifo + ".partial"));
}

TEST_F(Cli, SymlinkedOutputKeepsItsLink) {
  fs::create_directory(path("results"));
  fs::create_symlink("results/out.json", path("out.json"));
  const auto r = run_mdrsim(fmt::format("run {} --json {}", scene_, path("out.json")));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(path("out.json")));
  std::ifstream in(path("results/out.json"));
  EXPECT_TRUE(nlohmann::json::accept(in));
  EXPECT_FALSE(fs::exists(path("results/out.json.partial")));
}

TEST_F(Cli, HelpExitsZero) {
  for (const char* args : {"--help", "run --help", "sweep --help", "merge --help"}) {
    const auto r = run_mdrsim(args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << args << ": " << r.out;
    EXPECT_TRUE(r.err.empty()) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace mdrsim::test

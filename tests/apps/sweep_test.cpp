// mdrsim sweep and merge through the binary: grids, lists and log ranges; shards run as
// separate processes and merged byte for byte; a sweep killed midway and resumed.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

namespace fs = std::filesystem;

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

/// The columns after the varied keys, for a parabolic scene (it has JKR scales).
constexpr std::string_view kColumns =
    "normal_force,tangential_force,contact_radius,indentation,tangential_displacement,"
    "springs_in_contact,dimensionless_normal_force,dimensionless_tangential_force,"
    "dimensionless_contact_radius,dimensionless_indentation,"
    "dimensionless_tangential_displacement,peak_normal_force,dimensionless_peak_normal_force,"
    "tangential_strength,critical_error_estimate,springs,glued_radius,preload_depth,preload_force,"
    "warnings,disk_valid";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

/// The mdrsim binary started with `args` (no shell), from the source folder; standard
/// output and error go to `out` and `err`.
class Process {
 public:
  Process(const std::vector<std::string>& args, const std::string& out, const std::string& err) {
    std::vector<std::string> all{MDRSIM_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
      const int in = open("/dev/null", O_RDONLY);
      const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (in < 0 || o < 0 || e < 0 || chdir(MDRSIM_SOURCE_DIR) != 0) _exit(126);
      dup2(in, 0);
      dup2(o, 1);
      dup2(e, 2);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  ~Process() {
    if (pid_ > 0 && !waited_) {
      kill(pid_, SIGKILL);
      wait();
    }
  }

  void signal(int number) const { ::kill(pid_, number); }
  /// The exit code, or 128 + the signal that ended it.
  int wait() {
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    waited_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  pid_t pid_ = -1;
  bool waited_ = false;
};

class Sweep : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir();
    scene_ = path("scene.toml");
    std::ofstream(scene_) << kScene;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  /// The sweep's arguments for a scene and its flags, then `extra`.
  std::vector<std::string> sweep_args(const std::vector<std::string>& flags,
                                      const std::vector<std::string>& extra = {},
                                      const std::string& log_level = "off") const {
    std::vector<std::string> args{"sweep", scene_, "--log-level", log_level};
    args.insert(args.end(), flags.begin(), flags.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }
  /// Runs mdrsim to the end; its exit code.
  int run(const std::vector<std::string>& args, const std::string& name = "run") const {
    Process p(args, path(name + ".out"), path(name + ".err"));
    return p.wait();
  }
  std::string err(const std::string& name = "run") const { return slurp(path(name + ".err")); }

  std::string dir_;
  std::string scene_;
};

// ---- grids, lists and log ranges ----

TEST_F(Sweep, TwoKeysGiveTheirProductTheLastFastest) {
  const std::string csv = path("grid.csv");
  ASSERT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.3:2", "--vary",
                            "detachment.criterion=mode-mixed,stress,deformation", "--csv", csv})),
            0)
      << err();
  const auto lines = lines_of(slurp(csv));
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[0].rfind("# mdrsim sweep: scene ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(", rows 6, shard 0/1"), std::string::npos) << lines[0];
  EXPECT_EQ(
      lines[1],
      fmt::format("status,stop_reason,material.poisson_ratio,detachment.criterion,{}", kColumns));
  const std::vector<std::pair<std::string, std::string>> expected{
      {"0", "mode-mixed"},   {"0", "stress"},   {"0", "deformation"},
      {"0.3", "mode-mixed"}, {"0.3", "stress"}, {"0.3", "deformation"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto fields = split(lines[i + 2]);
    ASSERT_EQ(fields.size(), split(lines[1]).size()) << lines[i + 2];
    EXPECT_EQ(fields[0], "instability") << lines[i + 2];
    EXPECT_EQ(fields[1], "") << lines[i + 2];
    EXPECT_EQ(fields[2], expected[i].first) << lines[i + 2];
    EXPECT_EQ(fields[3], expected[i].second) << lines[i + 2];
  }
  // nu changes the critical point; without a tangential load the criteria agree.
  EXPECT_NE(split(lines[2])[4], split(lines[5])[4]);
  EXPECT_EQ(split(lines[2])[4], split(lines[3])[4]);
}

TEST_F(Sweep, ListOfNamesAndOfNumbers) {
  const std::string csv = path("list.csv");
  ASSERT_EQ(run(sweep_args({"--vary", "loading.normal.control=fixed-load,fixed-grips", "--vary",
                            "discretization.springs=100,2e2", "--csv", csv})),
            0)
      << err();
  const auto lines = lines_of(slurp(csv));
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[1].rfind("status,stop_reason,loading.normal.control,discretization.springs,", 0),
            0u);
  const char* controls[] = {"fixed-load", "fixed-load", "fixed-grips", "fixed-grips"};
  const char* springs[] = {"100", "200", "100", "200"};
  for (int i = 0; i < 4; ++i) {
    const auto fields = split(lines[i + 2]);
    EXPECT_EQ(fields[2], controls[i]);
    EXPECT_EQ(fields[3], springs[i]);
  }
  // Fixed grips jump off at 5/9 of the fixed-load pull-off force (JKR): about -0.56 F0.
  const double fixed_load = std::stod(split(lines[3])[10]);
  const double fixed_grips = std::stod(split(lines[5])[10]);
  EXPECT_NEAR(fixed_load, -1.0, 0.02);
  EXPECT_NEAR(fixed_grips, -5.0 / 9.0, 0.02);
}

TEST_F(Sweep, LogSpacedValues) {
  const std::string csv = path("log.csv");
  ASSERT_EQ(run(sweep_args({"--vary", "discretization.springs=100:10000:3:log", "--vary",
                            "profile.radius=1e-3:1e-1:5:log", "--csv", csv})),
            0)
      << err();
  const auto lines = lines_of(slurp(csv));
  ASSERT_EQ(lines.size(), 17u);
  std::vector<std::string> springs, radii;
  for (std::size_t i = 2; i < lines.size(); ++i) {
    springs.push_back(split(lines[i])[2]);
    radii.push_back(split(lines[i])[3]);
  }
  EXPECT_EQ(springs[0], "100");
  EXPECT_EQ(springs[5], "1000");
  EXPECT_EQ(springs[14], "10000");
  const std::vector<std::string> five(radii.begin(), radii.begin() + 5);
  EXPECT_EQ(five[0], "0.001");
  EXPECT_EQ(five[4], "0.1");
  EXPECT_NEAR(std::stod(five[2]), 0.01, 1e-17);
  EXPECT_NEAR(std::stod(five[1]) / std::stod(five[0]), std::sqrt(10.0), 1e-12);
  EXPECT_EQ(std::vector<std::string>(radii.begin() + 10, radii.end()), five);
}

TEST_F(Sweep, BadValuesFailBeforeTheCsvExists) {
  const std::string csv = path("bad.csv");
  EXPECT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.3:3", "--vary",
                            "detachment.criterion=mode-mixed,stres", "--csv", csv})),
            2);
  EXPECT_EQ(err(),
            "--vary: detachment.criterion: unknown 'stres'; did you mean 'stress'? (known: "
            "deformation, mode-dependent, "
            "mode-mixed, normal-only, stress)\n");
  EXPECT_FALSE(fs::exists(csv));
  // A long range checks its first, second and last values before any run.
  EXPECT_EQ(run(sweep_args({"--vary", "discretization.springs=10:21:100", "--csv", csv})), 2);
  EXPECT_EQ(err(), "--vary: discretization.springs = 10.111111111111112 is not a whole number\n");
  EXPECT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.6:100", "--csv", csv})), 2);
  EXPECT_EQ(err(), "--vary: material.poisson_ratio = 0.6 is outside (-1, 0.5]\n");
  EXPECT_FALSE(fs::exists(csv));
  EXPECT_EQ(run(sweep_args({"--vary", "a.b=0:1:2", "--vary", "a.b=1,2", "--csv", csv})), 2);
  EXPECT_EQ(err(), "--vary: a.b is varied twice\n");
  EXPECT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.3:1", "--csv", csv})), 2);
  EXPECT_EQ(err(),
            "--vary: material.poisson_ratio: COUNT 1 gives one value, but FROM 0 and TO 0.3 "
            "differ (give a COUNT of 2 or more, or one value)\n");
  EXPECT_FALSE(fs::exists(csv));
}

TEST_F(Sweep, ValueBadOnlyWithAnotherKeysValueFailsWhenItsRowRuns) {
  // Each value is fine with the other key's first value: a sphere of 0.1 mm cannot hold the
  // preload's contact radius of 0.5 mm, a paraboloid can. The rows before it are kept.
  const std::string csv = path("combination.csv");
  EXPECT_EQ(run(sweep_args({"--vary", "profile.type=parabolic,sphere", "--vary",
                            "profile.radius=0.01,1e-4", "--threads", "2", "--csv", csv})),
            2);
  EXPECT_EQ(err(), fmt::format("{}:9:30: loading.preload.contact_radius = 0.0005 is beyond the "
                               "profile's edge at 0.0001\n",
                               scene_));
  const auto lines = lines_of(slurp(csv));
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[4].rfind("instability,,sphere,0.01,", 0), 0u) << lines[4];
}

TEST_F(Sweep, BadShardOrResumeFlags) {
  const std::string csv = path("out.csv");
  for (const char* shard : {"3/3", "1", "-1/2", "0/0", "a/b", "1/2/3"}) {
    EXPECT_EQ(run(sweep_args(
                  {"--vary", "material.poisson_ratio=0:0.3:2", "--shard", shard, "--csv", csv})),
              2)
        << shard;
    EXPECT_EQ(err(), fmt::format("--shard: '{}' is not I/N with 0 <= I < N <= 1000000\n", shard));
  }
  EXPECT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.3:2", "--resume"})), 2);
  EXPECT_EQ(err(), "--resume: needs --csv PATH (a sweep on standard output cannot resume)\n");
  EXPECT_FALSE(fs::exists(csv));
}

TEST_F(Sweep, AnExistingCsvIsKeptUnlessResumeOrForce) {
  // A sweep run again onto the CSV of a longer one must not leave its few rows in place of
  // the thousands there were, with exit 0.
  const std::string csv = path("grid.csv");
  ASSERT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.3:4", "--csv", csv})), 0)
      << err();
  const std::string before = slurp(csv);
  ASSERT_EQ(lines_of(before).size(), 2u + 4u);
  const std::vector<std::string> small{"--vary", "material.poisson_ratio=0,0.3"};
  EXPECT_EQ(run(sweep_args(small, {"--csv", csv})), 2);
  EXPECT_EQ(err(), fmt::format("--csv: '{}' exists (--resume finishes the sweep in it, --force "
                               "replaces it)\n",
                               csv));
  EXPECT_EQ(slurp(csv), before);
  EXPECT_EQ(run(sweep_args(small, {"--csv", csv, "--force", "--resume"})), 2);
  EXPECT_EQ(err(), "--force: replaces the CSV that --resume finishes; give one of them\n");
  EXPECT_EQ(slurp(csv), before);
  ASSERT_EQ(run(sweep_args(small, {"--csv", csv, "--force"})), 0) << err();
  EXPECT_EQ(lines_of(slurp(csv)).size(), 2u + 2u);
  // An empty file (mktemp's) and a device hold no rows: written without --force.
  const std::string empty = path("empty.csv");
  std::ofstream{empty};
  ASSERT_EQ(run(sweep_args(small, {"--csv", empty})), 0) << err();
  EXPECT_EQ(lines_of(slurp(empty)).size(), 2u + 2u);
  EXPECT_EQ(run(sweep_args(small, {"--csv", "/dev/null"})), 0) << err();
}

// ---- linked keys, --where and random designs ----

/// A program whose approach work of adhesion must not exceed its work of adhesion (the scene
/// refuses dgamma_a > dgamma): a product grid of the two breaks on its first such row.
constexpr std::string_view kProgram = R"([material]
effective_modulus = 1.0e6
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
name = "press"
normal = { control = "fixed-grips", to = 2e-5 }
[[loading.stage]]
name = "pull"
normal = { control = "fixed-grips", by = -4e-5 }
until = "separation"
[discretization]
springs = 100
)";

TEST_F(Sweep, LinkedKeysAndWhereRunOnlyTheRowsAScenePermits) {
  std::ofstream(scene_) << kProgram;
  const std::string dgamma = "material.work_of_adhesion=0.01:0.04:4";
  const std::string approach = "material.approach_work_of_adhesion=0.01:0.04:4";
  const std::string csv = path("rows.csv");
  // The product reaches dgamma_a = 0.02 > dgamma = 0.01 among the values it checks first.
  EXPECT_EQ(run(sweep_args({"--vary", dgamma, "--vary", approach, "--csv", csv})), 2);
  EXPECT_EQ(err(),
            "--vary: material.approach_work_of_adhesion = 0.02 is above work_of_adhesion = 0.01 "
            "(0 <= dgamma_a <= dgamma)\n");
  EXPECT_FALSE(fs::exists(csv));
  // --where: the 10 rows of the lower triangle, in the product's order.
  ASSERT_EQ(run(sweep_args({"--vary", dgamma, "--vary", approach, "--where",
                            "material.approach_work_of_adhesion <= material.work_of_adhesion",
                            "--csv", csv})),
            0)
      << err();
  auto lines = lines_of(slurp(csv));
  ASSERT_EQ(lines.size(), 2u + 10u);
  EXPECT_NE(lines[0].find(", rows 10, shard 0/1"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1].rfind("status,stop_reason,material.work_of_adhesion,"
                           "material.approach_work_of_adhesion,normal_force,",
                           0),
            0u)
      << lines[1];
  const char* values[] = {"0.01", "0.02", "0.03", "0.04"};
  std::size_t line = 2;
  for (int g = 0; g < 4; ++g) {
    for (int a = 0; a <= g; ++a, ++line) {
      const auto fields = split(lines[line]);
      EXPECT_EQ(fields[2], values[g]) << lines[line];
      EXPECT_EQ(fields[3], values[a]) << lines[line];
      EXPECT_EQ(fields[0], "instability") << lines[line];
    }
  }
  // --link: dgamma_a = dgamma / 2 on one axis of 4 rows, the columns as for the product.
  ASSERT_EQ(
      run(sweep_args({"--vary", dgamma, "--link", "material.approach_work_of_adhesion=0.005:0.02:4",
                      "--csv", csv, "--force"})),
      0)
      << err();
  lines = lines_of(slurp(csv));
  ASSERT_EQ(lines.size(), 2u + 4u);
  const char* halves[] = {"0.005", "0.01", "0.015", "0.02"};
  for (int g = 0; g < 4; ++g) {
    EXPECT_EQ(split(lines[2 + g])[2], values[g]);
    EXPECT_EQ(split(lines[2 + g])[3], halves[g]);
  }
  // Shards of a filtered grid merge into the unsharded CSV.
  const std::vector<std::string> filtered{
      "--vary", dgamma,    "--vary",
      approach, "--where", "material.approach_work_of_adhesion <= material.work_of_adhesion"};
  ASSERT_EQ(run(sweep_args(filtered, {"--csv", csv, "--force"})), 0) << err();
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(run(sweep_args(filtered, {"--shard", fmt::format("{}/3", i), "--csv",
                                        path(fmt::format("part{}.csv", i))})),
              0)
        << err();
  }
  ASSERT_EQ(
      run({"merge", path("merged.csv"), path("part2.csv"), path("part0.csv"), path("part1.csv")}),
      0)
      << err();
  EXPECT_EQ(slurp(path("merged.csv")), slurp(csv));
}

TEST_F(Sweep, RandomDesignIsReproducibleInsideItsBoundsAndResumable) {
  const std::vector<std::string> design{"--vary",    "material.poisson_ratio=0:0.45",
                                        "--vary",    "profile.radius=1e-3:1e-1:log",
                                        "--design",  "random",
                                        "--samples", "9",
                                        "--seed",    "42"};
  const std::string first = path("first.csv");
  ASSERT_EQ(run(sweep_args(design, {"--csv", first, "--threads", "2"})), 0) << err();
  const std::string text = slurp(first);
  const auto lines = lines_of(text);
  ASSERT_EQ(lines.size(), 2u + 9u);
  EXPECT_NE(lines[0].find(", rows 9, shard 0/1"), std::string::npos) << lines[0];
  for (std::size_t i = 2; i < lines.size(); ++i) {
    const auto fields = split(lines[i]);
    EXPECT_EQ(fields[0], "instability") << lines[i];
    const double nu = std::stod(fields[2]);
    const double radius = std::stod(fields[3]);
    EXPECT_TRUE(nu >= 0.0 && nu <= 0.45) << lines[i];
    EXPECT_TRUE(radius >= 1e-3 && radius <= 1e-1) << lines[i];
  }
  // The same seed: the same CSV, on any thread count; another seed: other rows.
  const std::string again = path("again.csv");
  ASSERT_EQ(run(sweep_args(design, {"--csv", again, "--threads", "1"})), 0) << err();
  EXPECT_EQ(slurp(again), text);
  std::vector<std::string> reseeded = design;
  reseeded.back() = "43";
  ASSERT_EQ(run(sweep_args(reseeded, {"--csv", again, "--force"})), 0) << err();
  EXPECT_NE(lines_of(slurp(again))[2], lines[2]);
  EXPECT_NE(lines_of(slurp(again))[0], lines[0]);
  // Cut after 4 rows (and a torn fifth) and resumed: the uninterrupted CSV.
  std::string cut;
  for (std::size_t i = 0; i < 6; ++i) cut += lines[i] + "\n";
  std::ofstream(again, std::ios::binary) << cut << lines[6].substr(0, 9);
  ASSERT_EQ(run(sweep_args(design, {"--csv", again, "--resume"})), 0) << err();
  EXPECT_EQ(slurp(again), text);
  // Another seed is another sweep: --resume refuses it.
  std::ofstream(again, std::ios::binary) << cut;
  EXPECT_EQ(run(sweep_args(reseeded, {"--csv", again, "--resume"})), 2);
  EXPECT_NE(err().find("is a sweep of another grid"), std::string::npos) << err();
  // A Latin hypercube of 9 rows: one in each ninth of each range.
  const std::string latin = path("latin.csv");
  std::vector<std::string> hypercube = design;
  hypercube[5] = "latin";
  ASSERT_EQ(run(sweep_args(hypercube, {"--csv", latin})), 0) << err();
  std::vector<int> nu_strata(9, 0), radius_strata(9, 0);
  const auto latin_lines = lines_of(slurp(latin));
  ASSERT_EQ(latin_lines.size(), 2u + 9u);
  for (std::size_t i = 2; i < latin_lines.size(); ++i) {
    const auto fields = split(latin_lines[i]);
    ++nu_strata[static_cast<std::size_t>(std::stod(fields[2]) / 0.45 * 9.0)];
    ++radius_strata[static_cast<std::size_t>(std::log(std::stod(fields[3]) / 1e-3) /
                                             std::log(100.0) * 9.0)];
  }
  EXPECT_EQ(nu_strata, std::vector<int>(9, 1));
  EXPECT_EQ(radius_strata, std::vector<int>(9, 1));
}

TEST_F(Sweep, BadDesignFlagsExit2WithOneLineNamingTheFlag) {
  const std::string csv = path("bad.csv");
  const std::string nu = "material.poisson_ratio=0:0.3:3";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--vary", nu, "--link", "profile.radius=0.01,0.02"},
       "--link: profile.radius has 2 values, material.poisson_ratio has 3 (a linked key needs "
       "as many as the key it varies with)"},
      {{"--link", "profile.radius=0.01,0.02,0.03", "--vary", nu},
       "--link: profile.radius follows no --vary (a linked key varies with the --vary before it)"},
      {{"--vary", nu, "--where", "material.poisson_ratio < profile.radius"},
       "--where: profile.radius is not a varied key (known: material.poisson_ratio)"},
      {{"--vary", nu, "--where", "material.poisson_ratio"},
       "--where: 'material.poisson_ratio' is not A OP B (OP one of <=, <, >=, >, ==, !=; A and "
       "B a varied key, a number or NUMBER*KEY)"},
      {{"--vary", nu, "--where", "material.poisson_ratio > 1"},
       "--where: no row of the 3 candidates passes material.poisson_ratio > 1"},
      {{"--vary", nu, "--design", "sobol"},
       "--design: unknown 'sobol' (known: grid, latin, random)"},
      {{"--vary", nu, "--design", "random", "--samples", "4"},
       "--vary: material.poisson_ratio: a random design draws from FROM:TO or FROM:TO:log, not "
       "a COUNT ('3')"},
      {{"--vary", "material.poisson_ratio=0:0.3", "--design", "latin"},
       "--samples: --design latin needs --samples N"},
      {{"--vary", "material.poisson_ratio=0:0.3", "--design", "random", "--samples", "ten"},
       "--samples: 'ten' is not a whole number from 1 to 100000000 (--design random)"},
      {{"--vary", "material.poisson_ratio=0:0.3", "--design", "random", "--samples", "3", "--seed",
        "1.5"},
       "--seed: '1.5' is not a whole number from 0 to 18446744073709551615"},
      {{"--vary", nu, "--seed", "3"},
       "--seed: a grid draws nothing (--seed belongs to --design random or latin)"},
      {{"--vary", "material.poisson_ratio=0:0.3"},
       "--vary: 'material.poisson_ratio=0:0.3' is not KEY=FROM:TO:COUNT, KEY=FROM:TO:COUNT:log "
       "or KEY=V1,V2,..."},
      // A drawn range's values are checked before any run: the row of its largest draw.
      {{"--vary", "material.poisson_ratio=0:0.7", "--design", "random", "--samples", "20"},
       "--vary: material.poisson_ratio = 0.6"},
  };
  for (const auto& [flags, message] : cases) {
    EXPECT_EQ(run(sweep_args(flags, {"--csv", csv})), 2) << message;
    const std::string text = err();
    EXPECT_EQ(text.rfind(message, 0), 0u) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    EXPECT_FALSE(fs::exists(csv)) << message;
  }
}

// ---- shards and merge ----

TEST_F(Sweep, ShardsRunAsSeparateProcessesMergeIntoTheUnshardedCsv) {
  // 7 x 3 = 21 rows in 4 shards of 6, 5, 5 and 5 rows; the shards run at the same time.
  const std::vector<std::string> grid{"--vary", "material.poisson_ratio=0:0.45:7", "--vary",
                                      "loading.preload.contact_radius=3e-4,5e-4,8e-4"};
  const std::string whole = path("whole.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--threads", "2", "--csv", whole})), 0) << err();
  std::vector<std::unique_ptr<Process>> shards;
  std::vector<std::string> files;
  for (int i = 0; i < 4; ++i) {
    files.push_back(path(fmt::format("shard{}.csv", i)));
    shards.push_back(std::make_unique<Process>(
        sweep_args(grid,
                   {"--shard", fmt::format("{}/4", i), "--threads", "1", "--csv", files.back()}),
        path(fmt::format("shard{}.out", i)), path(fmt::format("shard{}.err", i))));
  }
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(shards[i]->wait(), 0) << slurp(path(fmt::format("shard{}.err", i)));
  }
  EXPECT_EQ(lines_of(slurp(files[0])).size(), 2u + 6u);
  EXPECT_EQ(lines_of(slurp(files[3])).size(), 2u + 5u);
  EXPECT_NE(slurp(files[2]).find(", rows 21, shard 2/4\n"), std::string::npos);
  // Any order of the shards.
  const std::string merged = path("merged.csv");
  ASSERT_EQ(run({"merge", merged, files[2], files[0], files[3], files[1]}), 0) << err();
  const std::string expected = slurp(whole);
  EXPECT_EQ(lines_of(expected).size(), 23u);
  EXPECT_EQ(slurp(merged), expected);
  EXPECT_FALSE(fs::exists(merged + ".partial"));
  // Standard output, and a shard row by row: row r is row r / 4 of shard r % 4.
  ASSERT_EQ(run({"merge", "-", files[1], files[0], files[2], files[3]}, "stdout"), 0);
  EXPECT_EQ(slurp(path("stdout.out")), expected);
  const auto rows = lines_of(expected);
  const auto shard1 = lines_of(slurp(files[1]));
  for (std::size_t k = 2; k < shard1.size(); ++k) EXPECT_EQ(shard1[k], rows[2 + 1 + 4 * (k - 2)]);
}

TEST_F(Sweep, SlurmScriptRunsOneShardPerArrayTaskAndMerges) {
  // scripts/slurm_sweep.sh as SLURM runs it: one process per array task, then the merge.
  const std::string grid =
      "--vary material.poisson_ratio=0:0.45:5 --vary discretization.springs=100,200";
  const std::string whole = path("whole.csv");
  ASSERT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.45:5", "--vary",
                            "discretization.springs=100,200", "--csv", whole})),
            0)
      << err();
  const std::string out = path("slurm.csv");
  const auto script = [&](const std::string& env, const std::string& args) {
    return std::system(fmt::format("cd '{}' && {} MDRSIM='{}' bash scripts/slurm_sweep.sh {} "
                                   ">'{}' 2>&1 </dev/null",
                                   MDRSIM_SOURCE_DIR, env, MDRSIM_BINARY, args, path("slurm.log"))
                           .c_str());
  };
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(script(fmt::format("SLURM_ARRAY_TASK_ID={} SLURM_ARRAY_TASK_COUNT=3 "
                                 "SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=2",
                                 i),
                     fmt::format("shard '{}' '{}' {} --log-level off", out, scene_, grid)),
              0)
        << slurp(path("slurm.log"));
    EXPECT_TRUE(fs::exists(path(fmt::format("slurm.shard-{}-of-3.csv", i))));
  }
  ASSERT_EQ(script("", fmt::format("merge '{}'", out)), 0) << slurp(path("slurm.log"));
  EXPECT_EQ(slurp(out), slurp(whole));
  // An array that is not 0..N-1 cannot be mapped to shards.
  EXPECT_NE(script("SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=2 SLURM_ARRAY_TASK_MIN=1 "
                   "SLURM_ARRAY_TASK_MAX=2",
                   fmt::format("shard '{}' '{}' {}", out, scene_, grid)),
            0);
}

TEST_F(Sweep, SlurmScriptFromAnyFolderWithJobOptionsNeverWaitsOnAMissingShard) {
  // From a folder other than the repository, with the installed mdrsim (on PATH, no MDRSIM)
  // and sbatch stubbed: it logs its arguments and the MDRSIM the jobs get, and says job 4242.
  // The merge job logs to mdrsim-sweep-4242_merge.log, beside its array's tasks: for a job
  // outside an array the directive's %a is SLURM's "no index", 4294967294.
  const std::string bin = path("bin");
  fs::create_directories(bin);
  fs::create_symlink(MDRSIM_BINARY, bin + "/mdrsim");
  std::ofstream(bin + "/sbatch") << "#!/bin/sh\necho \"MDRSIM=$MDRSIM $*\" >>'"
                                 << path("sbatch.log") << "'\necho 4242\n";
  fs::permissions(bin + "/sbatch", fs::perms::owner_all);
  const std::string grid = "--vary material.poisson_ratio=0:0.45:5";
  const auto script = [&](const std::string& env, const std::string& args) {
    return std::system(fmt::format("cd '{}' && env -u MDRSIM PATH='{}':\"$PATH\" {} bash '{}' {} "
                                   ">'{}' 2>&1 </dev/null",
                                   dir_, bin, env, MDRSIM_SOURCE_DIR "/scripts/slurm_sweep.sh",
                                   args, path("slurm.log"))
                           .c_str());
  };
  ASSERT_EQ(script("", fmt::format("submit --account=acct --time=4:00:00 2 out.csv '{}' {}", scene_,
                                   grid)),
            0)
      << slurp(path("slurm.log"));
  const std::string mdrsim = fs::canonical(MDRSIM_BINARY).string();
  EXPECT_EQ(lines_of(slurp(path("sbatch.log"))),
            (std::vector<std::string>{
                fmt::format("MDRSIM={} --parsable --account=acct --time=4:00:00 --array=0-1 {} "
                            "shard out.csv {} {}",
                            mdrsim, MDRSIM_SOURCE_DIR "/scripts/slurm_sweep.sh", scene_, grid),
                fmt::format("MDRSIM={} --account=acct --time=4:00:00 --dependency=afterany:4242 "
                            "--job-name=mdrsim-merge --output=mdrsim-sweep-4242_merge.log "
                            "--cpus-per-task=1 {} merge out.csv 2",
                            mdrsim, MDRSIM_SOURCE_DIR "/scripts/slurm_sweep.sh")}));
  // Task 1 of 2 ran out of time before it wrote anything: the merge names it and stops.
  ASSERT_EQ(script("SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=2",
                   fmt::format("shard out.csv '{}' {} --log-level off", scene_, grid)),
            0)
      << slurp(path("slurm.log"));
  const int status = script("", "merge out.csv 2");
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << slurp(path("slurm.log"));
  EXPECT_NE(
      slurp(path("slurm.log")).find("1 of 2 shards have no CSV (out.shard-I-of-2.csv for I = 1)"),
      std::string::npos)
      << slurp(path("slurm.log"));
  EXPECT_FALSE(fs::exists(path("out.csv")));
  // A shard cut short (a task killed at its time limit): mdrsim merge names it.
  ASSERT_EQ(script("SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=2",
                   fmt::format("shard out.csv '{}' {} --log-level off", scene_, grid)),
            0);
  const std::string shard = path("out.shard-1-of-2.csv");
  const std::string text = slurp(shard);
  std::ofstream(shard, std::ios::trunc) << text.substr(0, text.rfind('\n', text.size() - 2) + 1);
  EXPECT_NE(script("", "merge out.csv 2"), 0);
  EXPECT_NE(slurp(path("slurm.log")).find("(shard 1/2) has 1 of its 2 rows"), std::string::npos)
      << slurp(path("slurm.log"));
  // Finished again (--resume), the merge goes through.
  ASSERT_EQ(script("SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=2",
                   fmt::format("shard out.csv '{}' {} --log-level off", scene_, grid)),
            0);
  EXPECT_EQ(script("", "merge out.csv 2"), 0) << slurp(path("slurm.log"));
  EXPECT_EQ(lines_of(slurp(path("out.csv"))).size(), 7u);  // identity, header, 5 rows
}

TEST_F(Sweep, MoreShardsThanRowsLeaveSomeEmpty) {
  const std::vector<std::string> grid{"--vary", "material.poisson_ratio=0,0.2"};
  const std::string whole = path("whole.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--csv", whole})), 0) << err();
  std::vector<std::string> args{"merge", path("merged.csv")};
  for (int i = 0; i < 3; ++i) {
    args.push_back(path(fmt::format("s{}.csv", i)));
    ASSERT_EQ(run(sweep_args(grid, {"--shard", fmt::format("{}/3", i), "--csv", args.back()})), 0)
        << err();
  }
  EXPECT_EQ(lines_of(slurp(args.back())).size(), 2u);  // identity and header only
  ASSERT_EQ(run(args), 0) << err();
  EXPECT_EQ(slurp(path("merged.csv")), slurp(whole));
}

TEST_F(Sweep, MergeRefusesShardsThatDoNotMakeOneSweep) {
  const std::vector<std::string> grid{"--vary", "material.poisson_ratio=0:0.45:5"};
  std::vector<std::string> s;
  for (int i = 0; i < 3; ++i) {
    s.push_back(path(fmt::format("s{}.csv", i)));
    ASSERT_EQ(run(sweep_args(grid, {"--shard", fmt::format("{}/3", i), "--csv", s.back()})), 0);
  }
  const std::string other_grid = path("other_grid.csv");
  ASSERT_EQ(run(sweep_args({"--vary", "material.poisson_ratio=0:0.45:6", "--shard", "2/3", "--csv",
                            other_grid})),
            0);
  const std::string other_scene = path("other_scene.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--set", "material.youngs_modulus=2e6", "--shard", "2/3", "--csv",
                                  other_scene})),
            0);
  const std::string whole = path("whole.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--csv", whole})), 0);
  const std::string out = path("out.csv");
  const auto refused = [&](const std::vector<std::string>& shards, const std::string& message) {
    std::vector<std::string> args{"merge", out};
    args.insert(args.end(), shards.begin(), shards.end());
    EXPECT_EQ(run(args), 2) << message;
    EXPECT_EQ(err(), message + "\n");
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".partial"));
  };
  const auto q = [](const std::string& p) { return "'" + p + "'"; };
  refused({s[0], s[2]}, "merge: shard 1/3 is missing");
  refused({s[0], s[1], s[2], s[1]},
          fmt::format("merge: {} and {} are both shard 1/3", q(s[1]), q(s[1])));
  refused({s[0], s[1], other_grid},
          fmt::format("merge: {} is a sweep of another grid than {}", q(other_grid), q(s[0])));
  refused({s[0], s[1], other_scene},
          fmt::format("merge: {} is a sweep of another scene than {}", q(other_scene), q(s[0])));
  refused({s[0], whole},
          fmt::format("merge: {} is shard 0/1, but {} is shard 0/3", q(whole), q(s[0])));
  refused({scene_}, fmt::format("merge: {} is not a sweep CSV (its first line is not '# mdrsim "
                                "sweep: ...')",
                                q(scene_)));
  refused({path("none.csv")},
          fmt::format("merge: cannot read {} (no such file or directory)", q(path("none.csv"))));
  // A shard cut short, also inside its last line.
  const std::string text = slurp(s[1]);
  std::ofstream(s[1], std::ios::binary) << text.substr(0, text.size() - 5);
  refused({s[0], s[1], s[2]},
          fmt::format("merge: {} (shard 1/3) has 1 of its 2 rows; mdrsim sweep --resume "
                      "finishes it",
                      q(s[1])));
  EXPECT_EQ(run({"merge", s[0], s[0]}), 2);
  EXPECT_EQ(err(), fmt::format("merge: OUT {} is one of the shards\n", q(s[0])));
}

// ---- a sweep killed midway, and --resume ----

/// A sweep slow enough to be killed midway: 100 rows of 2e5 springs (about 8 ms each), so
/// that once a few rows are in its CSV the rest takes long past the signal.
constexpr int kSlowRows = 100;
std::vector<std::string> slow_grid() {
  return {"--vary", fmt::format("material.poisson_ratio=0:0.45:{}", kSlowRows), "--set",
          "discretization.springs=200000"};
}

/// Complete rows after the identity line and header; -1 while the header is not whole.
int rows_in(const std::string& path) {
  const std::string text = slurp(path);
  const auto newlines = std::count(text.begin(), text.end(), '\n');
  return newlines < 2 ? -1 : static_cast<int>(newlines - 2);
}

/// Starts the sweep, waits for `rows` rows in its CSV, then sends `signal`; the exit code.
int kill_midway(const std::vector<std::string>& args, const std::string& csv, int rows, int signal,
                const std::string& err) {
  Process p(args, err + ".out", err);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (rows_in(csv) < rows && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  p.signal(signal);
  return p.wait();
}

TEST_F(Sweep, KilledMidwayThenResumedEqualsAnUninterruptedSweep) {
  const std::string reference = path("reference.csv");
  ASSERT_EQ(run(sweep_args(slow_grid(), {"--threads", "1", "--csv", reference})), 0) << err();
  const std::string expected = slurp(reference);
  ASSERT_EQ(lines_of(expected).size(), 2u + kSlowRows);

  const std::string csv = path("killed.csv");
  const auto args = sweep_args(slow_grid(), {"--threads", "2", "--csv", csv}, "warn");
  EXPECT_EQ(kill_midway(args, csv, 3, SIGTERM, path("killed.err")), 143);
  // Every row it finished is there, whole, and they are the uninterrupted sweep's first rows.
  const std::string partial = slurp(csv);
  const int kept = rows_in(csv);
  EXPECT_GE(kept, 3);
  EXPECT_LT(kept, kSlowRows) << "the sweep ended before the signal: nothing was tested";
  ASSERT_FALSE(partial.empty());
  EXPECT_EQ(partial.back(), '\n');
  EXPECT_EQ(expected.substr(0, partial.size()), partial);
  EXPECT_NE(slurp(path("killed.err"))
                .find(fmt::format("[warning] sweep: stopped by SIGTERM with {} of {} rows in "
                                  "'{}'; --resume finishes it\n",
                                  kept, kSlowRows, csv)),
            std::string::npos)
      << slurp(path("killed.err"));

  // A torn last line (a kill during a write, a full disk) is cut off and its row redone.
  std::ofstream(csv, std::ios::app | std::ios::binary) << "instability,0.3,-0.0023";
  ASSERT_EQ(run(sweep_args(slow_grid(), {"--threads", "2", "--csv", csv, "--resume"})), 0) << err();
  EXPECT_EQ(slurp(csv), expected);
  // Resuming a complete CSV runs nothing and changes nothing.
  ASSERT_EQ(run(sweep_args(slow_grid(), {"--csv", csv, "--resume"})), 0) << err();
  EXPECT_EQ(slurp(csv), expected);
}

TEST_F(Sweep, InterruptedByCtrlCExits130WithWholeRows) {
  const std::string csv = path("interrupted.csv");
  const auto args = sweep_args(slow_grid(), {"--threads", "2", "--csv", csv});
  EXPECT_EQ(kill_midway(args, csv, 2, SIGINT, path("interrupted.err")), 130);
  const std::string partial = slurp(csv);
  EXPECT_GE(rows_in(csv), 2);
  EXPECT_LT(rows_in(csv), kSlowRows);
  EXPECT_EQ(partial.back(), '\n');
  ASSERT_EQ(run(sweep_args(slow_grid(), {"--threads", "1", "--csv", csv, "--resume"})), 0) << err();
  EXPECT_EQ(rows_in(csv), kSlowRows);
  EXPECT_EQ(slurp(csv).substr(0, partial.size()), partial);
}

TEST_F(Sweep, ResumeStartsAMissingCsvAndFinishesAShardsCsv) {
  const std::vector<std::string> grid{"--vary", "material.poisson_ratio=0:0.45:7"};
  const std::string whole = path("whole.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--shard", "1/2", "--csv", whole})), 0) << err();
  const std::string csv = path("resumed.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--shard", "1/2", "--csv", csv, "--resume"})), 0) << err();
  EXPECT_EQ(slurp(csv), slurp(whole));
  // Cut to its identity line and header, and to part of the header: both are finished.
  const std::string text = slurp(whole);
  const auto header_end = text.find('\n', text.find('\n') + 1) + 1;
  for (const std::size_t cut : {header_end, header_end - 10, std::size_t{0}}) {
    std::ofstream(csv, std::ios::binary) << text.substr(0, cut);
    ASSERT_EQ(run(sweep_args(grid, {"--shard", "1/2", "--csv", csv, "--resume"})), 0) << err();
    EXPECT_EQ(slurp(csv), text) << cut;
  }
}

TEST_F(Sweep, ResumeRefusesACsvOfAnotherSceneGridOrShard) {
  const std::vector<std::string> grid{"--vary", "material.poisson_ratio=0:0.45:4"};
  const std::string csv = path("out.csv");
  ASSERT_EQ(run(sweep_args(grid, {"--csv", csv})), 0) << err();
  std::string text = slurp(csv);
  std::string same_values;  // the grid's values, as a list
  for (std::size_t i = 2; i < 6; ++i) {
    same_values += (i == 2 ? "" : ",") + split(lines_of(text)[i])[2];
  }
  text.resize(text.rfind('\n', text.size() - 2) + 1);  // one row short
  std::ofstream(csv, std::ios::binary) << text;
  const auto identity = lines_of(text)[0];
  const auto hex = [&](const char* after) {
    const auto at = identity.find(after) + std::string_view(after).size();
    return identity.substr(at, 16);
  };
  const auto refused = [&](const std::vector<std::string>& args, const std::string& message) {
    EXPECT_EQ(run(args), 2) << message;
    EXPECT_EQ(err(), message + "\n");
    EXPECT_EQ(slurp(csv), text) << "the refused CSV was changed";
  };
  const std::string name = "'" + csv + "'";

  // Another scene: a --set, or the scene file changed.
  const auto other_scene =
      sweep_args(grid, {"--set", "material.youngs_modulus=2e6", "--csv", csv, "--resume"});
  ASSERT_EQ(
      run(sweep_args(grid, {"--set", "material.youngs_modulus=2e6", "--csv", path("probe.csv")})),
      0);
  const std::string other_hex = lines_of(slurp(path("probe.csv")))[0].substr(22, 16);
  refused(other_scene,
          fmt::format("--resume: {} is a sweep of another scene (scene {}; this one is {})", name,
                      hex("scene "), other_hex));
  // Another grid: other values, or another key.
  const auto other_grid = [&](const std::string& vary) {
    return sweep_args({"--vary", vary}, {"--csv", csv, "--resume"});
  };
  EXPECT_EQ(run(other_grid("material.poisson_ratio=0:0.45:5")), 2);
  EXPECT_EQ(err().rfind(fmt::format("--resume: {} is a sweep of another grid (grid {} of 4 rows; "
                                    "this one is ",
                                    name, hex("grid ")),
                        0),
            0u)
      << err();
  EXPECT_NE(err().find(" of 5 rows)\n"), std::string::npos) << err();
  EXPECT_EQ(run(other_grid("material.youngs_modulus=1e6,2e6,3e6,4e6")), 2);
  EXPECT_NE(err().find("is a sweep of another grid"), std::string::npos) << err();
  EXPECT_EQ(slurp(csv), text);
  // Another shard.
  refused(sweep_args(grid, {"--shard", "0/2", "--csv", csv, "--resume"}),
          fmt::format("--resume: {} is shard 0/1; this sweep is shard 0/2", name));
  // Not a sweep CSV at all: the scene file itself, then a trajectory.
  const std::string trajectory = path("trajectory.csv");
  ASSERT_EQ(run({"run", scene_, "--trajectory", trajectory, "--log-level", "off"}), 0);
  EXPECT_EQ(run(sweep_args(grid, {"--csv", trajectory, "--resume"})), 2);
  EXPECT_EQ(err(), fmt::format("--resume: '{}' is not a sweep CSV (its first line is not '# "
                               "mdrsim sweep: ...')\n",
                               trajectory));
  // The same values written another way are the same grid: the CSV is finished.
  ASSERT_EQ(run(other_grid("material.poisson_ratio=" + same_values)), 0) << err();
  EXPECT_EQ(lines_of(slurp(csv)).size(), 6u);
}

}  // namespace
}  // namespace mdrsim::test

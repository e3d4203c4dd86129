// --trajectory-stride: every K-th ordinary row and every row that matters; the size warning.
#include "engine/output/trajectory_stride.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "engine/output/trajectory_estimate.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

using cli::TrajectoryStride;

/// The springs of the events passed on (each test numbers its events by `spring`).
class Recorder final : public Observer {
 public:
  void on_event(const Event& e) override {
    if (e.kind != EventKind::finished) springs.push_back(e.spring);
  }
  std::vector<std::int64_t> springs;
};

Event ordinary(std::int64_t n, bool in_cascade = false) {
  return Event{
      .kind = EventKind::spring_detached, .state = {}, .spring = n, .in_cascade = in_cascade};
}

TEST(TrajectoryStride, EveryKthOrdinaryRowAndTheLast) {
  // 25 rows at stride 10: rows 0, 10, 20 (ceil(25/10) = 3) and the last, 24.
  Recorder out;
  TrajectoryStride stride(out, 10);
  for (int n = 0; n < 25; ++n) stride.on_event(ordinary(n));
  stride.on_event(Event{.kind = EventKind::finished, .state = {}});
  EXPECT_EQ(out.springs, (std::vector<std::int64_t>{0, 10, 20, 24}));
}

TEST(TrajectoryStride, StrideOneWritesEverything) {
  Recorder out;
  TrajectoryStride stride(out, 1);
  for (int n = 0; n < 5; ++n) stride.on_event(ordinary(n, n == 3));
  stride.finish();
  EXPECT_EQ(out.springs, (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
}

TEST(TrajectoryStride, SpecialRowsAndCascadeEndsAreAlwaysWritten) {
  // Rows 0-4 plain; 5 starts a cascade that rows 6-9 continue (in_cascade); 10-14 plain,
  // with a stage end (row 12) and a jump (row 13) among them.
  Recorder out;
  TrajectoryStride stride(out, 100);
  for (int n = 0; n < 15; ++n) {
    if (n == 12) {
      stride.on_event(Event{.kind = EventKind::stage_end, .state = {}, .spring = n});
    } else if (n == 13) {
      stride.on_event(Event{.kind = EventKind::jump, .state = {}, .spring = n});
    } else {
      stride.on_event(ordinary(n, n >= 6 && n <= 9));
    }
  }
  stride.finish();
  // 0: the first ordinary row; 5 and 9: the cascade's first and last; 12, 13: special
  // kinds; 14: the last row.
  EXPECT_EQ(out.springs, (std::vector<std::int64_t>{0, 5, 9, 12, 13, 14}));
}

TEST(TrajectoryStride, TheStageOfAHeldRowOutlivesTheEvent) {
  Recorder out;
  std::vector<std::string> names;
  struct Stages final : Observer {
    std::vector<std::string>* names;
    void on_event(const Event& e) override {
      if (e.kind != EventKind::finished) names->emplace_back(e.stage);
    }
  } stages;
  stages.names = &names;
  TrajectoryStride stride(stages, 2);
  {
    std::string stage = "approach";
    Event e = ordinary(0);
    e.stage = stage;
    stride.on_event(e);
    e.spring = 1;
    stride.on_event(e);  // held
    stage = "xxxxxxxx";  // the engine's storage changes
  }
  stride.finish();
  EXPECT_EQ(names, (std::vector<std::string>{"approach", "approach"}));
}

TEST(TrajectoryEstimate, RowsFromSpringsAndStagesBytesFromATypicalRow) {
  Scene scene;
  scene.springs = 1'000'000'000;
  const cli::TrajectoryEstimate e = cli::estimate_trajectory(scene, 1);
  EXPECT_EQ(e.rows, 1e9);  // one detachment per spring in the shorthand's pull-off
  // The row the writer formats for such a scene, written out by hand: 3 full-precision
  // values, no tangential load, 10 digits of springs.
  const std::string row =
      "pull-off,detached,0,-1.2345678901234567e-05,-1.2345678901234567e-05,"
      "-1.2345678901234567e-05,0,0,1000000000\n";
  EXPECT_EQ(e.bytes_per_row, static_cast<double>(row.size()));
  EXPECT_EQ(cli::estimate_trajectory(scene, 1000).rows, 1e6);
  const auto warning = cli::large_trajectory_warning(scene, 1);
  ASSERT_TRUE(warning.has_value());
  EXPECT_EQ(*warning,
            fmt::format("--trajectory: the file will be about {:.3g} GB (1e+09 rows of about {} "
                        "bytes: 1000000000 springs, 1 stage, stride 1); --trajectory-stride {} "
                        "writes about 100 MB",
                        1e9 * static_cast<double>(row.size()) / 1e9, row.size(),
                        static_cast<int>(std::ceil(1e9 * static_cast<double>(row.size()) / 1e8))));
  // 1e9 bytes is the threshold: 1e6 springs give some 100 MB, no warning.
  scene.springs = 1'000'000;
  EXPECT_FALSE(cli::large_trajectory_warning(scene, 1).has_value());
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, ',');) out.push_back(f);
  return out;
}

TEST(TrajectoryStrideCommand, KeepsEveryKthOrdinaryRowAndEveryRowThatMatters) {
  // A JKR cycle: a cascade in (glue on touch), one out, two stage ends and the critical state.
  const std::string dir = make_temp_dir();
  const std::string all = dir + "/all.csv";
  const std::string some = dir + "/some.csv";
  const std::string scene = "scenes/programs/jkr_cycle_reversible.toml";
  ASSERT_EQ(
      run_mdrsim(fmt::format("run {} --set discretization.springs=300 --trajectory {}", scene, all))
          .exit_code,
      0);
  const auto r = run_mdrsim(
      fmt::format("run {} --set discretization.springs=300 --trajectory {} --trajectory-stride 7",
                  scene, some));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("--trajectory: the file will be"), std::string::npos) << r.err;
  // The rows stride 7 must keep, read off the full trajectory by looking ahead one row.
  const std::vector<std::string> full = lines_of(all);
  const std::set<std::string> ordinary_kinds{"detached", "glued", "touched",
                                             "lifted",   "step",  "halved"};
  std::vector<std::string> expected{full[0]};
  std::size_t ordinary = 0;
  for (std::size_t i = 1; i < full.size(); ++i) {
    const auto f = fields(full[i]);
    const bool special = ordinary_kinds.count(f[1]) == 0;
    const bool last = i + 1 == full.size();
    const bool cascade_edge = !last && fields(full[i + 1])[2] != f[2];
    const bool kth = !special && ordinary++ % 7 == 0;
    if (special || kth || cascade_edge || last) expected.push_back(full[i]);
  }
  const std::vector<std::string> kept = lines_of(some);
  EXPECT_EQ(kept, expected);
  EXPECT_LT(kept.size(), full.size() / 3);  // and it does thin: ~600 rows to ~90
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mdrsim::test

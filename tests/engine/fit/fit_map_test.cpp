// The map runner: fits in input order whatever the threads, a bad curve keeps its status, and
// an exception stops the run.
#include "engine/fit/fit_map.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/fit/tip_shape.hpp"
#include "engine/measured/read_force_curves.hpp"

namespace mdrsim::fit {
namespace {

namespace fs = std::filesystem;
const fs::path kData = MDRSIM_AFM_DATA_DIR;

std::vector<measured::MeasuredFile> two_files() {
  std::vector<measured::MeasuredFile> files;
  files.push_back(
      measured::read_force_curves(kData / "fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data"));
  files.push_back(measured::read_force_curves(kData / "fmt-jpk-fd_spot3-0192.jpk-force"));
  // A curve of the map that could not be read, and one without a retract.
  measured::ForceCurve unreadable = files[0].curves[1];
  unreadable.label = "index/7";
  unreadable.segments.clear();
  unreadable.unreadable = "segment 0 (extend): empty (no samples)";
  files[0].curves.push_back(unreadable);
  measured::ForceCurve approach_only = files[0].curves[3];
  approach_only.label = "index/8";
  approach_only.segments.resize(1);
  files[0].curves.push_back(approach_only);
  return files;
}

CurveFitOptions jkr() {
  CurveFitOptions options;
  options.model = FitModel::jkr;
  options.tip = parse_tip("parabolic:radius=1e-5");
  return options;
}

TEST(FitCurves, ThreadsGiveTheFitsOfOneThreadInInputOrder) {
  const auto files = two_files();
  const auto curves = every_curve(files);
  ASSERT_EQ(curves.size(), 7U);
  std::vector<std::string> reports[2];
  std::vector<std::string> dumps[2];
  for (int t = 0; t < 2; ++t) {
    MapRun run;
    run.threads = t == 0 ? 1 : 3;
    run.on_fit = [&](std::size_t position, const CurveFit& fit) {
      reports[t].push_back(std::to_string(position) + " " + fit.curve);
    };
    std::size_t last = 0;
    run.on_progress = [&](std::size_t reported) { EXPECT_EQ(reported, ++last); };
    for (const CurveFit& fit :
         fit_curves(files, curves, measured::SegmentKind::retract, jkr(), run)) {
      dumps[t].push_back(curve_fit_json(fit, jkr(), measured::SegmentKind::retract).dump());
    }
    EXPECT_EQ(last, curves.size());
  }
  EXPECT_EQ(dumps[0], dumps[1]);
  EXPECT_EQ(reports[0], reports[1]);
  EXPECT_EQ(reports[0].front(), "0 index/0");
  EXPECT_EQ(reports[0].back(), "6 ");
  // The bad curves keep their statuses and reasons; the curves after them are fitted.
  const auto fits = fit_curves(files, curves, measured::SegmentKind::retract, jkr(), MapRun{2});
  EXPECT_EQ(fits[4].fit.status, FitStatus::unreadable);
  EXPECT_EQ(fits[4].fit.message, "segment 0 (extend): empty (no samples)");
  EXPECT_EQ(fits[5].fit.status, FitStatus::unreadable);
  EXPECT_EQ(fits[5].fit.message.rfind("index/8: ", 0), 0U) << fits[5].fit.message;
  EXPECT_EQ(fits[6].fit.status, FitStatus::fitted);
}

TEST(FitCurves, AnExceptionOfACallbackStopsTheRunAndIsRethrown) {
  const auto files = two_files();
  MapRun run;
  run.threads = 2;
  run.on_fit = [](std::size_t position, const CurveFit&) {
    if (position == 2) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(
      {
        try {
          fit_curves(files, every_curve(files), measured::SegmentKind::approach,
                     CurveFitOptions{FitModel::hertz, parse_tip("parabolic:radius=1e-5")}, run);
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "disk full");
          throw;
        }
      },
      std::runtime_error);
}

}  // namespace
}  // namespace mdrsim::fit

// The plain route of rtol for programs; one frame (a_max) for every row, so that the rows
// differ only in their spacing.
#include "engine/run/program_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/run/run_program.hpp"

namespace mdrsim {
namespace {

constexpr std::int64_t kFirstRow = 256;
constexpr int kRowsBeforeAccepting = 4;
/// Forces below this share of the path's largest are held to it in absolute terms.
constexpr double kForceFloor = 1e-6;

/// What must match for rows to be compared quantity by quantity.
std::string ending(const RunResult& r) {
  std::string s = to_string(r.status);
  s += fmt::format(" {} stages", r.stages.size());
  for (const JumpRecord& j : r.jumps) s += fmt::format(" {}:{}", j.stage, j.inward ? "in" : "out");
  s += r.critical ? " critical" : "";
  s += r.peak ? " peak" : "";
  return s;
}

/// A checked force of a row and the force of its edge spring there [N].
struct Checked {
  double* value;
  double edge;
};

/// The checked forces of a row, in a fixed order; pointers into the row.
std::vector<Checked> checked(RunResult& r) {
  std::vector<Checked> q;
  const auto normal = [&](ContactSnapshot& s) {
    q.push_back({&s.normal_force, s.edge_normal_force});
  };
  for (StageRecord& s : r.stages) {
    normal(s.end);
    q.push_back({&s.end.tangential_force, s.end.edge_tangential_force});
  }
  for (JumpRecord& j : r.jumps) {
    normal(j.critical);
    normal(j.after);
  }
  if (r.critical) normal(*r.critical);
  if (r.peak) normal(*r.peak);
  return q;
}

/// Estimates per checked force of the last row, from the last three rows. The differences
/// bound the error that falls with the spacing; the edge spring's force bounds the sawtooth
/// of the front's place between two springs, which differences of rows can miss when two
/// rows happen to put the front alike (a stage end at a let-go front did: 0.238017,
/// 0.237967, 0.238015 F0 at 16000, 64000, 256000 springs against 0.238026).
std::vector<double> estimates(std::vector<RunResult>& rows) {
  const std::size_t n = rows.size();
  const auto q0 = checked(rows[n - 3]);
  const auto q1 = checked(rows[n - 2]);
  const auto q2 = checked(rows[n - 1]);
  std::vector<double> e(q2.size());
  for (std::size_t i = 0; i < q2.size(); ++i) {
    e[i] = 2.0 * std::max(std::abs(*q2[i].value - *q1[i].value),
                          0.5 * std::abs(*q1[i].value - *q0[i].value)) +
           q2[i].edge;
  }
  return e;
}

/// Writes the estimates into the row's records, in checked()'s order.
void attach(RunResult& r, const std::vector<double>& e) {
  std::size_t i = 0;
  for (StageRecord& s : r.stages) {
    s.normal_force_error_estimate = e[i++];
    s.tangential_force_error_estimate = e[i++];
  }
  for (JumpRecord& j : r.jumps) {
    j.critical_error_estimate = e[i++];
    j.after_error_estimate = e[i++];
  }
  if (r.critical) r.accuracy.critical_error_estimate = e[i++];
  if (r.peak) r.accuracy.peak_error_estimate = e[i++];
}

}  // namespace

RunResult run_program_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const ProgramRowFrame frame = program_row_frame(scene);
  std::vector<RunResult> rows;
  std::vector<std::int64_t> springs;
  RunCounts counts;
  std::vector<double> last_estimates;
  bool met = false;
  std::string why;
  for (std::int64_t n = kFirstRow;; n *= 2) {
    ProgramRowSpec spec = program_row(frame, n);
    spec.edge_forces = true;
    rows.push_back(run_program_row(scene, spec, {}));
    springs.push_back(n);
    counts += rows.back().counts;
    if (rows.size() > 3) rows.erase(rows.begin());
    const std::size_t k = rows.size();
    if (k == 3 && ending(rows[0]) == ending(rows[1]) && ending(rows[1]) == ending(rows[2])) {
      last_estimates = estimates(rows);
      double largest = 0.0;
      const auto values = checked(rows.back());
      for (const Checked& q : values) largest = std::max(largest, std::abs(*q.value));
      met = true;
      for (std::size_t i = 0; i < values.size(); ++i) {
        const double scale = std::max(std::abs(*values[i].value), kForceFloor * largest);
        if (last_estimates[i] > rtol * scale) met = false;
      }
      if (met && static_cast<int>(springs.size()) >= kRowsBeforeAccepting) break;
      why = "the forces still differ across rows by more than rtol";
    } else if (k == 3) {
      last_estimates.clear();
      met = false;
      why = fmt::format("the rows of {}, {} and {} springs end differently ({}; {}; {})",
                        springs[springs.size() - 3], springs[springs.size() - 2], n,
                        ending(rows[0]), ending(rows[1]), ending(rows[2]));
    }
    if (2 * n > scene.discretization.max_row_springs) {
      met = false;
      break;
    }
  }
  // The finest row again, for its events (the rows above ran without observers).
  RunResult result = observers.empty()
                         ? std::move(rows.back())
                         : run_program_row(scene, program_row(frame, springs.back()), observers);
  if (!last_estimates.empty()) attach(result, last_estimates);
  result.counts = counts;
  result.accuracy.route = Accuracy::Route::row;
  result.accuracy.rows.assign(springs.end() - std::min<std::ptrdiff_t>(3, springs.size()),
                              springs.end());
  result.accuracy.outer_radius = frame.radius;
  result.accuracy.rtol_met = met;
  if (!met) {
    result.warnings.push_back(fmt::format(
        "rtol = {} not met with rows of up to {} springs: {}; the finest row is reported", rtol,
        springs.back(), why.empty() ? "too few rows" : why));
  }
  return result;
}

}  // namespace mdrsim

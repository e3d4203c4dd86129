// Accuracy on programs: rows in one frame (a_max), so that they differ only in their spacing;
// each reported state from the plain finest row or from Richardson across the last three.
#include "engine/run/program_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/run/row_sequence.hpp"
#include "engine/run/run_program.hpp"

namespace mdrsim {
namespace {

using Extrapolation = DiscretizationOptions::Extrapolation;

constexpr std::int64_t kFirstRow = 256;
/// The rows rtol compares: four, so that each estimate compares two differences (a plain
/// row's sawtooth can make two rows alike by chance).
constexpr std::size_t kRowsKept = 4;
/// Forces below this share of the path's largest are held to it in absolute terms.
constexpr double kForceFloor = 1e-6;
/// No estimate is below the rounding of the sums behind a value.
constexpr double kRounding = 1e-13;

const char* jump_end_name(JumpEnd end) {
  switch (end) {
    case JumpEnd::separated:
      return " (separated)";
    case JumpEnd::sliding:
      return " (sliding)";
    case JumpEnd::pressed:
      return " (pressed)";
    case JumpEnd::state:
      break;
  }
  return "";
}

/// What must match for rows to be compared state by state, item by item: the status, the
/// stages, every jump, the critical point and the peak.
std::vector<std::string> ending_items(const RunResult& r) {
  std::vector<std::string> items{to_string(r.status), fmt::format("{} stages", r.stages.size())};
  for (std::size_t i = 0; i < r.jumps.size(); ++i) {
    const JumpRecord& j = r.jumps[i];
    items.push_back(fmt::format("jump {} {} in '{}'{}", i + 1, j.inward ? "in" : "out", j.stage,
                                jump_end_name(j.end)));
  }
  items.emplace_back(r.critical ? "a critical point" : "no critical point");
  items.emplace_back(r.peak ? "a peak" : "no peak");
  return items;
}

bool end_alike(const RunResult& a, const RunResult& b) {
  return ending_items(a) == ending_items(b);
}

/// Where the first two of the rows (springs, result) that end differently part, in one short
/// phrase: a long program's rows list hundreds of jumps, most of them alike.
std::string first_difference(const std::vector<std::pair<std::int64_t, const RunResult*>>& rows) {
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const auto a = ending_items(*rows[k - 1].second);
    const auto b = ending_items(*rows[k].second);
    if (a == b) continue;
    std::size_t i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
    const std::size_t ja = rows[k - 1].second->jumps.size();
    const std::size_t jb = rows[k].second->jumps.size();
    return fmt::format("first apart between {} and {} springs: {} against {}{}", rows[k - 1].first,
                       rows[k].first, i < a.size() ? a[i] : "nothing",
                       i < b.size() ? b[i] : "nothing",
                       ja != jb ? fmt::format("; {} against {} jumps", ja, jb) : "");
  }
  return "they end alike";
}

/// A reported state of a row: where its value, its location between springs and its
/// estimates live in the row's result.
struct StateRef {
  std::string what;
  ContactSnapshot* state;
  const std::optional<ContactSnapshot>* located;  ///< null where rows never locate it
  std::optional<double>* normal_estimate;
  std::optional<double>* tangential_estimate;  ///< stage ends only
};

/// The reported states of a row in a fixed order: stage ends, jumps (critical point, after),
/// the critical point, the peak.
std::vector<StateRef> states(RunResult& r) {
  std::vector<StateRef> q;
  for (StageRecord& s : r.stages) {
    q.push_back({fmt::format("the end of stage '{}'", s.name), &s.end, &s.refined_end,
                 &s.normal_force_error_estimate, &s.tangential_force_error_estimate});
  }
  for (JumpRecord& j : r.jumps) {
    // A jump from no contact starts where the first spring touches: smooth in the spacing.
    const auto* located = j.critical.springs_in_contact == 0 ? nullptr : &j.refined_critical;
    q.push_back({fmt::format("the critical point of the jump in stage '{}'", j.stage), &j.critical,
                 located, &j.critical_error_estimate, nullptr});
    // A flight has no state after it (SPEC "A fixed load that loses the contact").
    if (j.end == JumpEnd::state) {
      q.push_back({fmt::format("the state after the jump in stage '{}'", j.stage), &j.after,
                   &j.refined_after, &j.after_error_estimate, nullptr});
    }
  }
  if (r.critical) {
    q.push_back({"the critical point", &*r.critical, &r.refined_critical,
                 &r.accuracy.critical_error_estimate, nullptr});
  }
  if (r.peak) {
    q.push_back({"the peak", &*r.peak, &r.refined_peak, &r.accuracy.peak_error_estimate, nullptr});
  }
  return q;
}

/// One state's value and estimates as the last three rows give it.
struct Choice {
  ContactSnapshot value;
  double normal_error;
  double tangential_error;
  bool extrapolated;
};

/// The plain estimate 2 max(|Q2 - Q1|, |Q1 - Q0| / 2) plus the edge spring's force, which
/// bounds the front's place between two springs (two rows can put it alike by chance: a
/// stage end at a let-go front gave 0.238017, 0.237967, 0.238015 F0 at 16000, 64000, 256000
/// springs against 0.238026).
double plain_error(double q0, double q1, double q2, double edge) {
  return 2.0 * std::max(std::abs(q2 - q1), 0.5 * std::abs(q1 - q0)) + edge;
}

/// Richardson 2 Q(2N) - Q(N) from the two finest rows of `located` (the states as the rows
/// located them between springs, coarsest first), its estimate twice the change from the
/// value of the pair before, or with four rows (as the shorthand's rtol) twice the larger of
/// the last change and half the one before.
Choice richardson(const std::vector<const ContactSnapshot*>& located,
                  const ContactSnapshot& reported) {
  std::vector<ContactSnapshot> r;
  for (std::size_t j = 1; j < located.size(); ++j) {
    r.push_back(extrapolate(*located[j - 1], *located[j]));
  }
  ContactSnapshot value = r.back();
  value.springs_in_contact = reported.springs_in_contact;
  value.edge_normal_force = reported.edge_normal_force;
  value.edge_tangential_force = reported.edge_tangential_force;
  const auto error = [&](double ContactSnapshot::*q) {
    const std::size_t j = r.size() - 1;
    double e = std::abs(r[j].*q - r[j - 1].*q);
    if (j >= 2) e = std::max(e, 0.5 * std::abs(r[j - 1].*q - r[j - 2].*q));
    return std::max(2.0 * e, kRounding * std::abs(value.*q));
  };
  return {value, error(&ContactSnapshot::normal_force), error(&ContactSnapshot::tangential_force),
          true};
}

/// Every state's choice from the last three or four rows (which end alike): Richardson where
/// all of them located the state and `extrapolation` allows it (automatic: where its estimate
/// is the smaller), the finest row's own value otherwise.
std::vector<Choice> choose(std::vector<RunResult>& rows, Extrapolation extrapolation) {
  std::vector<std::vector<StateRef>> refs;
  for (RunResult& row : rows) refs.push_back(states(row));
  const std::size_t n = rows.size();
  const auto& c = refs[n - 3];
  const auto& m = refs[n - 2];
  const auto& f = refs[n - 1];
  std::vector<Choice> out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const ContactSnapshot& q0 = *c[i].state;
    const ContactSnapshot& q1 = *m[i].state;
    const ContactSnapshot& q2 = *f[i].state;
    const Choice plain{
        q2, plain_error(q0.normal_force, q1.normal_force, q2.normal_force, q2.edge_normal_force),
        plain_error(q0.tangential_force, q1.tangential_force, q2.tangential_force,
                    q2.edge_tangential_force),
        false};
    std::vector<const ContactSnapshot*> located;
    for (const auto& row : refs) {
      if (row[i].located && *row[i].located) located.push_back(&**row[i].located);
    }
    Choice chosen = plain;
    if (located.size() == n && extrapolation != Extrapolation::none) {
      const Choice r = richardson(located, q2);
      if (extrapolation == Extrapolation::richardson || r.normal_error <= plain.normal_error) {
        chosen = r;
      }
    }
    // Only stage ends vouch for their tangential force (at a jump or the peak it is whatever
    // the state has; under a held normal force the peak is any state at that force).
    if (!f[i].tangential_estimate) chosen.tangential_error = 0.0;
    out.push_back(chosen);
  }
  return out;
}

/// The works a row reports, in a fixed order: each stage's per axis, then the total's.
std::vector<double*> works(RunResult& r) {
  std::vector<double*> w;
  for (StageRecord& s : r.stages) {
    w.push_back(&s.work.normal);
    w.push_back(&s.work.tangential);
  }
  if (r.work) {
    w.push_back(&r.work->normal);
    w.push_back(&r.work->tangential);
  }
  return w;
}

/// One work's value and estimate from the last three or four rows (which end alike).
struct WorkChoice {
  double value;
  double error;
  /// The rows' differences grow geometrically: the work depends on the spring count, not
  /// through a discretization error (a fixed load's flight after the last spring): no rtol
  /// covers it, and a warning says so.
  bool diverges = false;
};

/// Over four rows: each difference at least 1.5 times the one before (a converging work's
/// halve; a diverging one's doubled: 3.4e-7, 6.8e-7, 1.4e-6 J on a shear ramp's flight).
bool diverging(double w0, double w1, double w2, double w3) {
  const double d1 = std::abs(w1 - w0);
  const double d2 = std::abs(w2 - w1);
  const double d3 = std::abs(w3 - w2);
  return d3 > kRounding * std::abs(w3) && d2 >= 1.5 * d1 && d3 >= 1.5 * d2;
}

/// Every work's choice, as a state's force: the finest row's own with the plain estimate
/// 2 max(|W_j - W_j-1|, |W_j-1 - W_j-2| / 2), or Richardson 2 W_j - W_j-1 with twice the
/// change from the pair before (and half the one before that with four rows), where
/// `extrapolation` allows it (automatic: where its estimate is the smaller). The work is a
/// sum of exact trapezoids between the rows' changes, so its error is that of the changes'
/// places: O(dx), smooth where the states are (the reversible cycle: -1.73e-3, -8.82e-4,
/// -4.43e-4, -2.23e-4 relative on 256 ... 2048 springs).
std::vector<WorkChoice> choose_works(std::vector<RunResult>& rows, Extrapolation extrapolation) {
  std::vector<std::vector<double*>> w;
  for (RunResult& row : rows) w.push_back(works(row));
  const std::size_t n = rows.size();
  std::vector<WorkChoice> out;
  for (std::size_t i = 0; i < w.back().size(); ++i) {
    const double w0 = *w[n - 3][i];
    const double w1 = *w[n - 2][i];
    const double w2 = *w[n - 1][i];
    WorkChoice chosen{w2, std::max(plain_error(w0, w1, w2, 0.0), kRounding * std::abs(w2))};
    if (extrapolation != Extrapolation::none) {
      std::vector<double> r;
      for (std::size_t j = 1; j < n; ++j) r.push_back(2.0 * *w[j][i] - *w[j - 1][i]);
      const std::size_t j = r.size() - 1;
      double e = std::abs(r[j] - r[j - 1]);
      if (j >= 2) e = std::max(e, 0.5 * std::abs(r[j - 1] - r[j - 2]));
      const WorkChoice extrapolated{r[j], std::max(2.0 * e, kRounding * std::abs(r[j]))};
      if (extrapolation == Extrapolation::richardson || extrapolated.error <= chosen.error) {
        chosen = extrapolated;
      }
    }
    chosen.diverges = n >= 4 && diverging(*w[n - 4][i], w0, w1, w2);
    if (chosen.diverges) chosen = {w2, std::abs(w2 - w1), true};
    out.push_back(chosen);
  }
  return out;
}

/// Writes the works' choices into the row: values, each stage's estimate, the total's.
void write_works(RunResult& r, const std::vector<WorkChoice>& choices) {
  const auto w = works(r);
  for (std::size_t i = 0; i < w.size(); ++i) *w[i] = choices[i].value;
  for (std::size_t s = 0; s < r.stages.size(); ++s) {
    r.stages[s].work_error_estimate = AxisWork{choices[2 * s].error, choices[2 * s + 1].error};
  }
  if (r.work) {
    const std::size_t t = 2 * r.stages.size();
    r.accuracy.work_error_estimate = AxisWork{choices[t].error, choices[t + 1].error};
  }
}

/// What a program's estimates cover (Accuracy::covers): the forces, and the works unless one
/// of them diverges, which the warning returned names (empty if none).
std::string set_covers(RunResult& r, const std::vector<WorkChoice>& works_chosen) {
  r.accuracy.covers = {"stages.end.normal_force",     "stages.end.tangential_force",
                       "jumps.critical.normal_force", "jumps.after.normal_force",
                       "critical.normal_force",       "peak_adhesion.normal_force"};
  std::string diverging;
  for (std::size_t i = 0; i < works_chosen.size(); ++i) {
    if (!works_chosen[i].diverges) continue;
    const std::size_t stage = i / 2;
    diverging += fmt::format(
        "{}the {} work of {}", diverging.empty() ? "" : ", ", i % 2 == 0 ? "normal" : "tangential",
        stage < r.stages.size() ? fmt::format("stage '{}'", r.stages[stage].name)
                                : std::string("the program"));
  }
  if (!works_chosen.empty() && diverging.empty()) {
    r.accuracy.covers.push_back("stages.work");
    r.accuracy.covers.push_back("work");
  }
  if (diverging.empty()) return {};
  return fmt::format(
      "{} grows with the spring count (the rows' differences double): it is no continuum value, "
      "and neither rtol nor its estimate covers the works",
      diverging);
}

/// Writes the choices into the row; returns the states that Richardson did not reach (for
/// the richardson route's warning).
std::vector<std::string> write_choices(RunResult& r, const std::vector<Choice>& choices) {
  std::vector<std::string> plain;
  bool extrapolated = false;
  const auto refs = states(r);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const StateRef& ref = refs[i];
    const Choice& c = choices[i];
    *ref.state = c.value;
    *ref.normal_estimate = c.normal_error;
    if (ref.tangential_estimate) *ref.tangential_estimate = c.tangential_error;
    extrapolated = extrapolated || c.extrapolated;
    // States that start at a first touch are not located between springs; the peak has its
    // own estimate and is not one of the states a program vouches for.
    const bool peak = r.peak && ref.state == &*r.peak;
    if (!c.extrapolated && ref.located && ref.state->springs_in_contact > 0 && !peak) {
      plain.push_back(ref.what);
    }
  }
  r.accuracy.route = extrapolated ? Accuracy::Route::richardson : Accuracy::Route::row;
  return plain;
}

/// Whether every choice's estimate is within rtol of its force, and every work's of its
/// work. A force (a work) below 1e-6 of the path's largest is held to that absolutely, and
/// nothing to less than what is zero on the rows (zero_scale.hpp): a non-adhesive cycle's
/// total work is rounding of its stages' (6e-21 J of 6.4e-9 J).
bool within(const std::vector<Choice>& choices, const std::vector<WorkChoice>& work_choices,
            const ZeroScale& zero, double rtol) {
  double largest = 0.0;
  for (const Choice& c : choices) {
    largest =
        std::max({largest, std::abs(c.value.normal_force), std::abs(c.value.tangential_force)});
  }
  double largest_work = 0.0;
  for (const WorkChoice& c : work_choices) largest_work = std::max(largest_work, std::abs(c.value));
  const auto ok = [&](double value, double error) {
    return error <= rtol * std::max({std::abs(value), kForceFloor * largest, zero.force});
  };
  const auto work_ok = [&](const WorkChoice& c) {
    return c.error <= rtol * std::max({std::abs(c.value), kForceFloor * largest_work, zero.work});
  };
  return std::all_of(choices.begin(), choices.end(),
                     [&](const Choice& c) {
                       return ok(c.value.normal_force, c.normal_error) &&
                              ok(c.value.tangential_force, c.tangential_error);
                     }) &&
         std::all_of(work_choices.begin(), work_choices.end(),
                     [&](const WorkChoice& c) { return c.diverges || work_ok(c); });
}

ProgramRowSpec resolving_row(const ProgramRowFrame& frame, std::int64_t springs) {
  ProgramRowSpec spec = program_row(frame, springs);
  spec.edge_forces = true;
  spec.refine = true;
  return spec;
}

std::string list(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& item : items) s += (s.empty() ? "" : ", ") + item;
  return s;
}

}  // namespace

RunResult run_program_richardson(const Scene& scene, const ObserverList& observers) {
  const ProgramRowFrame frame = program_row_frame(scene);
  const std::int64_t n = scene.springs;
  std::vector<RunResult> rows;
  RunCounts counts;
  for (const std::int64_t springs : {n / 2, n, 2 * n}) {
    rows.push_back(run_program_row(scene, resolving_row(frame, springs),
                                   springs == 2 * n ? observers : ObserverList{}));
    counts += rows.back().counts;
  }
  RunResult result = rows.back();
  result.counts = counts;
  result.accuracy.route = Accuracy::Route::richardson;
  result.accuracy.rows = {n / 2, n, 2 * n};
  result.accuracy.outer_radius = frame.radius;
  if (!end_alike(rows[0], rows[1]) || !end_alike(rows[1], rows[2])) {
    result.warnings.push_back(fmt::format(
        "richardson: the rows of {}, {} and {} springs end differently ({}); the finest row is "
        "reported as it is",
        n / 2, n, 2 * n, first_difference({{n / 2, &rows[0]}, {n, &rows[1]}, {2 * n, &rows[2]}})));
    return result;
  }
  const std::vector<std::string> plain =
      write_choices(result, choose(rows, Extrapolation::richardson));
  const std::vector<WorkChoice> works_chosen = choose_works(rows, Extrapolation::richardson);
  write_works(result, works_chosen);
  set_covers(result, works_chosen);
  result.accuracy.route = Accuracy::Route::richardson;
  if (!plain.empty()) {
    result.warnings.push_back(fmt::format(
        "richardson: {} could not be located between springs (springs pressed outside the "
        "glued ones, a front pinned since a jump, a shear-off): the finest row's value is "
        "reported, with its plain estimate",
        list(plain)));
  }
  return result;
}

RunResult run_program_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const ProgramRowFrame frame = program_row_frame(scene);
  const Extrapolation extrapolation = scene.discretization.extrapolation;
  std::vector<RunResult> rows;
  std::vector<std::int64_t> springs;
  RunCounts counts;
  std::vector<Choice> choices;
  std::vector<WorkChoice> work_choices;
  bool met = false;
  std::string why;
  for (std::int64_t n = kFirstRow;; n *= 2) {
    rows.push_back(run_program_row(scene, resolving_row(frame, n), {}));
    springs.push_back(n);
    counts += rows.back().counts;
    if (rows.size() > kRowsKept) rows.erase(rows.begin());
    const std::size_t k = rows.size();
    const bool alike = std::all_of(rows.begin(), rows.end(),
                                   [&](const RunResult& r) { return end_alike(r, rows.back()); });
    if (k >= 3 && alike) {
      choices = choose(rows, extrapolation);
      work_choices = choose_works(rows, extrapolation);
      met = within(choices, work_choices, frame.zero, rtol);
      if (met && k == kRowsKept) break;
      met = false;
      why = "the forces or works still differ across rows by more than rtol";
    } else if (k >= 3) {
      choices.clear();
      work_choices.clear();
      met = false;
      std::vector<std::pair<std::int64_t, const RunResult*>> kept;
      for (std::size_t i = 0; i < k; ++i)
        kept.emplace_back(springs[springs.size() - k + i], &rows[i]);
      why = fmt::format("the rows of {} to {} springs end differently ({})", kept.front().first, n,
                        first_difference(kept));
    }
    if (2 * n > scene.discretization.max_row_springs) break;
  }
  // The finest row again, for its events (the rows above ran without observers).
  RunResult result = observers.empty()
                         ? std::move(rows.back())
                         : run_program_row(scene, resolving_row(frame, springs.back()), observers);
  result.accuracy.route = Accuracy::Route::row;
  if (!choices.empty()) write_choices(result, choices);
  if (!work_choices.empty()) write_works(result, work_choices);
  if (std::string w = set_covers(result, work_choices); !w.empty()) {
    result.warnings.push_back(std::move(w));
  }
  result.counts = counts;
  result.accuracy.rows.assign(
      springs.end() - std::min<std::ptrdiff_t>(kRowsKept, std::ssize(springs)), springs.end());
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

// Stage ends, jumps and works combined across rows: the states' and works' choices, written
// back into the reported row, and whether they meet rtol.
#include "engine/accuracy/path_estimates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/accuracy/error_estimate.hpp"
#include "engine/accuracy/row_sequence.hpp"
#include "engine/model/machine_work.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

using Extrapolation = DiscretizationOptions::Extrapolation;

/// Forces below this share of the path's largest are held to it in absolute terms.
constexpr double kForceFloor = 1e-6;
/// The relative rounding of a work summed over rows of up to 2^25 springs (see choose_works).
constexpr double kSumRounding = 1e-11;

/// What must match for rows to be compared state by state, item by item: the status, the
/// stages, every jump, the critical point and the peak.
std::vector<std::string> ending_items(const RunResult& r) {
  std::vector<std::string> items{to_string(r.status), fmt::format("{} stages", r.stages.size())};
  for (std::size_t i = 0; i < r.jumps.size(); ++i) {
    const JumpRecord& j = r.jumps[i];
    items.push_back(
        fmt::format("jump {} {} in '{}'{}", i + 1, j.inward ? "in" : "out", j.stage,
                    j.end == JumpEnd::state ? "" : fmt::format(" ({})", to_string(j.end))));
  }
  items.emplace_back(r.critical ? "a critical point" : "no critical point");
  items.emplace_back(r.peak ? "a peak" : "no peak");
  return items;
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
/// and with PathStates::all the critical point and the peak.
std::vector<StateRef> states(RunResult& r, PathStates which) {
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
    // A flight has no state after it (docs: a fixed load that loses the contact).
    if (j.end == JumpEnd::state) {
      q.push_back({fmt::format("the state after the jump in stage '{}'", j.stage), &j.after,
                   &j.refined_after, &j.after_error_estimate, nullptr});
    }
  }
  if (which == PathStates::path) return q;
  if (r.critical) {
    q.push_back({"the critical point", &*r.critical, &r.refined_critical,
                 &r.accuracy.critical_error_estimate, nullptr});
  }
  if (r.peak) {
    q.push_back({"the peak", &*r.peak, &r.refined_peak, &r.accuracy.peak_error_estimate, nullptr});
  }
  return q;
}

/// The plain estimate of a state's force plus the edge spring's force.
double plain_error(double q0, double q1, double q2, double edge) {
  const double q[] = {q0, q1, q2};
  return change_estimate(q) + edge;
}

/// Richardson 2 Q(2N) - Q(N) from the two finest rows of `located` (the states as the rows
/// located them between springs, coarsest first), its estimate change_estimate of the
/// extrapolated values.
StateChoice richardson(const std::vector<const ContactSnapshot*>& located,
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
    std::vector<double> values;
    for (const ContactSnapshot& s : r) values.push_back(s.*q);
    return std::max(change_estimate(values), rounding_floor(value.*q));
  };
  return {value, error(&ContactSnapshot::normal_force), error(&ContactSnapshot::tangential_force),
          true};
}

/// Over four rows: each difference at least 1.5 times the one before (a converging work's
/// halve; a diverging one's doubled: 3.4e-7, 6.8e-7, 1.4e-6 J on a shear ramp's flight).
bool diverging(double w0, double w1, double w2, double w3, double rounding) {
  const double d1 = std::abs(w1 - w0);
  const double d2 = std::abs(w2 - w1);
  const double d3 = std::abs(w3 - w2);
  // Every difference above rounding: rows that agree and then step by one spring's place
  // (the critical point of a held F_x at the same x on 512, 1024 and 2048 springs, then one
  // spring further on 4096: differences 0, 0, 1.6e-14 J) are a sawtooth, not a divergence.
  return d1 > rounding && d2 >= 1.5 * d1 && d3 >= 1.5 * d2;
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

/// The tangential driving point of `s` under `c`: the machine end a_u u_x + a_F F_x where it
/// drives through a spring (the snapshot keeps no tangential held value), else u_x.
double tangential_driving(const AffineConstraint& c, const ContactSnapshot& s) {
  return drives_through_spring(c) ? c.displacement_coefficient * s.tangential_displacement +
                                        c.force_coefficient * s.tangential_force
                                  : s.tangential_displacement;
}

/// The work [J] per axis the machine does from stage `stage`'s last equilibrium to its end
/// located between springs (carried_works), none where the row does not locate it.
AxisWork carried_to_located_end(const StageRecord& stage, const StageControl& control) {
  if (!stage.refined_end || stage.end.springs_in_contact == 0) return {0.0, 0.0};
  const ContactSnapshot& from = stage.end;
  const ContactSnapshot& to = *stage.refined_end;
  const auto normal_point = [&](const ContactSnapshot& x) {
    return AxisPoint{x.normal_force,
                     driving_point(control.normal, x.normal_control, x.indentation)};
  };
  const auto tangential_point = [&](const ContactSnapshot& x) {
    return AxisPoint{x.tangential_force, tangential_driving(control.tangential, x)};
  };
  return {trapezoid_work(normal_point(from), normal_point(to)),
          trapezoid_work(tangential_point(from), tangential_point(to))};
}

/// The works `row` reports in choose_works' order, each stage's carried on from its last
/// equilibrium to its located end and the next stage's starting there (choose_works).
std::vector<double> carried_works(const RunResult& row, const std::vector<StageControl>& controls) {
  std::vector<double> w;
  for (const StageRecord& s : row.stages) {
    w.push_back(s.work.normal);
    w.push_back(s.work.tangential);
  }
  if (row.work) {
    w.push_back(row.work->normal);
    w.push_back(row.work->tangential);
  }
  const std::size_t stages = row.stages.size();
  for (std::size_t s = 0; s < stages && s < controls.size(); ++s) {
    const AxisWork carried = carried_to_located_end(row.stages[s], controls[s]);
    w[2 * s] += carried.normal;
    w[2 * s + 1] += carried.tangential;
    // The next stage starts at the located end; the last one's carry is the total's.
    if (s + 1 < stages) {
      w[2 * s + 2] -= carried.normal;
      w[2 * s + 3] -= carried.tangential;
    } else if (row.work) {
      w[2 * stages] += carried.normal;
      w[2 * stages + 1] += carried.tangential;
    }
  }
  return w;
}

/// A bound [J] on the normal work that stage `s` of `row` owes to a front pinned off the row's
/// springs, 0 where its front is not. The stage before moved the front (its end is located
/// between springs) and this one turns the indentation back (a peeling front reloaded, an
/// advancing one retracted): the row's front stays on its spring while the continuum's stays
/// between springs, and the strip between them carries force through the stage. Its work is a
/// sawtooth S dx frac(a / dx) in the spacing, which Richardson does not remove: it can even be
/// a constant where a / dx is near an integer on every row (the reload of a rebinding cycle:
/// 4.9e-13 J off on rows of 1024 to 65536 springs, 8.5e-6 of the program's work, with an
/// estimate of 6e-17 J). The strip is narrower than a spacing, so its force is at most the
/// edge spring's (or the located end's less the row's, if larger), which the bound takes twice
/// (the strip's tension may grow as the front is held) over the stage's whole travel in d.
double pinned_start_bound(const RunResult& row, std::size_t s) {
  if (s == 0 || s >= row.stages.size()) return 0.0;
  const StageRecord& before = row.stages[s - 1];
  const ContactSnapshot& end = before.end;
  if (!before.refined_end || end.springs_in_contact <= 0 ||
      before.refined_end->springs_in_contact <= 0) {
    return 0.0;
  }
  const double spacing = end.contact_radius / static_cast<double>(end.springs_in_contact);
  const double offset = std::abs(before.refined_end->contact_radius - end.contact_radius);
  if (!(offset > 1e-6 * spacing)) return 0.0;
  const double start = s >= 2 ? row.stages[s - 2].end.indentation : 0.0;
  const double travel_before = end.indentation - start;
  const double travel = row.stages[s].end.indentation - end.indentation;
  if (!(travel_before * travel < 0.0)) return 0.0;
  const double strip = std::max(std::abs(end.edge_normal_force),
                                std::abs(before.refined_end->normal_force - end.normal_force));
  return 2.0 * strip * std::abs(travel);
}

}  // namespace

bool is_critical_state(const RunResult& row, const ContactSnapshot& state) {
  return row.critical && state.springs_in_contact == row.critical->springs_in_contact &&
         state.normal_force == row.critical->normal_force;
}

bool is_peak_state(const RunResult& row, const ContactSnapshot& state) {
  return row.peak && state.springs_in_contact == row.peak->springs_in_contact &&
         state.normal_force == row.peak->normal_force;
}

void take_peak(const ContactSnapshot& value, double estimate, std::vector<StateChoice>& choices) {
  for (StateChoice& c : choices) {
    if (!c.at_peak) continue;
    c.value = value;
    c.normal_error = estimate;
  }
}

bool end_alike(const RunResult& a, const RunResult& b) {
  return ending_items(a) == ending_items(b);
}

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

std::vector<StateChoice> choose_states(std::vector<RunResult>& rows, Extrapolation extrapolation,
                                       PathStates which) {
  std::vector<std::vector<StateRef>> refs;
  for (RunResult& row : rows) refs.push_back(states(row, which));
  const std::size_t n = rows.size();
  const auto& c = refs[n - 3];
  const auto& m = refs[n - 2];
  const auto& f = refs[n - 1];
  std::vector<StateChoice> out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const ContactSnapshot& q0 = *c[i].state;
    const ContactSnapshot& q1 = *m[i].state;
    const ContactSnapshot& q2 = *f[i].state;
    const StateChoice plain{
        q2, plain_error(q0.normal_force, q1.normal_force, q2.normal_force, q2.edge_normal_force),
        plain_error(q0.tangential_force, q1.tangential_force, q2.tangential_force,
                    q2.edge_tangential_force),
        false};
    std::vector<const ContactSnapshot*> located;
    for (const auto& row : refs) {
      if (row[i].located && *row[i].located) located.push_back(&**row[i].located);
    }
    StateChoice chosen = plain;
    if (located.size() == n && extrapolation != Extrapolation::none) {
      const StateChoice r = richardson(located, q2);
      if (extrapolation == Extrapolation::richardson || r.normal_error <= plain.normal_error) {
        chosen = r;
      }
    }
    // Only stage ends vouch for their tangential force (at a jump or the peak it is whatever
    // the state has; under a held normal force the peak is any state at that force).
    if (!f[i].tangential_estimate) chosen.tangential_error = 0.0;
    chosen.at_critical = which != PathStates::all && is_critical_state(rows.back(), q2);
    chosen.at_peak =
        which == PathStates::critical_and_peak_elsewhere && is_peak_state(rows.back(), q2);
    out.push_back(chosen);
  }
  return out;
}

std::vector<WorkChoice> choose_works(const std::vector<RunResult>& rows,
                                     Extrapolation extrapolation,
                                     const std::vector<StageControl>& controls) {
  std::vector<std::vector<double>> w;
  for (const RunResult& row : rows) w.push_back(carried_works(row, controls));
  const std::size_t n = rows.size();
  // A work is a sum over the row's events, a total a sum of its stages' works: both carry the
  // rounding of the axis's largest work, which a small remainder (2.8e-6 J of a preload's and
  // a pull-off's 39.7 J) shows as differences of 4e-11 J (1e-12 of 39.7 J) at 2^20 to 2^22
  // springs, up and down. kSumRounding of that work: below it, differences are no divergence.
  double largest[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < w.back().size(); ++i) {
    largest[i % 2] = std::max(largest[i % 2], std::abs(w.back()[i]));
  }
  // The normal works that a front pinned off the row's springs makes a sawtooth: each stage's
  // own, and the program's, which sums them.
  const RunResult& finest = rows.back();
  std::vector<double> pinned(w.back().size(), 0.0);
  for (std::size_t s = 0; s < finest.stages.size(); ++s) {
    const double bound = pinned_start_bound(finest, s);
    pinned[2 * s] = bound;
    if (finest.work) pinned[2 * finest.stages.size()] += bound;
  }
  std::vector<WorkChoice> out;
  for (std::size_t i = 0; i < w.back().size(); ++i) {
    const double w0 = w[n - 3][i];
    const double w1 = w[n - 2][i];
    const double w2 = w[n - 1][i];
    const double plain[] = {w0, w1, w2};
    WorkChoice chosen{w2, std::max(change_estimate(plain) + pinned[i], rounding_floor(w2))};
    if (extrapolation != Extrapolation::none) {
      std::vector<double> r;
      for (std::size_t j = 1; j < n; ++j) r.push_back(richardson_value(w[j - 1][i], w[j][i]));
      // Richardson removes the smooth 1/N part and keeps the pinned strip's sawtooth, which
      // 2 W(2N) - W(N) takes at most three times its bound: its value stays the better one
      // (the reload's work 5e-6 off instead of the plain row's 1e-4), its estimate covers it.
      const WorkChoice extrapolated{
          r.back(), std::max(change_estimate(r) + 3.0 * pinned[i], rounding_floor(r.back()))};
      if (extrapolation == Extrapolation::richardson || extrapolated.error <= chosen.error) {
        chosen = extrapolated;
      }
    }
    chosen.diverges = n >= 4 && diverging(w[n - 4][i], w0, w1, w2, kSumRounding * largest[i % 2]);
    if (chosen.diverges) chosen = {w2, std::abs(w2 - w1), true};
    out.push_back(chosen);
  }
  return out;
}

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

void take_critical(const ContactSnapshot& value, double estimate,
                   std::vector<StateChoice>& choices) {
  for (StateChoice& c : choices) {
    if (!c.at_critical) continue;
    c.value = value;
    c.normal_error = estimate;
  }
}

WrittenStates write_states(RunResult& r, const std::vector<StateChoice>& choices,
                           PathStates which) {
  WrittenStates out;
  const auto refs = states(r, which);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const StateRef& ref = refs[i];
    const StateChoice& c = choices[i];
    *ref.state = c.value;
    *ref.normal_estimate = c.normal_error;
    if (ref.tangential_estimate) *ref.tangential_estimate = c.tangential_error;
    out.extrapolated = out.extrapolated || c.extrapolated;
    // States that start at a first touch are not located between springs; the peak has its
    // own estimate and is not one of the states a program vouches for.
    const bool peak = r.peak && ref.state == &*r.peak;
    if (!c.extrapolated && ref.located && ref.state->springs_in_contact > 0 && !peak) {
      out.plain.push_back(ref.what);
    }
  }
  return out;
}

bool within(const std::vector<StateChoice>& choices, const std::vector<WorkChoice>& work_choices,
            const ZeroScale& zero, double rtol) {
  double largest = 0.0;
  for (const StateChoice& c : choices) {
    largest =
        std::max({largest, std::abs(c.value.normal_force), std::abs(c.value.tangential_force)});
  }
  double largest_work = 0.0;
  for (const WorkChoice& c : work_choices) largest_work = std::max(largest_work, std::abs(c.value));
  const auto ok = [&](double value, double error) {
    return meets_rtol(error, value, rtol, std::max(kForceFloor * largest, zero.force));
  };
  // No rtol asks a work for less than the rounding of the sums behind it (choose_works).
  const auto work_ok = [&](const WorkChoice& c) {
    return meets_rtol(c.error, c.value, rtol, std::max(kForceFloor * largest_work, zero.work),
                      2.0 * kSumRounding * largest_work);
  };
  return std::all_of(
             choices.begin(), choices.end(),
             [&](const StateChoice& c) {
               return (c.at_critical || c.at_peak || ok(c.value.normal_force, c.normal_error)) &&
                      ok(c.value.tangential_force, c.tangential_error);
             }) &&
         std::all_of(work_choices.begin(), work_choices.end(),
                     [&](const WorkChoice& c) { return c.diverges || work_ok(c); });
}

std::vector<std::int64_t> PathRefinement::rows_used() const {
  return {springs.end() - std::min<std::ptrdiff_t>(kRowsKept, std::ssize(springs)), springs.end()};
}

PathRefinement refine_path(std::int64_t first, std::int64_t max_springs,
                           const std::function<RunResult(std::int64_t)>& run,
                           Extrapolation extrapolation, PathStates which,
                           const std::vector<StageControl>& controls, const ZeroScale& zero,
                           double rtol) {
  PathRefinement p;
  std::vector<RunResult>& rows = p.rows;
  for (std::int64_t n = first;; n *= 2) {
    rows.push_back(run(n));
    p.springs.push_back(n);
    p.counts += rows.back().counts;
    if (rows.size() > kRowsKept) rows.erase(rows.begin());
    const std::size_t k = rows.size();
    const bool alike = std::all_of(rows.begin(), rows.end(),
                                   [&](const RunResult& r) { return end_alike(r, rows.back()); });
    if (k >= 3 && alike) {
      p.choices = choose_states(rows, extrapolation, which);
      p.work_choices = choose_works(rows, extrapolation, controls);
      p.met = within(p.choices, p.work_choices, zero, rtol);
      if (p.met && k == kRowsKept) break;
      p.met = false;
      p.why = "the forces or works still differ across rows by more than rtol";
    } else if (k >= 3) {
      p.choices.clear();
      p.work_choices.clear();
      p.met = false;
      std::vector<std::pair<std::int64_t, const RunResult*>> kept;
      for (std::size_t i = 0; i < k; ++i) {
        kept.emplace_back(p.springs[p.springs.size() - k + i], &rows[i]);
      }
      p.why = fmt::format("the rows of {} to {} springs end differently ({})", kept.front().first,
                          n, first_difference(kept));
    }
    if (2 * n > max_springs) break;
  }
  return p;
}

}  // namespace mdrsim

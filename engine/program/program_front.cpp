// The glued front of a program row between springs: its phase from the front's margin, and the
// row's branch interpolated there.
#include "engine/program/program_front.hpp"

#include <algorithm>
#include <cmath>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/fold_refinement.hpp"

namespace mdrsim {
void StageLine::place(ProgramRow& row, double t) const {
  if (normal.rate != 0.0) row.set_normal_held(normal.start + normal.rate * t);
  if (tangential.rate != 0.0) row.set_tangential_held(tangential.start + tangential.rate * t);
  row.set_time(clock.start + clock.rate * t);
}

double ProgramFront::let_go_margin(const ProgramRow& row) const {
  const std::int64_t k = row.glued();
  const double stretch = std::max(0.0, row.image(k) - row.indentation());
  return criterion_->margin(
      {stretch, row.tangential_displacement() - row.boundary_offset(), row.position(k)});
}

std::optional<ContactSnapshot> ProgramFront::at_rest(ProgramRow& row) {
  const std::int64_t k = row.glued();
  const std::int64_t m = row.in_contact();
  if (m == 0) return row.snapshot();  // nothing in contact: no front to place
  if (k == 0 && m >= 2 && !row.friction()) return pressed_at_rest(row);
  if (m != k || k < 2) {
    phase_.reset();
    return std::nullopt;
  }
  // Spring n glues once the gap g_n - d (with n - 1 glued) reaches its limit (advancing); the
  // boundary lets go once the criterion's margin reaches zero (receding).
  const auto glue_margin = [](const ProgramRow& r, std::int64_t n) {
    return r.image(n) - r.indentation() - r.front_limit(n);
  };
  struct Branch {
    ContactSnapshot state;
    double margin;
  };
  // The branch one spring in and one spring out, at the same held values.
  const Branch inner = row.trial([](ProgramRow& r) { r.let_go_boundary(false); },
                                 [&](const ProgramRow& r) {
                                   return Branch{r.snapshot(), glue_margin(r, k)};
                                 });
  const ContactSnapshot at = row.snapshot();

  std::optional<double> phase;
  std::optional<ContactSnapshot> outer;
  if (row.adhesive() && row.can_glue(k + 1)) {
    const double here = inner.margin;
    const double next = glue_margin(row, k + 1);
    if (here <= 0.0 && next > 0.0) {
      phase = here / (here - next);
      outer = row.trial([](ProgramRow& r) { r.glue_next(); },
                        [](const ProgramRow& r) { return r.snapshot(); });
    }
  }
  if (!phase) {
    const Branch out = row.trial([](ProgramRow& r) { r.glue_next_as_boundary(); },
                                 [&](const ProgramRow& r) {
                                   return Branch{r.snapshot(), let_go_margin(r)};
                                 });
    const double here = let_go_margin(row);
    if (here > 0.0 && out.margin <= 0.0) phase = here / (here - out.margin);
    outer = out.state;
  }
  if (phase) {
    phase_ = phase;
  } else if (!phase_) {
    return std::nullopt;  // pinned, with no phase known since it last moved
  }
  return interpolate_snapshots(inner.state, at, *outer, *phase_);
}

std::optional<ContactSnapshot> ProgramFront::pressed_at_rest(ProgramRow& row) {
  // Springs pressed without glue (a press that does not glue, the springs a glue sheared off
  // under compression left in): the front sits where g(a) = d, at the phase of d between
  // g_m and g_m+1, on the branch of springs m - 1, m and m + 1 in contact at the same held
  // values.
  const std::int64_t m = row.in_contact();
  const double here = row.image(m) - row.indentation();
  const double next = row.image(m + 1) - row.indentation();
  if (!(here <= 0.0 && next > 0.0)) return std::nullopt;
  const auto look = [](const ProgramRow& r) { return r.snapshot(); };
  const ContactSnapshot inner = row.trial([](ProgramRow& r) { r.lift_outer(); }, look);
  const ContactSnapshot outer = row.trial([](ProgramRow& r) { r.touch_next(); }, look);
  return interpolate_snapshots(inner, row.snapshot(), outer, here / (here - next));
}

void ProgramFront::candidate(const std::optional<ContactSnapshot>& state) {
  if (!state || state->springs_in_contact == 0 || !(state->normal_force < 0.0)) return;
  if (!peak_ || state->normal_force < peak_->normal_force) peak_ = state;
}

void ProgramFront::branch_state(bool let_go, const ContactSnapshot& before) {
  if (branch_size_ > 0 && branch_let_go_ != let_go) branch_size_ = 0;
  branch_let_go_ = let_go;
  if (branch_size_ == 3) {
    branch_[0] = branch_[1];
    branch_[1] = branch_[2];
    branch_size_ = 2;
  }
  branch_[static_cast<std::size_t>(branch_size_++)] = before;
  if (branch_size_ < 3) return;
  const double in = branch_[0].normal_force;
  const double at = branch_[1].normal_force;
  const double out = branch_[2].normal_force;
  if (!(at <= in && at <= out)) return;
  if (const auto s = parabola_vertex(in, at, out)) {
    candidate(interpolate_snapshots(branch_[0], branch_[1], branch_[2], *s));
  }
}

std::optional<ContactSnapshot> ProgramFront::peak(const ContactSnapshot& plain) const {
  if (!peak_ ||
      !(std::abs(peak_->normal_force - plain.normal_force) <= 2.0 * plain.edge_normal_force)) {
    return std::nullopt;
  }
  return peak_;
}

std::optional<ContactSnapshot> ProgramFront::fold(ProgramRow& row, const StageLine& line, double t,
                                                  const ContactSnapshot& before) {
  const std::int64_t k = row.glued() + 1;  // the spring that let go at t
  const auto& previous = previous_single_;
  if (!previous || !previous->let_go || previous->spring != k + 1 || row.in_contact() != k - 1 ||
      k < 3 || !(previous->t < t)) {
    return std::nullopt;
  }
  // The let-go of spring k - 1 along the stage line (d and u_x affine in t while the springs
  // stay): it is due already at t, so it lies behind, where the margin is still positive.
  const double d = row.indentation();
  const double u = row.tangential_displacement();
  const double d_per_t = row.indentation_per_held() * line.normal.rate;
  const double u_per_t = row.tangential_per_held() * line.tangential.rate;
  const double g = row.image(k - 1);
  const double s = row.boundary_offset();
  const double a = row.position(k - 1);
  const auto margin = [&](double at) {
    const double stretch = std::max(0.0, g - (d + d_per_t * (at - t)));
    return criterion_->margin({stretch, u + u_per_t * (at - t) - s, a});
  };
  if (margin(t) > 0.0) return std::nullopt;
  // Back from t in steps that double from the last let-go's distance (which is tiny where
  // the fold falls between springs k + 1 and k).
  double behind = previous->t;
  for (int i = 0; i < 64 && !(margin(behind) > 0.0); ++i) behind = t - 2.0 * (t - behind);
  if (!(margin(behind) > 0.0)) return std::nullopt;  // broken at rest: a shear-off, not a fold
  const double t_inner = bracketed_root(margin, behind, t);
  const ContactSnapshot inner = row.trial([&](ProgramRow& r) { line.place(r, t_inner); },
                                          [](const ProgramRow& r) { return r.snapshot(); });

  // The fold is the largest parameter of the let-go branch: the vertex of -t.
  const auto vertex = parabola_vertex(-t_inner, -t, -previous->t);
  if (!vertex) return std::nullopt;
  fold_parameter_ = quadratic_through(t_inner, t, previous->t, *vertex);
  ContactSnapshot q = interpolate_snapshots(inner, before, previous->before, *vertex);
  q.springs_in_contact = before.springs_in_contact;
  return q;
}

std::optional<ContactSnapshot> ProgramFront::advancing_fold(ProgramRow& row, const StageLine& line,
                                                            double t,
                                                            const ContactSnapshot& before) {
  const std::int64_t k = row.glued();  // the spring that glued at t
  const auto& previous = previous_single_;
  if (!previous || previous->let_go || previous->spring != k - 1 || row.in_contact() != k ||
      k < 3 || !row.can_glue(k + 1) || !(previous->t < t)) {
    return std::nullopt;
  }
  // The glue of spring k + 1 along the stage line (d affine in t while the springs stay): it
  // is due already at t, so it lies behind, where its gap is still above its limit.
  const double d = row.indentation();
  const double d_per_t = row.indentation_per_held() * line.normal.rate;
  const double limit = row.gluing_depth(k + 1);
  const auto margin = [&](double at) { return limit - (d + d_per_t * (at - t)); };
  if (margin(t) > 0.0) return std::nullopt;
  double behind = previous->t;
  for (int i = 0; i < 64 && !(margin(behind) > 0.0); ++i) behind = t - 2.0 * (t - behind);
  if (!(margin(behind) > 0.0)) return std::nullopt;
  const double t_outer = bracketed_root(margin, behind, t);
  const ContactSnapshot outer = row.trial([&](ProgramRow& r) { line.place(r, t_outer); },
                                          [](const ProgramRow& r) { return r.snapshot(); });

  // The fold is the largest parameter of the gluing branch: the vertex of -t.
  const auto vertex = parabola_vertex(-previous->t, -t, -t_outer);
  if (!vertex) return std::nullopt;
  fold_parameter_ = quadratic_through(previous->t, t, t_outer, *vertex);
  ContactSnapshot q = interpolate_snapshots(previous->before, before, outer, *vertex);
  q.springs_in_contact = before.springs_in_contact;
  return q;
}

std::optional<ContactSnapshot> ProgramFront::at_rest_at(ProgramRow& row, const StageLine& line,
                                                        double t) {
  const std::optional<double> kept = phase_;
  phase_.reset();
  std::optional<ContactSnapshot> q;
  row.trial(
      [&](ProgramRow& r) {
        line.place(r, t);
        q = at_rest(r);
      },
      [](const ProgramRow&) { return 0; });
  phase_ = kept;
  return q;
}

}  // namespace mdrsim

// The viscoelastic row's critical point located between springs from the let-gos before it.
#include "engine/program/viscoelastic_fold.hpp"

#include <cmath>

#include "engine/model/fold_refinement.hpp"

namespace mdrsim {
namespace {

/// The last bits of an event's time and of a held value: the root of an event is found to its
/// last bits in a clock that adds up every event's interval (measured: the relaxed pull-off's
/// fold on 2^20 springs moves by 0.016 spacings, its depths' rounding 0.7 of the clock's last
/// bit times the rate of the depth).
constexpr double kHeldRoundingUlps = 1.0;

double ulp_of(double x) {
  const double a = std::abs(x);
  return std::nextafter(a, HUGE_VAL) - a;
}

}  // namespace

void ViscoelasticFold::change(ViscoelasticRowChange change, std::string_view stage,
                              const ViscoelasticRowSample& before, double held, bool by_shear) {
  if (change != ViscoelasticRowChange::let_go) {
    size_ = 0;
    cascaded_ = false;
    last_let_go_ = -HUGE_VAL;
    return;
  }
  const bool same_stage = stage == stage_;
  const bool continues = same_stage && before.time == last_let_go_;
  last_let_go_ = before.time;
  if (continues) {
    cascaded_ = true;  // a let-go within a cascade (by shear or not): no point of the branch
    return;
  }
  // A cascade inside the trail broke its branch, a new stage moves along another line, and a
  // let-go broken at rest by shear ends the branch (a shear-off, not a fold).
  if (cascaded_ || !same_stage || by_shear) size_ = 0;
  stage_ = std::string(stage);
  cascaded_ = false;
  if (by_shear) return;
  if (size_ == 3) {
    trail_[0] = trail_[1];
    trail_[1] = trail_[2];
    size_ = 2;
  }
  trail_[static_cast<std::size_t>(size_++)] = {before.glued, held, before};
}

std::optional<ViscoelasticFold::Located> ViscoelasticFold::located(
    const ViscoelasticCascade& loss) const {
  if (size_ < 3 || loss.first_by_shear || loss.changes < 2 || loss.stage != stage_) {
    return std::nullopt;
  }
  const auto& [outer2, outer, first] = trail_;  // springs n + 2, n + 1, n
  const std::int64_t n = first.spring;
  if (first.before.time != loss.before.time || n != loss.before.glued || outer.spring != n + 1 ||
      outer2.spring != n + 2 || n < 2) {
    return std::nullopt;
  }
  // The held value along the branch, h(s) through s = -1 (spring n), 0 and 1 (spring n + 2):
  // moving one way to spring n, and turning within half a spacing of it, where the let-go of
  // spring n - 1 is due as soon as spring n's.
  const double h_in = first.held;
  const double h_at = outer.held;
  const double h_out = outer2.held;
  const double curvature = h_in - 2.0 * h_at + h_out;
  if (!(curvature != 0.0) || !((h_in < h_at && h_at < h_out) || (h_in > h_at && h_at > h_out))) {
    return std::nullopt;
  }
  const double s = 0.5 * (h_in - h_out) / curvature;
  if (!(s >= -2.0 && s <= 0.0)) return std::nullopt;  // no turn between springs n - 1 and n + 1
  const ContactSnapshot in = viscoelastic_snapshot(first.before);
  const ContactSnapshot at = viscoelastic_snapshot(outer.before);
  const ContactSnapshot out = viscoelastic_snapshot(outer2.before);
  ContactSnapshot q = interpolate_snapshots(in, at, out, s);
  q.glued_radius = quadratic_through(first.before.glued_radius, outer.before.glued_radius,
                                     outer2.before.glued_radius, s);
  q.springs_in_contact = loss.before.pressed;
  if (!std::isfinite(q.normal_force)) return std::nullopt;
  // The held values' rounding (kHeldRoundingUlps of the clock's last bit times their rate, and
  // of their own) moves the turn by `place` spacings, and each field by its slope times that.
  const double t = first.before.time;
  const double rate = (h_out - h_in) / (outer2.before.time - t);
  const double place = kHeldRoundingUlps *
                       (std::abs(rate) * ulp_of(t) + ulp_of(h_in) + ulp_of(h_out)) /
                       std::abs(curvature);
  ContactSnapshot rounding;
  for (double ContactSnapshot::*field :
       {&ContactSnapshot::normal_force, &ContactSnapshot::indentation,
        &ContactSnapshot::normal_control, &ContactSnapshot::contact_radius,
        &ContactSnapshot::time}) {
    const double slope =
        0.5 * (out.*field - in.*field) + s * (in.*field - 2.0 * at.*field + out.*field);
    rounding.*field = std::abs(slope) * place;
  }
  return Located{q, rounding};
}

void ViscoelasticFold::locate(const ViscoelasticCascade& loss, RunResult& r) const {
  if (const auto fold = located(loss)) {
    r.refined_critical = fold->state;
    r.refined_critical_rounding = fold->rounding;
  }
}

}  // namespace mdrsim

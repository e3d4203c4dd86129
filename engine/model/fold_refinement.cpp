// Quadratic interpolation of the discrete branch at its fold, its shear-off point and its peak.
#include "engine/model/fold_refinement.hpp"

#include <algorithm>
#include <cmath>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/boundary_let_go.hpp"
#include "engine/model/snapshot_fields.hpp"

namespace mdrsim {

double quadratic_through(double inner, double at, double outer, double s) {
  return at + 0.5 * s * (outer - inner) + 0.5 * s * s * (inner - 2.0 * at + outer);
}

std::optional<double> parabola_vertex(double inner, double at, double outer) {
  const double curvature = inner - 2.0 * at + outer;
  if (!(curvature > 0.0)) return std::nullopt;
  return std::clamp(0.5 * (inner - outer) / curvature, -1.0, 1.0);
}

ContactSnapshot interpolate_snapshots(const ContactSnapshot& in, const ContactSnapshot& at,
                                      const ContactSnapshot& out, double s) {
  ContactSnapshot q = at;
  for (const auto member : kBranchQuantities) {
    q.*member = quadratic_through(in.*member, at.*member, out.*member, s);
  }
  return q;
}

std::optional<ContactSnapshot> refine_fold(const Contact& contact,
                                           const DetachmentCriterion& criterion,
                                           const Contact::State& outer,
                                           const Contact::State& critical) {
  const std::int64_t n = critical.springs_in_contact;
  if (n < 2 || outer.springs_in_contact != n + 1) return std::nullopt;
  Contact probe = contact;
  probe.restore(critical);
  probe.detach_boundary_spring();
  const BoundaryLetGo next = locate_boundary_let_go(probe, criterion);
  if (next.let_go.kind != LetGo::Kind::at_elongation) return std::nullopt;
  probe.set_normal_control(next.normal_control);

  const auto s =
      parabola_vertex(next.normal_control, critical.normal_control, outer.normal_control);
  if (!s) return std::nullopt;
  const ContactSnapshot in = probe.snapshot();
  const ContactSnapshot out = contact.snapshot_of(outer);
  return interpolate_snapshots(in, contact.snapshot_of(critical), out, *s);
}

std::optional<ContactSnapshot> refine_shear_off(const Contact& contact,
                                                const DetachmentCriterion& criterion,
                                                const Contact::State& outer2,
                                                const Contact::State& outer,
                                                const Contact::State& critical) {
  const std::int64_t n = critical.springs_in_contact;
  if (n < 1 || outer.springs_in_contact != n + 1 || outer2.springs_in_contact != n + 2) {
    return std::nullopt;
  }
  Contact probe = contact;
  probe.restore(critical);
  const SpringFoundation& row = contact.foundation();
  const auto margin_at_rest = [&](double a) {
    return criterion.margin({0.0, probe.tangential_displacement_at_radius(a), a});
  };
  const double hi = row.position(n);
  const double lo = row.position(n - 1);
  const double at_hi = margin_at_rest(hi);
  // At the centre a criterion holding there at rest (a user's constant strength) has no a_s
  // below hi; the built-ins' margin at rest is <= 0 at a = 0, which breaks the glue there.
  const double at_lo = lo > 0.0 || margin_at_rest(0.0) > 0.0 ? margin_at_rest(lo) : -1.0;
  if (!(at_hi >= 0.0) || !(at_lo < 0.0)) return std::nullopt;
  const double a_s = at_hi == 0.0 ? hi : bracketed_root(margin_at_rest, std::max(lo, 0.0), hi);
  // Springs n + 2, n + 1, n sit at s = 1, 0, -1 of the parabola; a_s at s in [-2, -1].
  const double s = (a_s - hi) / row.spacing() - 1.0;
  ContactSnapshot q = interpolate_snapshots(
      contact.snapshot_of(critical), contact.snapshot_of(outer), contact.snapshot_of(outer2), s);
  q.springs_in_contact = n;
  return q;
}

ContactSnapshot refine_peak(const Contact& contact, const Contact::State& outer,
                            const Contact::State& at, const Contact::State& inner) {
  const ContactSnapshot o = contact.snapshot_of(outer);
  const ContactSnapshot c = contact.snapshot_of(at);
  const ContactSnapshot i = contact.snapshot_of(inner);
  const auto s = parabola_vertex(i.normal_force, c.normal_force, o.normal_force);
  return s ? interpolate_snapshots(i, c, o, *s) : c;
}

}  // namespace mdrsim

// Quadratic interpolation of the discrete branch at the vertex of its control-value parabola.
#include "engine/fold_refinement.hpp"

#include <cmath>

#include "engine/boundary_let_go.hpp"

namespace mdrsim {
namespace {

/// The quadratic through q(-1) = inner, q(0) = at, q(1) = outer, at s in [-1, 1].
double quadratic(double inner, double at, double outer, double s) {
  return at + 0.5 * s * (outer - inner) + 0.5 * s * s * (inner - 2.0 * at + outer);
}

}  // namespace

std::optional<RefinedFold> refine_fold(const Contact& contact, const DetachmentCriterion& criterion,
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

  const double l_inner = next.normal_control;
  const double l_at = critical.normal_control;
  const double l_outer = outer.normal_control;
  const double curvature = l_inner - 2.0 * l_at + l_outer;
  if (!(curvature > 0.0)) return std::nullopt;
  double s = 0.5 * (l_inner - l_outer) / curvature;
  if (s < -1.0) s = -1.0;
  if (s > 1.0) s = 1.0;

  const ContactSnapshot in = probe.snapshot();
  const ContactSnapshot at = contact.snapshot_of(critical);
  const ContactSnapshot out = contact.snapshot_of(outer);
  ContactSnapshot fold = at;
  fold.normal_control = quadratic(l_inner, l_at, l_outer, s);
  fold.indentation = quadratic(in.indentation, at.indentation, out.indentation, s);
  fold.normal_force = quadratic(in.normal_force, at.normal_force, out.normal_force, s);
  fold.contact_radius = quadratic(in.contact_radius, at.contact_radius, out.contact_radius, s);
  fold.tangential_displacement = quadratic(in.tangential_displacement, at.tangential_displacement,
                                           out.tangential_displacement, s);
  fold.tangential_force =
      quadratic(in.tangential_force, at.tangential_force, out.tangential_force, s);
  return RefinedFold{fold, 0.5 * std::abs(out.normal_force - in.normal_force)};
}

}  // namespace mdrsim

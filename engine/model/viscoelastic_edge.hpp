// The adhesive edge of a row of viscoelastic springs: the line load at which the boundary spring
// lets go and the gap at which the spring outside the contact glues, both written with the
// glassy modulus E_0, and what a spring's instantaneous (glassy) step does to its arms.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "detachment/criterion.hpp"
#include "engine/base/material.hpp"
#include "engine/model/prony_creep.hpp"

namespace mdrsim {

/// A let-go or a glue is instantaneous: the dashpots do not move, so the spring answers with
/// E_0 = E* + sum_j E_j. Per spring i = 1..N at x_i = i dx (index i - 1):
struct ViscoelasticEdge {
  double glassy_modulus = 0.0;  ///< E_0* [Pa]
  /// |q| [N/m] at which spring i, the boundary of the glued contact, lets go: E_0 times the
  /// criterion's critical elongation at x_i with no tangential displacement (the criterion
  /// built with E_0 for E*: every built-in gives sqrt(2 pi x dgamma(x) E_0) there). A spring
  /// with no glue at its radius lets go at 0; a criterion that never lets go gives infinity.
  std::vector<double> let_go_loads;
  /// The gap g(x_i) - d [m] at which spring i, just outside the contact, glues:
  /// sqrt(2 pi x_i dgamma_a(x_i) / E_0) (0: on touch).
  std::vector<double> glue_gaps;
  /// The surface energy of spring i's ring per unit x of one half, pi x_i dgamma(x_i) [J/m]
  /// (the ring 2 pi x dgamma dx over the two halves' 2 dx).
  std::vector<double> surface_energies;
  /// Whether a spring that let go glues again like a fresh one (loading.rebinding).
  bool rebinding = false;
  /// G_0* = G* E_0* / E* [Pa]: a let-go steps the tangential stretch by -q_x / G_0.
  double glassy_shear_modulus = 0.0;
  /// The glassy criterion, for a boundary spring that carries a tangential load: its margin at
  /// elongation -q_z / E_0 and u_x = q_x / G_0 (null: let_go_loads alone); must outlive the edge.
  const DetachmentCriterion* criterion = nullptr;
};

/// The material a criterion of the edge sees: E* and G* replaced by their glassy values
/// E_0* = E* + sum_j E_j* and G_0* = G* E_0* / E* (nu constant in time); adhesion unchanged.
Material glassy_material(const Material& material);

/// The edge of N springs spaced dx [m] for `material` (relaxed E*, its Prony terms), with
/// `glassy_criterion` built on glassy_material(material).
ViscoelasticEdge viscoelastic_edge(const DetachmentCriterion& glassy_criterion,
                                   const Material& material, double spacing, std::size_t springs,
                                   bool rebinding);

/// The arm stresses [N/m] after the spring's stretch steps by `step` [m] at once: each arm's
/// spring takes the whole step, sigma_j + E_j step.
void glassy_step(std::span<double> stresses, std::span<const PronyTerm> terms, double step);

/// The first s in (0, span] [s] at which the indenter, whose reach (its stretch at the spring
/// plus the glue gap) [m] is `reach` at s = 0 and moves at `rate` [m/s], meets the surface of
/// a free spring t0 [s] after its release, from the side of no contact. With `on_level` the
/// two are taken to stand together at s = 0 (they do up to rounding): the meeting is then the
/// one after they part, never one the rounding of the start makes up.
std::optional<double> reach_time(const FreeSpringCreep& creep, double t0, double reach, double rate,
                                 double span, bool on_level);
std::optional<double> reach_time(const FreeSpringCreepRef& creep, double t0, double reach,
                                 double rate, double span, bool on_level);

}  // namespace mdrsim

// The work of the machines along the continuum path, from the energy the contact stores and sheds.
#pragma once

#include "engine/continuum/continuum_branch.hpp"
#include "engine/result/program_records.hpp"

namespace mdrsim {

/// An integral and a bound on its error.
struct Estimated {
  double value = 0.0;
  double error = 0.0;
};

/// A state and the energy it stores, computed once where the path meets the state twice.
struct StoredState {
  BranchState state;
  Estimated energy;  ///< stored_energy(branch, state) [J]
};

/// The normal energy of the glued springs, E* int_0^a (d - g)^2 dx at s's contact radius and
/// indentation [J]: the profile's closed form where it has one, else quadrature. States that
/// share a and d (the preload and the tangential load's application) share it.
Estimated glued_normal_energy(const ContinuumBranch& branch, const BranchState& s);

/// The energy stored in the glued springs, E* int_0^a (d - g)^2 dx + G* a u_x^2 (both halves),
/// plus the energy of the machines' springs, F^2 / 2k and F_x^2 / 2k_t, where they drive
/// through one [J]; `normal` is glued_normal_energy(branch, s).
Estimated stored_energy(const ContinuumBranch& branch, const BranchState& s,
                        const Estimated& normal);
/// The same, its normal part computed here.
Estimated stored_energy(const ContinuumBranch& branch, const BranchState& s);
/// The state with its stored energy.
StoredState stored_state(const ContinuumBranch& branch, const BranchState& s);

/// The energy the springs take with them as the front recedes along the branch from radius
/// `from` down to `to`: int (E* e(x)^2 + G* u_x(x)^2) dx [J].
Estimated released_energy(const ContinuumBranch& branch, double from, double to);

/// The machines' work along a stable stretch of the path from `top` to `bottom` (both
/// equilibria, the front receding between them or pinned when their radii agree): the
/// stored energy's change plus what the springs took; the tangential share is the held
/// force times the move of u_x under a tangential fixed load (zero otherwise: fixed grips
/// hold u_x, a compliant machine holds its end), the normal share the rest.
AxisWork stretch_work(const ContinuumBranch& branch, const StoredState& top,
                      const StoredState& bottom, double& error);
/// The same, the two stored energies computed here.
AxisWork stretch_work(const ContinuumBranch& branch, const BranchState& top,
                      const BranchState& bottom, double& error);

/// The machines' work over a jump at a held control from `from` to `to`: a fixed load
/// moves at constant force; fixed grips and a compliant machine's end stand still.
AxisWork jump_work(const ContinuumBranch& branch, const BranchState& from, const BranchState& to);

}  // namespace mdrsim

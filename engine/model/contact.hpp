// The glued contact: attached springs, held values and the equilibrium they fix (paper eqs. 10,
// 36-37).
#pragma once

#include <cstdint>
#include <utility>

#include "controllers/controller.hpp"
#include "engine/base/material.hpp"
#include "engine/model/compensated_sum.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/model/spring_foundation.hpp"

namespace mdrsim {

/// Springs 1..n are attached. The normal force is 2 E* dx sum_{i<=n} (d - g(x_i)) (graded:
/// sum_{i<=n} w_i (d - g_k(x_i)), spring_foundation.hpp) and the tangential force 2 G* dx n u_x
/// (both halves): each is linear in its displacement, so the controllers' constraints give the
/// equilibrium by one division, O(1) per query.
class Contact {
 public:
  /// Mutable part of the contact, cheap to copy: stepping backs up by restoring it.
  struct State {
    std::int64_t springs_in_contact;
    /// sum of g(x_i) over attached springs [m]; graded: of w_i g(x_i) [N] (spring_foundation.hpp)
    CompensatedSum image_sum;
    double normal_control;   ///< held value of the normal controller
    double tangential_held;  ///< held value of the tangential controller
    double boundary_image;   ///< g at the boundary spring, 0 without springs [m]
  };

  Contact(const SpringFoundation& foundation, const Material& material, AffineConstraint normal,
          AffineConstraint tangential);

  std::int64_t springs_in_contact() const { return state_.springs_in_contact; }
  double normal_control() const { return state_.normal_control; }
  void set_normal_control(double value) { state_.normal_control = value; }
  double tangential_held() const { return state_.tangential_held; }
  void set_tangential_held(double value) { state_.tangential_held = value; }

  LinearResponse normal_response() const;
  LinearResponse tangential_response() const;
  double indentation() const;              ///< d [m]
  double tangential_displacement() const;  ///< u_x [m]
  double contact_radius() const;           ///< position of the boundary spring, 0 if none [m]
  double boundary_image() const { return state_.boundary_image; }  ///< g at the boundary [m]
  /// The normal held value that puts the indenter at `indentation` [m].
  double normal_control_at(double indentation) const;
  /// The normal force of a saved state, without a snapshot [N].
  double normal_force_of(const State& state) const;
  /// The indentation [m] and normal force [N] of a saved state with springs attached.
  std::pair<double, double> normal_state_of(const State& state) const;
  /// The tangential displacement [m] of a contact whose boundary sat at radius `a` [m]:
  /// the held value under the constraint with the continuum stiffness 2 G* a, so that it
  /// equals tangential_displacement() at every spring position and is continuous between.
  double tangential_displacement_at_radius(double a) const;

  /// Removes the boundary spring: O(1).
  void detach_boundary_spring();

  ContactSnapshot snapshot() const;
  /// The snapshot of a saved state, without changing this contact.
  ContactSnapshot snapshot_of(const State& state) const;
  State save() const { return state_; }
  void restore(const State& state) { state_ = state; }

  const SpringFoundation& foundation() const { return *foundation_; }
  const Material& material() const { return material_; }

 private:
  const SpringFoundation* foundation_;
  Material material_;
  AffineConstraint normal_;
  AffineConstraint tangential_;
  State state_;
};

}  // namespace mdrsim

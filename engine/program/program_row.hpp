// The spring row of a loading program: glued springs in runs of one tangential offset, pressed
// springs outside them, and the running sums that give the equilibrium in O(1).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/base/material.hpp"
#include "engine/model/compensated_sum.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/model/gluing_depth.hpp"
#include "engine/program/friction_row.hpp"
#include "engine/program/graded_springs.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// One axis of the loading machine: the constraint a_u u + a_F F = held and, where the axis
/// carries no stiffness (fixed load, nothing attached), the displacement it rests at.
struct MachineAxis {
  AffineConstraint constraint{1.0, 0.0};
  double held = 0.0;  ///< [m] or [N]
  double rest = 0.0;  ///< displacement while the axis has no stiffness [m]
};

/// Springs i = 1, 2, ... at x_i = i dx; spring N sits exactly at the reference radius a_ref.
/// Springs 1..k are glued; springs 1..m (m >= k) are in contact: the glued ones and, outside
/// them, springs pressed without glue (compression only, frictionless). A glued spring
/// carries the tangential stretch u_x - s, s the indenter's u_x when it glued; springs glue
/// in runs at one s, so a stack of (first spring, s) runs and two sums replace per-spring
/// state. Normal force 2 E* dx sum_{i<=m} (d - g_i), tangential 2 G* dx sum_{i<=k} (u_x - s_i).
/// With friction (docs/friction.md) a FrictionRow mirrors the springs in contact and gives the
/// tangential force, the pressed springs' stick and slip included; the tangential axis is then
/// driven in u_x (fixed grips), which the scene checks.
class ProgramRow {
 public:
  /// `reference_image` is g at spring N: the front value the program reaches there, which
  /// equals g(a_ref) up to rounding (so that spring N is reached whatever the rounding).
  ProgramRow(const Profile& profile, const Material& material, double reference_radius,
             std::int64_t reference_springs, double reference_image, bool rebinding);

  double position(std::int64_t i) const {  ///< x_i [m]
    return i == reference_springs_ ? reference_radius_ : spacing_ * static_cast<double>(i);
  }
  double image(std::int64_t i) const { return values(i).image; }  ///< g(x_i) [m]
  /// The gap g_i - d at which the front glues spring i [m]: the advancing limit at x_i
  /// (engine/model/gluing_depth.hpp), 0 for spring 1 (nothing glued yet: it glues on touch).
  double front_limit(std::int64_t i) const {
    if (i == 1) return 0.0;
    SpringValues& v = values(i);
    if (v.front_limit < 0.0) {
      v.front_limit = graded_ ? graded_->front_limit(position(i))
                              : advancing_limit(material_, true, position(i));
    }
    return v.front_limit;
  }
  /// The springs of a graded half-space from now on (a row with nothing in contact):
  /// graded_springs.hpp's weights, images and gluing limit.
  void use_graded_springs(const GradedSprings& springs) {
    graded_ = springs;
    recent_ = {};
  }
  const std::optional<GradedSprings>& graded() const { return graded_; }
  /// The indentation at which spring i glues, springs 1..i-1 glued: gluing_depth() on the
  /// row's values, g_i - l_i [m].
  double gluing_depth(std::int64_t i) const { return image(i) - front_limit(i); }
  double spacing() const { return spacing_; }
  std::int64_t reference_springs() const { return reference_springs_; }

  std::int64_t glued() const { return glued_; }            ///< k
  std::int64_t in_contact() const { return in_contact_; }  ///< m
  /// With friction a pressed spring that slides glues only once it sticks (docs/friction.md).
  bool can_glue(std::int64_t i) const {
    return (rebinding_ || i > ever_glued_) &&
           !(friction_ && i <= in_contact_ && friction_->spring(i).sliding != 0);
  }
  double boundary_offset() const { return runs_.back().offset; }  ///< s of spring k [m]
  /// Whether the boundary spring's tangential stretch is its own (glued = "coulomb": it slips,
  /// staying glued) rather than its glued run's u_x - s.
  bool boundary_slips() const { return friction_ && friction_->glued_springs_slip(); }
  /// The boundary spring k's tangential stretch at (d, u_x) while no spring changes: u_x - s,
  /// or under glued = "coulomb" the friction row's (docs/friction.md) [m].
  double boundary_stretch(double indentation, double tangential) const {
    if (boundary_slips()) return friction_->glued_stretch(glued_, indentation, tangential);
    return tangential - boundary_offset();
  }
  /// The tangential stretch the detachment criterion sees at the boundary spring k [m]: its
  /// stretch less what friction holds of it once the glue is gone, where it stays pressed
  /// (d >= g_k): the stretch the let-go releases. Griffith per spring: the glue goes only where
  /// the energy it releases pays its surface energy, and a stick zone releases nothing
  /// (docs/friction.md "Letting go under friction"). Its whole stretch out of contact.
  double boundary_released_stretch(double indentation, double tangential) const {
    if (!friction_) return boundary_stretch(indentation, tangential);
    return friction_released_stretch(indentation, tangential);
  }
  /// Whether the released stretch moves as d and u_x move at rates vd and vu: with u_x alone
  /// for a spring that sticks; with d alone for a glued spring sliding while pressed
  /// (glued = "coulomb") (its limit mu f_z over kx), not while it is in tension (limit 0 at the
  /// glued edge); with d too where friction holds part of it while pressed.
  bool boundary_stretch_moves(double indentation, double vd, double vu) const {
    if (friction_ && vd != 0.0 && friction_->released_limit_moves()) {
      const double g = image(glued_);
      if (indentation > g || (indentation == g && vd > 0.0)) return true;
    }
    if (!boundary_slips() || friction_->spring(glued_).sliding == 0) return vu != 0.0;
    const double g = image(glued_);
    return vd != 0.0 && (indentation > g || (indentation == g && vd > 0.0));
  }
  /// Whether every glued spring carries the same offset s (one run).
  bool one_offset() const { return runs_.size() <= 1; }
  /// Springs 1..n glue, each at the present u_x, on a row with nothing in contact: a zoomed
  /// row's start (program_zoom.hpp).
  void glue_first(std::int64_t n) { glue_through(n); }
  /// A zoomed row's start: every spring glued with the one tangential offset [m] (at zero
  /// stretch: the tangential machine holds u_x there while they glue), then the machine as
  /// the stage started on the full row.
  void start_zoomed(const MachineAxis& normal, const MachineAxis& tangential, double offset) {
    edit_tangential() = {{1.0, 0.0}, offset, offset};
    glue_first(reference_springs_);
    edit_normal() = normal;
    edit_tangential() = tangential;
  }
  bool adhesive() const { return material_.adhesive(); }
  /// Friction on every spring in contact from now on (a row with nothing in contact).
  void enable_friction(const FrictionSettings& settings) {
    friction_.emplace(material_, settings, spacing_);
    friction_->reserve(reference_springs_);
  }
  const FrictionRow* friction() const { return friction_ ? &*friction_ : nullptr; }
  /// Moves the friction row along `motion` to t (no friction event in between); returns the
  /// work its slips dissipated [J].
  double advance_friction(const LinearMotion& motion, double t) {
    // The held values' changes have dropped what they move (set_normal_held,
    // set_tangential_held); the advance itself changes F_x(d, u_x) only through the sliding
    // springs. Nothing sliding (a press's touches), the equilibrium stays as it is.
    if (friction_->force_follows_indentation()) tangential_cached_ = false;
    return friction_->advance(motion, t);
  }
  void apply_friction(const RowFrictionEvent& event) {
    tangential_.rest = tangential_displacement();  // where u_x rests if nothing sticks now
    tangential_cached_ = tangential_response_cached_ = false;  // K changes
    friction_->apply(event);
  }
  const Material& material() const { return material_; }

  const MachineAxis& normal() const { return normal_; }
  const MachineAxis& tangential() const { return tangential_; }
  /// Changing an axis drops what is cached of it.
  MachineAxis& edit_normal() {
    normal_cached_ = normal_response_cached_ = false;
    return normal_;
  }
  MachineAxis& edit_tangential() {
    tangential_cached_ = tangential_response_cached_ = false;
    return tangential_;
  }
  /// A new held value keeps the response (the springs and the constraint).
  void set_normal_held(double held) {
    normal_.held = held;
    normal_cached_ = false;
    // Sliding springs follow mu f_z; with none F_x does not depend on d (a press with
    // friction solves the tangential axis once per touch, not once more per move).
    if (friction_ && friction_->force_follows_indentation()) tangential_cached_ = false;
  }
  void set_tangential_held(double held) {
    tangential_.held = held;
    tangential_cached_ = false;
  }

  /// Equilibrium: the axis has stiffness (else it rests, see MachineAxis::rest).
  bool normal_has_stiffness() const;
  bool tangential_has_stiffness() const;
  double indentation() const { return normal_equilibrium().displacement; }  ///< d [m]
  double tangential_displacement() const {                                  ///< u_x [m]
    return tangential_equilibrium().displacement;
  }
  double normal_force() const { return normal_equilibrium().force; }          ///< F [N]
  double tangential_force() const { return tangential_equilibrium().force; }  ///< F_x [N]
  double normal_force_at(double indentation) const;
  double tangential_force_at(double displacement) const;
  /// d(d)/d(held) and d(u_x)/d(held) while the springs stay as they are.
  double indentation_per_held() const;
  double tangential_per_held() const;
  /// d(u_x)/d(d) at a fixed held value: with friction under a held force, the sliding springs'
  /// mu f_z moves u_x with d (0 without friction or under fixed grips).
  double tangential_per_indentation() const {
    if (!friction_ || is_fixed_grips(tangential_.constraint)) return 0.0;
    return held_force_per_indentation();
  }
  /// The held value that the present state satisfies under `constraint`.
  double held_value_of_normal(const AffineConstraint& constraint) const;
  double held_value_of_tangential(const AffineConstraint& constraint) const;
  /// A new controller on an axis takes its held value from the present state: nothing jumps.
  void hand_normal_to(const AffineConstraint& constraint) {
    const double rest = indentation();
    const double held = held_value_of_normal(constraint);
    edit_normal() = {constraint, held, rest};
  }
  void hand_tangential_to(const AffineConstraint& constraint) {
    const double rest = tangential_displacement();
    const double held = held_value_of_tangential(constraint);
    edit_tangential() = {constraint, held, rest};
  }

  /// Spring k+1 glues at the present u_x; it was pressed (m > k) or becomes the new edge.
  void glue_next();
  /// Whether the advancing front glues a spring as it touches it (dgamma_a = 0).
  bool glues_on_touch() const { return material_.glues_on_touch(); }
  /// Springs k+1..last glue at the present u_x, on a row without friction whose springs in
  /// contact are all glued, as a press that glues on touch reaches them one by one (the same
  /// row as glue_next one at a time, to the bit, where the machine fixes d and u_x); returns the
  /// energy they store at the present indentation d, each glued where d passed its image: the work
  /// the press did on them, sum of E* dx (d - g_i)^2 over both halves [J].
  double glue_through(std::int64_t last);
  /// Spring k+1 glues at the boundary spring's offset s_k: the branch one spring further
  /// out, as a receding front left it (for locating the front between springs).
  void glue_next_as_boundary();
  /// The boundary spring k lets go; it stays in contact, pressed, when `pressed`. Returns the
  /// work friction dissipates as it slips to its limit at once (0 without friction) [J].
  double let_go_boundary(bool pressed);
  void touch_next();  ///< spring m+1 is pressed
  void lift_outer();  ///< spring m (not glued) leaves

  ContactSnapshot snapshot() const;

  /// The elastic energy of the springs at the present equilibrium, both halves, with the
  /// spring of a compliant machine: O(1) from running sums (friction_row.hpp says when the
  /// friction row's part is more) [J].
  double stored_energy() const;
  /// The surface energy the glue holds: 2 pi x_i dgamma(x_i) dx over springs i <= k, what
  /// breaking it all would create (the MDR image of the glued disk's pi a^2 dgamma) [J].
  /// One dgamma: pi dgamma dx^2 k (k + 1), with no sum to keep.
  double glued_surface() const {
    if (surface_varies_) return sums_.surface.value();
    const auto k = static_cast<double>(glued_);
    return std::numbers::pi * surface_work_of_adhesion_ * spacing_ * spacing_ * k * (k + 1.0);
  }
  /// Whether a glue or a let-go changes the stored energy of its own spring only: without
  /// friction (no other spring slips) and under fixed grips on both axes (d and u_x stay).
  bool changes_stay_local() const {
    return !friction_ && is_fixed_grips(normal_.constraint) &&
           is_fixed_grips(tangential_.constraint);
  }
  /// Without friction: the stored energy the glues and let-gos took out of the row at the d and
  /// u_x of each, summed over the row's life: a let-go's spring's (its tangential stretch, and
  /// its normal one where it leaves the contact), less a glue's (its normal stretch where it
  /// joins the contact), both halves [J]. Where changes_stay_local, what they released.
  double released_by_changes() const { return sums_.released.value(); }

  /// Applies `change` (one change at the edges, or new held values), returns what `look`
  /// sees of the row then, and puts the row back exactly: O(1), where a copy of the row would
  /// copy every run of glued springs.
  template <class Change, class Look>
  auto trial(Change&& change, Look&& look) {
    const Edges saved = edges();
    const double time = time_;
    change(*this);
    auto seen = look(static_cast<const ProgramRow&>(*this));
    restore(saved);
    time_ = time;
    return seen;
  }
  /// The program's clock where the row stands (timed programs; 0 otherwise) [s]: snapshots
  /// carry it.
  void set_time(double time) { time_ = time; }
  double time() const { return time_; }
  /// Whether snapshots carry the edge springs' forces (for rtol's estimates).
  void record_edge_forces(bool on) { edge_forces_ = on; }

 private:
  double friction_released_stretch(double indentation, double tangential) const;
  /// Resets the sums over springs in contact and glued once no spring is left in them.
  void forget_rounding_of_empty_sums();

  /// The equilibrium of each axis, computed once per change of the row or of that axis: a
  /// step asks for it many times.
  struct AxisEquilibrium {
    double displacement;
    double force;
  };
  // The cached paths inline: a step asks for the equilibrium many times.
  const AxisEquilibrium& normal_equilibrium() const {
    if (!normal_cached_) solve_normal();
    return normal_equilibrium_;
  }
  const AxisEquilibrium& tangential_equilibrium() const {
    if (!tangential_cached_) solve_tangential();
    return tangential_equilibrium_;
  }
  void solve_normal() const;
  void solve_tangential() const;
  double solve_indentation() const;
  double solve_tangential_displacement() const;
  double held_force_per_indentation() const;  ///< tangential_per_indentation under a held F_x

  /// g and the front's limit of the springs near the edges, computed once: each step asks
  /// for springs k, k + 1, m and m + 1 several times.
  struct SpringValues {
    std::int64_t index = -1;
    double image = 0.0;
    double front_limit = -1.0;  ///< computed when first asked for; < 0 before
  };
  SpringValues& values(std::int64_t i) const {
    SpringValues& v = recent_[static_cast<std::size_t>(i) & (recent_.size() - 1)];
    if (v.index != i) fill(v, i);
    return v;
  }
  void fill(SpringValues& v, std::int64_t i) const;
  void glue_at(double offset);  ///< spring k+1 glues with this s
  /// Whether a spring of offset s gluing or letting go leaves the tangential equilibrium.
  bool tangential_unchanged_by(double offset) const;
  /// The sums over springs in contact weigh spring i's image by this: 1 on a homogeneous row
  /// (its sums are scaled by 2 E* dx, sum_scale()), w_i on a graded one (scaled by 1).
  double sum_weight(std::int64_t i) const {
    return graded_ ? graded_->weight(i, position(i)) : 1.0;
  }
  double sum_scale() const { return graded_ ? 1.0 : 2.0 * material_.effective_modulus * spacing_; }
  /// What the springs 1..m stiffen by, times sum_scale(): m, or C_k x_m^(1+k) where graded.
  double contact_count(std::int64_t m) const {
    if (!graded_) return static_cast<double>(m);
    return m > 0 ? graded_->stiffness_to(position(m)) : 0.0;
  }
  /// Half of spring i's normal stiffness, both halves [N/m]: its energy per stretch squared.
  double half_weight(std::int64_t i) const {
    return graded_ ? 0.5 * graded_->weight(i, position(i)) : material_.effective_modulus * spacing_;
  }
  /// Drops what the change of the springs on each axis makes stale.
  void springs_changed(bool normal, bool tangential);
  mutable std::array<SpringValues, 4> recent_{};

  struct Run {
    std::int64_t first;     ///< innermost spring of the run
    double offset;          ///< s [m]
    double squares_before;  ///< sum of s_i^2 over the runs inside it [m^2]
  };
  /// A run of offset s from spring `first` on: the sum of squares before it is its
  /// predecessor's, once per run, not once per spring.
  void push_run(std::int64_t first, double offset);
  /// sum of s_i^2, i <= k [m^2].
  double offset_squares() const {
    if (runs_.empty()) return 0.0;
    const Run& last = runs_.back();
    return last.squares_before +
           static_cast<double>(glued_ - last.first + 1) * last.offset * last.offset;
  }
  const Profile* profile_;
  Material material_;
  double reference_radius_;
  std::int64_t reference_springs_;
  double reference_image_;
  double spacing_;
  bool rebinding_;
  bool surface_varies_;  ///< dgamma varies with the radius: glued_surface keeps a sum
  /// dgamma where it does not vary (a uniform table's or sinusoid's to the bit) [J/m^2].
  double surface_work_of_adhesion_;

  std::int64_t glued_ = 0;
  std::int64_t in_contact_ = 0;
  std::int64_t ever_glued_ = 0;
  std::optional<GradedSprings> graded_;
  CompensatedSum contact_images_;  ///< sum of g_i, i <= m [m]; graded: of w_i g_i [N]
  CompensatedSum glued_offsets_;   ///< sum of s_i, i <= k [m]
  /// What the energy balance needs beyond the forces' sums (the runs keep sum of s_i^2).
  struct EnergySums {
    CompensatedSum image_squares;  ///< sum of g_i^2, i <= m [m^2]; graded: of w_i g_i^2 [N m]
    CompensatedSum surface;        ///< glued_surface, where dgamma varies [J]
    CompensatedSum released;       ///< released_by_changes [J]
  };
  EnergySums sums_;
  /// 2 pi x_i dgamma(x_i) dx: the surface energy spring i's glue holds [J].
  double surface_energy(std::int64_t i) const;
  std::vector<Run> runs_;
  std::optional<FrictionRow> friction_;
  MachineAxis normal_;
  MachineAxis tangential_;
  mutable AxisEquilibrium normal_equilibrium_{};
  mutable AxisEquilibrium tangential_equilibrium_{};
  bool edge_forces_ = false;
  mutable bool normal_cached_ = false;
  mutable bool tangential_cached_ = false;
  // d(displacement)/d(held) of each axis: one division per change of the springs, none per
  // change of the held value.
  mutable double normal_per_held_ = 0.0;
  mutable double tangential_per_held_ = 0.0;
  mutable bool normal_response_cached_ = false;
  mutable bool tangential_response_cached_ = false;

  /// All that a change at the edges or of the held values alters: the counts, the sums, the
  /// last run (a change pushes or pops one at most), the axes and what is cached of them.
  double time_ = 0.0;
  struct Edges {
    std::int64_t glued, in_contact, ever_glued;
    CompensatedSum contact_images, glued_offsets;
    EnergySums sums;
    std::size_t runs;
    Run last_run;
    MachineAxis normal, tangential;
    AxisEquilibrium normal_equilibrium, tangential_equilibrium;
    bool normal_cached, tangential_cached, normal_response_cached, tangential_response_cached;
    double normal_per_held, tangential_per_held;
  };
  Edges edges() const;
  void restore(const Edges& saved);
};

}  // namespace mdrsim

// Equilibrium of a program's spring row from running sums; O(1) changes at its edges.
#include "engine/program/program_row.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mdrsim {

ProgramRow::ProgramRow(const Profile& profile, const Material& material, double reference_radius,
                       std::int64_t reference_springs, double reference_image, bool rebinding)
    : profile_(&profile),
      material_(material),
      reference_radius_(reference_radius),
      reference_springs_(reference_springs),
      reference_image_(reference_image),
      spacing_(reference_radius / static_cast<double>(reference_springs)),
      rebinding_(rebinding),
      surface_varies_(material.work_of_adhesion_by_radius != nullptr &&
                      !material.work_of_adhesion_by_radius->uniform()),
      surface_work_of_adhesion_(material.work_of_adhesion_at(0.0)) {}

void ProgramRow::springs_changed(bool normal, bool tangential) {
  if (friction_) tangential = true;  // every spring in contact may carry a tangential force
  // Under fixed grips (a_F = 0) d(displacement)/d(held) = 1/a_u does not depend on the springs.
  if (normal) {
    normal_cached_ = false;
    if (!is_fixed_grips(normal_.constraint) || normal_per_held_ == 0.0) {
      normal_response_cached_ = false;
    }
  }
  if (tangential) {
    tangential_cached_ = false;
    if (!is_fixed_grips(tangential_.constraint) || tangential_per_held_ == 0.0) {
      tangential_response_cached_ = false;
    }
  }
}

void ProgramRow::fill(SpringValues& v, std::int64_t i) const {
  v.index = i;
  if (i == reference_springs_) {
    v.image = reference_image_;
  } else {
    v.image = graded_ ? graded_->image->image(position(i)) : profile_->mdr_image(position(i));
  }
  v.front_limit = -1.0;
}

namespace {
/// Whether the constraint fixes the displacement against this stiffness [N/m].
bool has_stiffness(const AffineConstraint& c, double stiffness) {
  return c.displacement_coefficient + c.force_coefficient * stiffness > 0.0;
}
}  // namespace

bool ProgramRow::normal_has_stiffness() const {
  return has_stiffness(normal_.constraint, static_cast<double>(in_contact_));
}

bool ProgramRow::tangential_has_stiffness() const {
  // With friction every sticking spring holds (K = 2 G* dx per sticking spring).
  if (friction_) return has_stiffness(tangential_.constraint, friction_->tangential_stiffness());
  return has_stiffness(tangential_.constraint, static_cast<double>(glued_));
}

double ProgramRow::normal_force_at(double d) const {
  return sum_scale() * (contact_count(in_contact_) * d - contact_images_.value());
}

double ProgramRow::tangential_force_at(double u) const {
  if (friction_) return friction_->tangential_force(indentation(), u);
  const double per_spring = 2.0 * material_.effective_shear_modulus * spacing_;
  return per_spring * (static_cast<double>(glued_) * u - glued_offsets_.value());
}

void ProgramRow::solve_normal() const {
  normal_equilibrium_.displacement = solve_indentation();
  normal_equilibrium_.force = normal_force_at(normal_equilibrium_.displacement);
  normal_cached_ = true;
}

void ProgramRow::solve_tangential() const {
  tangential_equilibrium_.displacement = solve_tangential_displacement();
  tangential_equilibrium_.force = tangential_force_at(tangential_equilibrium_.displacement);
  tangential_cached_ = true;
}

double ProgramRow::solve_indentation() const {
  const double per_held = indentation_per_held();
  if (per_held == 0.0) return normal_.rest;
  const double offset = sum_scale() * contact_images_.value();
  return (normal_.held + normal_.constraint.force_coefficient * offset) * per_held;
}

double ProgramRow::solve_tangential_displacement() const {
  const double per_held = tangential_per_held();
  if (per_held == 0.0) return tangential_.rest;
  if (friction_) {
    // Fixed grips (a_F = 0): u_x = held / a_u whatever F_x, held - 0 F_x(d, 0) being held but
    // for held = -0 against F_x(d, 0) < 0 (+0): F_x(d, 0) is computed only then (a press asks
    // at each touch). (With F_x(d, 0) beyond a double the run stops on its F_x either way.)
    const double held = tangential_.held;
    if (is_fixed_grips(tangential_.constraint) && !(held == 0.0 && std::signbit(held))) {
      return held * per_held;
    }
    // F_x = K u + F_x(d, 0), affine in u while no spring changes.
    const double at_zero = friction_->tangential_force(indentation(), 0.0);
    return (tangential_.held - tangential_.constraint.force_coefficient * at_zero) * per_held;
  }
  const double offset = 2.0 * material_.effective_shear_modulus * spacing_ * glued_offsets_.value();
  return (tangential_.held + tangential_.constraint.force_coefficient * offset) * per_held;
}

double ProgramRow::indentation_per_held() const {
  if (!normal_response_cached_) {
    const AffineConstraint& c = normal_.constraint;
    const double k = sum_scale() * contact_count(in_contact_);
    normal_per_held_ =
        normal_has_stiffness() ? 1.0 / (c.displacement_coefficient + c.force_coefficient * k) : 0.0;
    normal_response_cached_ = true;
  }
  return normal_per_held_;
}

double ProgramRow::tangential_per_held() const {
  if (!tangential_response_cached_) {
    const AffineConstraint& c = tangential_.constraint;
    const double k = friction_ ? friction_->tangential_stiffness()
                               : 2.0 * material_.effective_shear_modulus * spacing_ *
                                     static_cast<double>(glued_);
    tangential_per_held_ = tangential_has_stiffness()
                               ? 1.0 / (c.displacement_coefficient + c.force_coefficient * k)
                               : 0.0;
    tangential_response_cached_ = true;
  }
  return tangential_per_held_;
}

double ProgramRow::held_force_per_indentation() const {
  return -tangential_.constraint.force_coefficient *
         friction_->tangential_force_per_indentation(indentation()) * tangential_per_held();
}

double ProgramRow::held_value_of_normal(const AffineConstraint& c) const {
  return c.displacement_coefficient * indentation() + c.force_coefficient * normal_force();
}

double ProgramRow::held_value_of_tangential(const AffineConstraint& c) const {
  return c.displacement_coefficient * tangential_displacement() +
         c.force_coefficient * tangential_force();
}

void ProgramRow::glue_next() {
  // The displacements before the change: an axis without stiffness rests where it was.
  normal_.rest = indentation();
  tangential_.rest = tangential_displacement();
  // With friction a pressed spring glues keeping its stretch: its offset, not u_x.
  const bool pressed = friction_ && glued_ < in_contact_;
  glue_at(pressed ? friction_->spring(glued_ + 1).offset : tangential_.rest);
}

double ProgramRow::glue_through(std::int64_t last) {
  // glue_next for each spring, with what does not change from one to the next done once:
  // the displacements (fixed by the machine, or by glued springs at no stretch), the cache
  // they drop, the run of the one offset.
  if (glued_ >= last) return 0.0;
  if (friction_ || glued_ != in_contact_) {
    throw std::logic_error("ProgramRow::glue_through: springs pressed or friction on the row");
  }
  const double d = indentation();
  const double u = tangential_displacement();
  normal_.rest = d;
  tangential_.rest = u;
  springs_changed(true, !tangential_unchanged_by(u));
  if (runs_.empty() || runs_.back().offset != u) push_run(glued_ + 1, u);
  CompensatedSum squares;
  for (std::int64_t i = glued_ + 1; i <= last; ++i) {
    const double g = image(i);
    const double w = sum_weight(i);
    contact_images_.add(w * g);
    glued_offsets_.add(u);
    sums_.image_squares.add(w * g * g);
    if (surface_varies_) sums_.surface.add(surface_energy(i));
    const double stretch = d - g;
    squares.add(w * stretch * stretch);
  }
  glued_ = last;
  in_contact_ = last;
  ever_glued_ = std::max(ever_glued_, last);
  // Half of 2 E* dx (both halves) per spring, times the stretch squared (graded: half of w_i).
  return (graded_ ? 0.5 : material_.effective_modulus * spacing_) * squares.value();
}

void ProgramRow::push_run(std::int64_t first, double offset) {
  double before = 0.0;
  if (!runs_.empty()) {
    const Run& last = runs_.back();
    before =
        last.squares_before + static_cast<double>(first - last.first) * last.offset * last.offset;
  }
  runs_.push_back({first, offset, before});
}

void ProgramRow::glue_next_as_boundary() {
  normal_.rest = indentation();
  tangential_.rest = tangential_displacement();
  glue_at(runs_.empty() ? tangential_.rest : runs_.back().offset);
}

bool ProgramRow::tangential_unchanged_by(double offset) const {
  // Where the tangential displacement does not depend on the springs (a_F = 0), a spring at
  // zero tangential stretch adds or removes no tangential force.
  return is_fixed_grips(tangential_.constraint) && tangential_cached_ &&
         offset == tangential_equilibrium_.displacement;
}

void ProgramRow::glue_at(double u) {
  springs_changed(true, !tangential_unchanged_by(u));
  ++glued_;
  if (glued_ > ever_glued_) ever_glued_ = glued_;
  const double stretch = tangential_.rest - u;
  double brought = material_.effective_shear_modulus * spacing_ * stretch * stretch;
  if (glued_ > in_contact_) {
    in_contact_ = glued_;
    const double g = image(glued_);
    const double w = sum_weight(glued_);
    contact_images_.add(w * g);
    sums_.image_squares.add(w * g * g);
    const double normal = normal_.rest - g;
    brought += half_weight(glued_) * normal * normal;
    if (friction_) friction_->touch(g, u);
  }
  if (!friction_) sums_.released.add(-brought);
  if (friction_) friction_->glue_next(normal_.rest);
  if (runs_.empty() || runs_.back().offset != u) push_run(glued_, u);
  glued_offsets_.add(u);
  if (surface_varies_) sums_.surface.add(surface_energy(glued_));
}

double ProgramRow::let_go_boundary(bool pressed) {
  normal_.rest = indentation();
  tangential_.rest = tangential_displacement();
  double dissipated = 0.0;
  if (friction_) {
    // Unpressed, its limit is 0: it lets go of its stretch with no slip work, and leaves.
    dissipated = friction_->let_go_boundary(normal_.rest, tangential_.rest);
    if (!pressed && in_contact_ == glued_) friction_->lift_outer();
  }
  const double offset = runs_.back().offset;
  springs_changed(true, !tangential_unchanged_by(offset));
  glued_offsets_.add(-offset);
  if (surface_varies_) sums_.surface.add(-surface_energy(glued_));
  if (runs_.back().first == glued_) runs_.pop_back();
  const double stretch = tangential_.rest - offset;
  double released = material_.effective_shear_modulus * spacing_ * stretch * stretch;
  if (!pressed && in_contact_ == glued_) {
    const double g = image(in_contact_);
    const double w = sum_weight(in_contact_);
    contact_images_.add(-(w * g));
    sums_.image_squares.add(-(w * g * g));
    const double normal = normal_.rest - g;
    released += half_weight(in_contact_) * normal * normal;
    --in_contact_;
  }
  if (!friction_) sums_.released.add(released);
  --glued_;
  forget_rounding_of_empty_sums();
  return dissipated;
}

void ProgramRow::touch_next() {
  normal_.rest = indentation();
  if (friction_) friction_->touch(image(in_contact_ + 1), tangential_displacement());
  springs_changed(true, false);
  ++in_contact_;
  const double g = image(in_contact_);
  const double w = sum_weight(in_contact_);
  contact_images_.add(w * g);
  sums_.image_squares.add(w * g * g);
}

void ProgramRow::lift_outer() {
  normal_.rest = indentation();
  if (friction_) friction_->lift_outer();
  springs_changed(true, false);
  const double g = image(in_contact_);
  const double w = sum_weight(in_contact_);
  contact_images_.add(-(w * g));
  sums_.image_squares.add(-(w * g * g));
  --in_contact_;
  forget_rounding_of_empty_sums();
}

// A sum over no spring is 0, not the rounding its adds and removes left (1e-30 N of force
// on an empty row after the crack-front case's cascade of 10^5 springs).
void ProgramRow::forget_rounding_of_empty_sums() {
  if (in_contact_ == 0) contact_images_ = sums_.image_squares = CompensatedSum{};
  if (glued_ == 0) glued_offsets_ = sums_.surface = CompensatedSum{};
}

double ProgramRow::surface_energy(std::int64_t i) const {
  const double x = position(i);
  return 2.0 * std::numbers::pi * x * material_.work_of_adhesion_at(x) * spacing_;
}

double ProgramRow::friction_released_stretch(double indentation, double tangential) const {
  const double stretch = boundary_stretch(indentation, tangential);
  // Out of contact the spring lifts as it lets go: its whole stretch goes.
  if (image(glued_) > indentation) return stretch;
  const double held = friction_->released_limit_stretch(glued_, indentation);
  if (held == 0.0) return stretch;
  return std::copysign(std::max(std::abs(stretch) - held, 0.0), stretch);
}

double ProgramRow::stored_energy() const {
  const double d = indentation();
  const double u = tangential_displacement();
  // Both halves of kz (d - g_i)^2 / 2 and kx (u - s_i)^2 / 2, from the sums the forces keep.
  double energy = (graded_ ? 0.5 : material_.effective_modulus * spacing_) *
                  (contact_count(in_contact_) * d * d - 2.0 * d * contact_images_.value() +
                   sums_.image_squares.value());
  if (friction_) {
    energy += friction_->stored_energy(d, u);
  } else {
    energy +=
        material_.effective_shear_modulus * spacing_ *
        (static_cast<double>(glued_) * u * u - 2.0 * u * glued_offsets_.value() + offset_squares());
  }
  // A compliant machine's spring, stretched by a_F F: F^2 a_F / 2 (a_u = 1).
  const auto spring_of = [](const AffineConstraint& c, double force) {
    return 0.5 * c.force_coefficient / c.displacement_coefficient * force * force;
  };
  if (drives_through_spring(normal_.constraint)) {
    energy += spring_of(normal_.constraint, normal_force());
  }
  if (drives_through_spring(tangential_.constraint)) {
    energy += spring_of(tangential_.constraint, tangential_force());
  }
  return energy;
}

ProgramRow::Edges ProgramRow::edges() const {
  return {glued_,
          in_contact_,
          ever_glued_,
          contact_images_,
          glued_offsets_,
          sums_,
          runs_.size(),
          runs_.empty() ? Run{} : runs_.back(),
          normal_,
          tangential_,
          normal_equilibrium_,
          tangential_equilibrium_,
          normal_cached_,
          tangential_cached_,
          normal_response_cached_,
          tangential_response_cached_,
          normal_per_held_,
          tangential_per_held_};
}

void ProgramRow::restore(const Edges& saved) {
  glued_ = saved.glued;
  in_contact_ = saved.in_contact;
  ever_glued_ = saved.ever_glued;
  contact_images_ = saved.contact_images;
  glued_offsets_ = saved.glued_offsets;
  sums_ = saved.sums;
  runs_.resize(saved.runs);
  if (saved.runs > 0) runs_.back() = saved.last_run;
  normal_ = saved.normal;
  tangential_ = saved.tangential;
  normal_equilibrium_ = saved.normal_equilibrium;
  tangential_equilibrium_ = saved.tangential_equilibrium;
  normal_cached_ = saved.normal_cached;
  tangential_cached_ = saved.tangential_cached;
  normal_response_cached_ = saved.normal_response_cached;
  tangential_response_cached_ = saved.tangential_response_cached;
  normal_per_held_ = saved.normal_per_held;
  tangential_per_held_ = saved.tangential_per_held;
}

ContactSnapshot ProgramRow::snapshot() const {
  ContactSnapshot s;
  s.indentation = indentation();
  s.normal_force = normal_force();
  s.normal_control = normal_.held;
  s.contact_radius = in_contact_ > 0 ? position(in_contact_) : 0.0;
  s.tangential_displacement = tangential_displacement();
  s.tangential_force = tangential_force();
  s.springs_in_contact = in_contact_;
  s.glued_radius = glued_ > 0 ? position(glued_) : 0.0;
  s.time = time_;
  if (friction_) {
    s.springs_sliding = friction_->springs_sliding();
    s.stick_radius = in_contact_ > 0 ? friction_->stick_radius() : 0.0;
  }
  if (!edge_forces_) return s;
  if (in_contact_ > 0) {
    s.edge_normal_force =
        2.0 * half_weight(in_contact_) * std::abs(s.indentation - image(in_contact_));
  }
  if (glued_ > 0) {
    s.edge_tangential_force = 2.0 * material_.effective_shear_modulus * spacing_ *
                              std::abs(s.tangential_displacement - runs_.back().offset);
  }
  return s;
}

}  // namespace mdrsim

// A program row on a parabola, and every observable of two rows compared to the bit: for the
// tests of the row's trial and of the parts that try changes on it and put it back.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>

#include "engine/base/material.hpp"
#include "engine/program/program_row.hpp"
#include "profiles/profile.hpp"

namespace mdrsim::test {

/// Springs i = 1..springs at x_i = i a_ref / springs, spring N at g(a_ref) exactly (as
/// ProgramRowSpec gives it). `profile` must outlive the row.
inline ProgramRow row_on(const Profile& profile, const Material& material, double reference_radius,
                         std::int64_t springs, bool rebinding = false) {
  return ProgramRow(profile, material, reference_radius, springs,
                    profile.mdr_image(reference_radius), rebinding);
}

/// The fields in which two states differ, one line each: doubles to the bit (-0 against +0
/// too: a held -0 means something to the row).
class Differences {
 public:
  void bits(double a, double b, const std::string& what) {
    if (std::bit_cast<std::uint64_t>(a) != std::bit_cast<std::uint64_t>(b)) {
      out_ << "  " << what << ": " << a << " against " << b << "\n";
    }
  }
  void same(std::int64_t a, std::int64_t b, const std::string& what) {
    if (a != b) out_ << "  " << what << ": " << a << " against " << b << "\n";
  }
  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_ = [] {
    std::ostringstream out;
    out << std::setprecision(17);
    return out;
  }();
};

inline void add_axis(Differences& d, const MachineAxis& a, const MachineAxis& b,
                     const std::string& what) {
  d.bits(a.constraint.displacement_coefficient, b.constraint.displacement_coefficient,
         what + " a_u");
  d.bits(a.constraint.force_coefficient, b.constraint.force_coefficient, what + " a_F");
  d.bits(a.held, b.held, what + " held");
  d.bits(a.rest, b.rest, what + " rest");
}

inline void add_snapshot(Differences& d, const ContactSnapshot& a, const ContactSnapshot& b) {
  d.bits(a.normal_control, b.normal_control, "normal_control");
  d.bits(a.indentation, b.indentation, "indentation");
  d.bits(a.normal_force, b.normal_force, "normal_force");
  d.bits(a.contact_radius, b.contact_radius, "contact_radius");
  d.bits(a.tangential_displacement, b.tangential_displacement, "tangential_displacement");
  d.bits(a.tangential_force, b.tangential_force, "tangential_force");
  d.same(a.springs_in_contact, b.springs_in_contact, "springs_in_contact");
  d.same(a.springs_sliding, b.springs_sliding, "springs_sliding");
  d.bits(a.stick_radius, b.stick_radius, "stick_radius");
  d.bits(a.edge_normal_force, b.edge_normal_force, "edge_normal_force");
  d.bits(a.edge_tangential_force, b.edge_tangential_force, "edge_tangential_force");
  d.bits(a.glued_radius, b.glued_radius, "glued_radius");
  d.same(a.disk_valid, b.disk_valid, "disk_valid");
}

inline void expect_same_snapshot(const ContactSnapshot& a, const ContactSnapshot& b,
                                 const std::string& what) {
  Differences d;
  add_snapshot(d, a, b);
  EXPECT_EQ(d.text(), "") << what;
}

/// What the row's accessors answer now, where they differ. Reads both rows alike: the answers
/// fill the same caches in each, so that two rows read together stay alike.
inline std::string answer_differences(const ProgramRow& a, const ProgramRow& b) {
  Differences d;
  d.same(a.glued(), b.glued(), "k");
  d.same(a.in_contact(), b.in_contact(), "m");
  if (a.glued() != b.glued() || a.in_contact() != b.in_contact()) return d.text();
  d.same(a.one_offset(), b.one_offset(), "one_offset");
  if (a.glued() > 0) d.bits(a.boundary_offset(), b.boundary_offset(), "s_k");
  add_axis(d, a.normal(), b.normal(), "normal");
  add_axis(d, a.tangential(), b.tangential(), "tangential");
  d.same(a.normal_has_stiffness(), b.normal_has_stiffness(), "normal_has_stiffness");
  d.same(a.tangential_has_stiffness(), b.tangential_has_stiffness(), "tangential_has_stiffness");
  d.bits(a.indentation(), b.indentation(), "d");
  d.bits(a.normal_force(), b.normal_force(), "F");
  d.bits(a.tangential_displacement(), b.tangential_displacement(), "u_x");
  d.bits(a.tangential_force(), b.tangential_force(), "F_x");
  d.bits(a.indentation_per_held(), b.indentation_per_held(), "dd/dheld");
  d.bits(a.tangential_per_held(), b.tangential_per_held(), "du_x/dheld");
  d.bits(a.tangential_per_indentation(), b.tangential_per_indentation(), "du_x/dd");
  // The sums over the springs, away from the equilibrium: sum g_i and sum s_i.
  const double probe = a.image(a.reference_springs());
  d.bits(a.normal_force_at(probe), b.normal_force_at(probe), "F(d = g_N)");
  d.bits(a.tangential_force_at(probe), b.tangential_force_at(probe), "F_x(u_x = g_N)");
  // The springs glued once (which may not glue again without rebinding).
  for (std::int64_t i = 1; i <= a.reference_springs() + 1; ++i) {
    d.same(a.can_glue(i), b.can_glue(i), "can_glue(" + std::to_string(i) + ")");
  }
  add_snapshot(d, a.snapshot(), b.snapshot());
  return d.text();
}

/// Every field of two rows without friction: the accessors' answers, and the state they do
/// not show at once (each run of glued springs and its offset, the sums' rounding) read off
/// copies of both, unwound one spring at a time. Reports the first state that differs.
inline void expect_same_row(const ProgramRow& a, const ProgramRow& b, const std::string& what) {
  std::string differ = answer_differences(a, b);
  if (!differ.empty()) {
    ADD_FAILURE() << what << ", the rows differ in\n" << differ;
    return;
  }
  ProgramRow x = a;
  ProgramRow y = b;
  while (x.in_contact() > 0) {
    const std::string step =
        "k = " + std::to_string(x.glued()) + ", m = " + std::to_string(x.in_contact());
    if (x.in_contact() > x.glued()) {
      x.lift_outer();
      y.lift_outer();
    } else {
      x.let_go_boundary(false);
      y.let_go_boundary(false);
    }
    differ = answer_differences(x, y);
    if (!differ.empty()) {
      ADD_FAILURE() << what << ", the rows unwound from " << step << " differ in\n" << differ;
      return;
    }
  }
}

}  // namespace mdrsim::test

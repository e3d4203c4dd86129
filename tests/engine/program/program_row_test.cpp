// The program's spring row: its forces as the sums over the springs, and its trial, which must
// put back every field a change at the edges or of the held values alters, to the bit.
#include "engine/program/program_row.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "profiles/parabolic_profile.hpp"
#include "tests/support/program_row_state.hpp"

namespace mdrsim {
namespace {

using test::expect_same_row;
using test::expect_same_snapshot;
using test::row_on;

constexpr double kRadius = 0.01;  // R [m]
// E* = 1 MPa, G* = 0.8 MPa (nu = 0.3 gives about that), dgamma = 0.05 J/m^2, dgamma_a = 0.01.
const Material kMaterial{.effective_modulus = 1e6,
                         .effective_shear_modulus = 0.8e6,
                         .work_of_adhesion = 0.05,
                         .approach_work_of_adhesion = 0.01};

constexpr AffineConstraint kFixedGrips{1.0, 0.0};
constexpr AffineConstraint kFixedLoad{0.0, 1.0};
constexpr AffineConstraint kCompliant{1.0, 1.0 / 200.0};  // a machine spring of 200 N/m

/// 300 springs across 0.3 mm: g_N = 9 um.
constexpr std::int64_t kSprings = 300;
constexpr double kReference = 3e-4;  // a_ref [m]

/// A row with three runs of glued springs (offsets 0, 20 nm and -10 nm), springs pressed
/// outside them, the normal axis through a machine spring and the tangential one at a held
/// force: every sum and every cache of the row holds something.
ProgramRow mixed_row(const Profile& profile) {
  ProgramRow row = row_on(profile, kMaterial, kReference, kSprings);
  row.record_edge_forces(true);
  row.edit_normal().constraint = kFixedGrips;
  row.set_normal_held(8e-6);
  row.glue_through(100);
  row.set_tangential_held(2e-8);
  for (int i = 0; i < 50; ++i) row.glue_next();
  row.set_tangential_held(-1e-8);
  for (int i = 0; i < 40; ++i) row.glue_next();
  for (int i = 0; i < 30; ++i) row.touch_next();
  // Held values that keep the same equilibrium under the new constraints.
  const double w = row.held_value_of_normal(kCompliant);
  row.edit_normal() = {kCompliant, w, 0.0};
  const double f = row.held_value_of_tangential(kFixedLoad);
  row.edit_tangential() = {kFixedLoad, f, 0.0};
  return row;
}

/// Every spring in contact glued in one run, both axes at fixed grips.
ProgramRow one_run_row(const Profile& profile) {
  ProgramRow row = row_on(profile, kMaterial, kReference, kSprings);
  row.set_normal_held(4e-6);
  row.set_tangential_held(5e-9);
  row.glue_through(120);
  return row;
}

/// Nothing in contact: the normal axis at a held force, resting at 1 um.
ProgramRow empty_row(const Profile& profile) {
  ProgramRow row = row_on(profile, kMaterial, kReference, kSprings);
  row.edit_normal() = {kFixedLoad, 1e-3, 1e-6};
  return row;
}

struct NamedChange {
  std::string name;
  std::function<bool(const ProgramRow&)> allowed;
  std::function<void(ProgramRow&)> apply;
};

/// Every change the row offers that a trial may make: one change at the edges, or new held
/// values or constraints (the trial's contract, program_row.hpp).
std::vector<NamedChange> changes() {
  const auto always = [](const ProgramRow&) { return true; };
  const auto glued = [](const ProgramRow& r) { return r.glued() > 0; };
  const auto room = [](const ProgramRow& r) { return r.in_contact() < r.reference_springs(); };
  return {
      {"touch_next", room, [](ProgramRow& r) { r.touch_next(); }},
      {"lift_outer", [](const ProgramRow& r) { return r.in_contact() > r.glued(); },
       [](ProgramRow& r) { r.lift_outer(); }},
      {"glue_next", [](const ProgramRow& r) { return r.glued() < r.reference_springs(); },
       [](ProgramRow& r) { r.glue_next(); }},
      {"glue_next_as_boundary",
       [](const ProgramRow& r) { return r.glued() < r.reference_springs(); },
       [](ProgramRow& r) { r.glue_next_as_boundary(); }},
      {"glue_through",
       [](const ProgramRow& r) {
         return r.glued() == r.in_contact() && r.glued() + 10 <= r.reference_springs();
       },
       [](ProgramRow& r) { r.glue_through(r.glued() + 10); }},
      {"let_go_boundary(pressed)", glued, [](ProgramRow& r) { r.let_go_boundary(true); }},
      {"let_go_boundary(leaves)", glued, [](ProgramRow& r) { r.let_go_boundary(false); }},
      {"set_normal_held", always, [](ProgramRow& r) { r.set_normal_held(r.normal().held * 0.5); }},
      {"set_tangential_held", always,
       [](ProgramRow& r) { r.set_tangential_held(r.tangential().held + 3e-9); }},
      {"edit_normal", always,
       [](ProgramRow& r) {
         r.edit_normal() = {kFixedLoad, -1e-4, 2e-6};
       }},
      {"edit_tangential", always,
       [](ProgramRow& r) {
         r.edit_tangential() = {kCompliant, 1e-8, -1e-9};
       }},
      {"new held values and a glue", room,
       [](ProgramRow& r) {
         r.set_normal_held(r.normal().held + 1e-7);
         r.set_tangential_held(r.tangential().held - 1e-9);
         r.glue_next();
       }},
  };
}

// The forces are the sums over the springs, both halves: F = 2 E* dx sum_{i<=m} (d - g_i),
// F_x = 2 G* dx sum_{i<=k} (u_x - s_i), here on 4 springs (2 glued at s = 0 and 10 nm, one
// more pressed) with g_i = (i dx)^2/R computed apart. To 1e-14 relative: a few roundings of
// sums of four terms.
TEST(ProgramRow, ForcesAreTheSumsOverTheSprings) {
  const ParabolicProfile profile(kRadius);
  const double dx = 1e-4;
  ProgramRow row = row_on(profile, kMaterial, 4.0 * dx, 4);
  const double d = 5e-6;
  const double u = 3e-8;
  row.set_normal_held(d);
  row.glue_next();  // s_1 = 0
  row.set_tangential_held(1e-8);
  row.glue_next();  // s_2 = 10 nm
  row.touch_next();
  row.set_tangential_held(u);
  ASSERT_EQ(row.glued(), 2);
  ASSERT_EQ(row.in_contact(), 3);
  const auto g = [&](int i) { return (i * dx) * (i * dx) / kRadius; };
  const double normal = 2.0 * 1e6 * dx * ((d - g(1)) + (d - g(2)) + (d - g(3)));
  const double tangential = 2.0 * 0.8e6 * dx * ((u - 0.0) + (u - 1e-8));
  EXPECT_EQ(row.indentation(), d);
  EXPECT_EQ(row.tangential_displacement(), u);
  EXPECT_NEAR(row.normal_force(), normal, 1e-14 * std::abs(normal));
  EXPECT_NEAR(row.tangential_force(), tangential, 1e-14 * std::abs(tangential));
  EXPECT_EQ(row.boundary_offset(), 1e-8);
  EXPECT_FALSE(row.one_offset());

  // Under a held force the indentation is the one that carries it: F = K d - C, K = 2 E* dx m.
  row.edit_normal() = {kFixedLoad, normal, 0.0};
  EXPECT_NEAR(row.indentation(), d, 1e-14 * d);
  EXPECT_NEAR(row.indentation_per_held(), 1.0 / (2.0 * 1e6 * dx * 3.0), 1e-15 / (2.0 * 1e6 * dx));
}

// A trial of each change, from three rows (three runs and pressed springs under a machine
// spring and a held force; one run at fixed grips; nothing in contact), shows its look the row
// as the change leaves it (to the bit: the same change applied to a copy) and puts every field
// back (to the bit: a copy taken before).
TEST(ProgramRow, ATrialOfEachChangeRestoresEveryField) {
  const ParabolicProfile profile(kRadius);
  int tried = 0;
  for (const auto& [state, make] :
       std::vector<std::pair<std::string, std::function<ProgramRow(const Profile&)>>>{
           {"mixed", mixed_row}, {"one run", one_run_row}, {"empty", empty_row}}) {
    for (const NamedChange& change : changes()) {
      ProgramRow row = make(profile);
      if (!change.allowed(row)) continue;
      const std::string where = state + ", " + change.name;
      // The row as it stands, read before the copies are taken so that their caches agree.
      (void)row.snapshot();
      const ProgramRow before = row;
      ProgramRow changed = row;
      change.apply(changed);
      const ContactSnapshot seen =
          row.trial(change.apply, [](const ProgramRow& r) { return r.snapshot(); });
      expect_same_snapshot(seen, changed.snapshot(), where + ": the trial's look");
      expect_same_row(row, before, where + ": after the trial");
      ++tried;
    }
  }
  // Every change from each row that allows it: 11 + 11 + 9.
  EXPECT_EQ(tried, 31);
}

/// One random change the row allows (uniform over those that apply), with random values.
void random_change(ProgramRow& row, std::mt19937_64& rng, const std::vector<NamedChange>& all) {
  std::vector<const NamedChange*> allowed;
  for (const NamedChange& c : all) {
    if (c.allowed(row)) allowed.push_back(&c);
  }
  const auto pick = std::uniform_int_distribution<std::size_t>(0, allowed.size() - 1)(rng);
  allowed[pick]->apply(row);
}

/// Random changes with random values, each a function of the row and the generator's draw,
/// so that the same draws give the same changes on two rows.
std::vector<NamedChange> random_changes(std::mt19937_64& rng) {
  std::vector<NamedChange> all = changes();
  const auto always = [](const ProgramRow&) { return true; };
  const auto constraint = [&rng]() {
    const AffineConstraint kinds[] = {kFixedGrips, kFixedLoad, kCompliant};
    return kinds[std::uniform_int_distribution<int>(0, 2)(rng)];
  };
  const auto value = [&rng](double scale) {
    return std::uniform_real_distribution<double>(-scale, scale)(rng);
  };
  all.push_back({"random normal held", always, [=](ProgramRow& r) {
                   r.set_normal_held(is_fixed_grips(r.normal().constraint) ? value(1e-5)
                                                                           : value(1e-2));
                 }});
  all.push_back({"random tangential held", always,
                 [=](ProgramRow& r) { r.set_tangential_held(value(5e-8)); }});
  all.push_back(
      {"random normal constraint", always, [=](ProgramRow& r) {
         const AffineConstraint c = constraint();
         r.edit_normal() = {c, is_fixed_grips(c) ? value(1e-5) : value(1e-2), value(1e-5)};
       }});
  all.push_back({"random tangential constraint", always, [=](ProgramRow& r) {
                   const AffineConstraint c = constraint();
                   r.edit_tangential() = {c, value(5e-8), value(1e-8)};
                 }});
  all.push_back({"glue through a random spring",
                 [](const ProgramRow& r) {
                   return r.glued() == r.in_contact() && r.glued() < r.reference_springs();
                 },
                 [&rng](ProgramRow& r) {
                   r.glue_through(std::uniform_int_distribution<std::int64_t>(
                       r.glued() + 1, r.reference_springs())(rng));
                 }});
  return all;
}

// A row and an independent copy take the same random changes (500 per sequence, 40 seeds);
// between them the first also takes trials of random changes, which it rolls back. The rows
// must agree in every field after every 50th change, the last one included. The row has 60 springs,
// so that sequences fill and empty it; without rebinding, so that the springs glued once show.
TEST(ProgramRow, RandomChangesWithRolledBackTrialsLeaveTheRowAsItsCopy) {
  const ParabolicProfile profile(kRadius);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    const std::vector<NamedChange> all = random_changes(rng);
    ProgramRow row = row_on(profile, kMaterial, 6e-5, 60);
    row.record_edge_forces(true);
    ProgramRow copy = row;
    int trials = 0;
    for (int step = 1; step <= 500; ++step) {
      // The same draws for both rows: the generator's state before the change, replayed.
      const std::mt19937_64 before = rng;
      random_change(row, rng, all);
      rng = before;
      random_change(copy, rng, all);
      if (std::uniform_int_distribution<int>(0, 2)(rng) > 0) {
        ++trials;
        row.trial([&](ProgramRow& r) { random_change(r, rng, all); },
                  [](const ProgramRow& r) { return r.snapshot(); });
      }
      if (step % 50 == 0) {
        expect_same_row(row, copy,
                        "seed " + std::to_string(seed) + ", step " + std::to_string(step));
        if (HasFailure()) return;
      }
    }
    EXPECT_GT(trials, 250) << seed;
  }
}

}  // namespace
}  // namespace mdrsim

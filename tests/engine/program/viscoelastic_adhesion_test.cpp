// The adhesive edge under a relaxing bulk, run by `mdrsim run`'s path (run_scene) on a parabola
// and a standard linear solid, against derivations written here from the row's definition
// (SPEC "Time and viscoelastic media", no engine code): JKR's pull-off in the slow and fast
// limits, the relaxed retraction's speed-independent pull-off, gluing at the advancing gap,
// rebinding, and each stage's energy balance with the cascade's losses.
//
// The derivations. Spring i sits at x_i = i a_max / N, g_i = x_i^2 / R, and carries the line
// load q_i = E_inf (d - g_i) + sum_j sigma_ij. A let-go is instantaneous (the dashpots do not
// move): the boundary spring k lets go at q_k = -t_k, t_k = sqrt(2 pi x_k dgamma E_0), and
// releases q_k^2 / (2 E_0) per unit length of each half, 2 dx of them: at the threshold, the
// ring's 2 pi x_k dgamma dx. Where every glued spring's arms carry one stress S(t) (after a
// hold that relaxed them all; or a retraction slower than tau, which drives them all to one
// steady E_1 tau d'), q_i = q_k + E_inf (g_k - g_i), so the force as spring k lets go is
//   F_k = 2 dx sum_{i <= k} q_i = 2 dx [ -k t_k + E_inf sum_{i <= k} (g_k - g_i) ],
// whatever S: the pull-off min_k F_k does not depend on the speed. In the continuum,
// 2 int_0^a (g(a) - g(x)) dx = 4 a^3 / (3R) and 2 a t(a) = sqrt(8 pi a^3 dgamma E_0):
// F(a) = 4 E_inf a^3 / (3R) - sqrt(8 pi a^3 dgamma E_0), JKR's curve of E_inf with dgamma
// E_0 / E_inf, least at -(3/2) pi R dgamma E_0 / E_inf. A cycle much faster than tau keeps
// every arm glassy, q_i = E_0 (d - g_i): JKR of (E_0, dgamma), least at -(3/2) pi R dgamma.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kRadius = 0.01;             // R [m]
constexpr double kRelaxed = 1.0e6;           // E*_inf [Pa]
constexpr double kArm = 9.0e6;               // E*_1 [Pa]
constexpr double kGlassy = kRelaxed + kArm;  // E*_0 [Pa]
constexpr double kTau = 0.1;                 // [s]
constexpr double kDgamma = 0.05;             // [J/m^2]

struct Cycle {
  double preload;        // the press's depth [m]
  double press_speed;    // [m/s]
  double hold = 0.0;     // [s]; 0: no hold stage
  double retract_speed;  // [m/s]
  std::int64_t springs;
  double approach = 0.0;  // dgamma_a [J/m^2]
  bool rebinding = false;
  double stop_at = -1.0;  // > 0: the retraction stops at this depth and a second press follows
};

std::string cycle_text(const Cycle& c) {
  std::string text = fmt::format(
      "[material]\neffective_modulus = {}\nwork_of_adhesion = {}\n"
      "approach_work_of_adhesion = {}\nrelaxation = [ {{ modulus = {}, time = {} }} ]\n"
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[loading]\nrebinding = {}\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
      "speed = {}\n",
      kRelaxed, kDgamma, c.approach, kArm, kTau, kRadius, c.rebinding ? "true" : "false", c.preload,
      c.press_speed);
  if (c.hold > 0.0)
    text += fmt::format("[[loading.stage]]\nname = \"hold\"\nduration = {}\n", c.hold);
  if (c.stop_at > 0.0) {
    text += fmt::format(
        "[[loading.stage]]\nname = \"withdraw\"\nnormal = {{ to = {} }}\nspeed = {}\n"
        "[[loading.stage]]\nname = \"press-again\"\nnormal = {{ to = {} }}\nspeed = {}\n",
        c.stop_at, c.retract_speed, c.preload, c.press_speed);
  } else {
    text += fmt::format(
        "[[loading.stage]]\nname = \"withdraw\"\nnormal = {{ by = -1.0 }}\n"
        "until = \"separation\"\nspeed = {}\n",
        c.retract_speed);
  }
  text += fmt::format("[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n", c.springs);
  return text;
}

/// Every glue and let-go, in order.
class EdgeChanges : public Observer {
 public:
  void on_event(const Event& e) override {
    if (e.kind == EventKind::spring_glued || e.kind == EventKind::spring_detached ||
        e.kind == EventKind::spring_touched) {
      changes.push_back(e.state);
      kinds.push_back(e.kind);
      stages.emplace_back(e.stage);
    }
  }
  std::int64_t count(EventKind kind, const std::string& stage) const {
    std::int64_t n = 0;
    for (std::size_t i = 0; i < kinds.size(); ++i) n += kinds[i] == kind && stages[i] == stage;
    return n;
  }
  std::vector<ContactSnapshot> changes;
  std::vector<EventKind> kinds;
  std::vector<std::string> stages;
};

struct CycleRun {
  RunResult result;
  EdgeChanges edge;
};

CycleRun run_cycle(const Cycle& c) {
  CycleRun run;
  const Scene scene =
      SceneDocument::from_text(cycle_text(c), "cycle.toml").build(Registries::builtin());
  ObserverList observers;
  observers.add(run.edge);
  run.result = run_scene(scene, observers);
  return run;
}

/// The let-go threshold t(x) = sqrt(2 pi x dgamma E_0) [N/m].
double threshold(double x) { return std::sqrt(2.0 * std::numbers::pi * x * kDgamma * kGlassy); }

/// min_k F_k of the springs x_i = i a / N pressed with a common arm stress, the springs of
/// modulus `modulus` (E_inf relaxed, E_0 glassy) [N].
double row_pull_off(double a_max, std::int64_t n, double modulus) {
  const double dx = a_max / static_cast<double>(n);
  double best = std::numeric_limits<double>::infinity();
  double images = 0.0;
  for (std::int64_t k = 1; k <= n; ++k) {
    const double x = dx * static_cast<double>(k);
    const double g = x * x / kRadius;
    images += g;
    const double f =
        2.0 * dx *
        (-static_cast<double>(k) * threshold(x) + modulus * (static_cast<double>(k) * g - images));
    best = std::min(best, f);
  }
  return best;
}

/// -(3/2) pi R dgamma_eff of JKR [N].
double jkr_pull_off(double dgamma) { return -1.5 * std::numbers::pi * kRadius * dgamma; }

TEST(ViscoelasticAdhesion, RelaxedPullOffDoesNotDependOnTheSpeed) {
  // Pressed to a = 1.5 mm, held 100 tau: the arms keep exp(-100) of their stress.
  const double preload = 2.25e-4;
  const double a_max = std::sqrt(kRadius * preload);
  const double continuum = jkr_pull_off(kDgamma * kGlassy / kRelaxed);
  std::printf("relaxed retraction (held 100 tau): pull-off against the speed\n");
  std::printf("%8s %10s %24s %16s %14s %14s\n", "springs", "V [m/s]", "pull-off F [N]",
              "d there [m]", "vs row sum", "vs JKR");
  for (const std::int64_t n : {200, 800}) {
    const double row_sum = row_pull_off(a_max, n, kRelaxed);
    std::vector<double> forces;
    std::vector<double> depths;
    for (const double speed : {1.0e-6, 1.0e-5, 1.0e-4, 1.0e-3, 1.0e-2}) {
      const CycleRun run = run_cycle({preload, 1.0e-3, 100.0 * kTau, speed, n});
      const RunResult& r = run.result;
      ASSERT_TRUE(r.peak.has_value());
      forces.push_back(r.peak->normal_force);
      depths.push_back(r.peak->indentation);
      std::printf("%8lld %10.0e %24.16e %16.9e %14.2e %14.2e\n", static_cast<long long>(n), speed,
                  r.peak->normal_force, r.peak->indentation,
                  std::abs(r.peak->normal_force / row_sum - 1.0),
                  std::abs(r.peak->normal_force / continuum - 1.0));
      // The row's own sum of the same springs, to the rounding of a sum of n loads.
      EXPECT_NEAR(r.peak->normal_force, row_sum, 1e-10 * std::abs(row_sum)) << n << " " << speed;
      EXPECT_EQ(r.status, RunStatus::instability);
    }
    const auto [lo, hi] = std::minmax_element(forces.begin(), forces.end());
    // Four decades of speed, one pull-off: the SPEC's 1e-6.
    EXPECT_LT((*hi - *lo) / std::abs(continuum), 1e-6) << n;
    // Only the displacement moves: a faster retraction pulls the arms into tension sooner, so
    // the pull-off comes at a deeper indentation.
    for (std::size_t i = 1; i < depths.size(); ++i) EXPECT_GT(depths[i], depths[i - 1]) << n;
    // The row's sum against the continuum's: the edge's discreteness, O(1/N) (1.0 % at 200
    // springs, a* at 75 of them).
    EXPECT_NEAR(row_sum, continuum, 300.0 / static_cast<double>(n) * 1e-2 * std::abs(continuum));
  }
}

TEST(ViscoelasticAdhesion, SlowAndFastLimitsAreJkrOfTheRelaxedAndGlassyModuli) {
  std::printf("limits: pull-off against JKR\n");
  std::printf("%6s %8s %22s %22s %12s %12s\n", "limit", "springs", "pull-off F [N]", "JKR [N]",
              "vs row sum", "vs JKR");
  for (const std::int64_t n : {200, 800}) {
    // Slow: 1e-7 m/s, the press 2250 s = 22500 tau. Every arm reaches the steady
    // E_1 tau V, common to the glued springs: the relaxed row's sum exactly.
    const double slow_preload = 2.25e-4;
    const CycleRun slow = run_cycle({slow_preload, 1.0e-7, 0.0, 1.0e-7, n});
    const double slow_sum = row_pull_off(std::sqrt(kRadius * slow_preload), n, kRelaxed);
    const double slow_jkr = jkr_pull_off(kDgamma * kGlassy / kRelaxed);
    // Fast: 100 m/s, the cycle ~2e-7 s = 2e-6 tau: the arms relax by that share.
    const double fast_preload = 9.0e-6;  // a = 0.3 mm, a* = 0.12 mm
    const CycleRun fast = run_cycle({fast_preload, 100.0, 0.0, 100.0, n});
    const double fast_sum = row_pull_off(std::sqrt(kRadius * fast_preload), n, kGlassy);
    const double fast_jkr = jkr_pull_off(kDgamma);
    ASSERT_TRUE(slow.result.peak && fast.result.peak);
    const double slow_f = slow.result.peak->normal_force;
    const double fast_f = fast.result.peak->normal_force;
    std::printf("%6s %8lld %22.14e %22.14e %12.2e %12.2e\n", "slow", static_cast<long long>(n),
                slow_f, slow_jkr, std::abs(slow_f / slow_sum - 1.0),
                std::abs(slow_f / slow_jkr - 1.0));
    std::printf("%6s %8lld %22.14e %22.14e %12.2e %12.2e\n", "fast", static_cast<long long>(n),
                fast_f, fast_jkr, std::abs(fast_f / fast_sum - 1.0),
                std::abs(fast_f / fast_jkr - 1.0));
    // Slow: the common steady stress drops out of F_k, to the rounding of the sum.
    EXPECT_NEAR(slow_f, slow_sum, 1e-10 * std::abs(slow_sum));
    // Fast: the arms relax by ~t / tau = 2e-6 of the glassy load over the cycle.
    EXPECT_NEAR(fast_f, fast_sum, 1e-5 * std::abs(fast_sum));
    // Against JKR: the row's O(1/N) (1.0 % at 200 springs, a* at 0.37 N and 0.4 N).
    const double discreteness = 300.0 / static_cast<double>(n) * 1e-2;
    EXPECT_NEAR(slow_f, slow_jkr, discreteness * std::abs(slow_jkr));
    EXPECT_NEAR(fast_f, fast_jkr, discreteness * std::abs(fast_jkr));
    EXPECT_EQ(slow.result.status, RunStatus::instability);
    EXPECT_EQ(fast.result.status, RunStatus::instability);
  }
}

TEST(ViscoelasticAdhesion, CycleBalancesEveryStageAndTheCascadeLosesItsExcess) {
  const double preload = 2.25e-4;
  const double a_max = std::sqrt(kRadius * preload);
  std::printf("cycle (press, hold 100 tau, withdraw to separation): energy per stage [J]\n");
  std::printf("%8s %10s %13s %13s %13s %13s %13s %10s\n", "springs", "stage", "machine", "stored",
              "surface", "bulk", "jump_losses", "residual");
  for (const std::int64_t n : {200, 800}) {
    const CycleRun run = run_cycle({preload, 1.0e-3, 100.0 * kTau, 1.0e-3, n});
    const RunResult& r = run.result;
    ASSERT_EQ(r.stages.size(), 3u);
    const double dx = a_max / static_cast<double>(n);
    double rings = 0.0;  // sum of 2 pi x dgamma dx over every spring
    for (std::int64_t i = 1; i <= n; ++i) {
      rings += 2.0 * std::numbers::pi * dx * static_cast<double>(i) * kDgamma * dx;
    }
    for (const StageRecord& s : r.stages) {
      ASSERT_TRUE(s.energy.has_value());
      const EnergyBalance& e = *s.energy;
      std::printf("%8lld %10s %13.6e %13.6e %13.6e %13.6e %13.6e %10.1e\n",
                  static_cast<long long>(n), s.name.c_str(), e.machine_work, e.stored_change,
                  e.surface_change, e.dissipated_by_bulk, e.jump_losses, e.residual);
      // Each term summed apart, in closed form per spring: the residual is rounding.
      const double scale = std::max(
          {std::abs(e.machine_work), std::abs(e.stored_change), std::abs(e.dissipated_by_bulk)});
      EXPECT_LT(std::abs(e.residual), 1e-12 * scale) << s.name;
    }
    // Every spring glued on touch (dgamma_a = 0): no stretch, the whole ring is lost.
    const double glued = r.stages[0].energy->surface_change + r.stages[1].energy->surface_change;
    EXPECT_NEAR(glued, -rings, 1e-12 * rings);
    EXPECT_NEAR(r.stages[0].energy->jump_losses + r.stages[1].energy->jump_losses, rings,
                1e-12 * rings);
    // The withdrawal lets every spring go: each releases q^2 / (2 E_0) per half-length. Spring K
    // (the critical point's boundary) lets go at its threshold, its ring exactly; the cascade's
    // springs i < K hold q_i = -t_K + E_inf (g_K - g_i) then, their excess over the ring lost.
    const EnergyBalance& withdraw = *r.stages[2].energy;
    EXPECT_NEAR(withdraw.surface_change, rings, 1e-12 * rings);
    ASSERT_TRUE(r.critical.has_value());
    const std::int64_t k = r.critical->springs_in_contact;
    const double xk = dx * static_cast<double>(k);
    double excess = 0.0;
    for (std::int64_t i = 1; i < k; ++i) {
      const double x = dx * static_cast<double>(i);
      const double q = -threshold(xk) + kRelaxed * (xk * xk - x * x) / kRadius;
      excess += (q * q / (2.0 * kGlassy) - std::numbers::pi * x * kDgamma) * 2.0 * dx;
    }
    std::printf("%8lld cascade of %lld springs: jump_losses %.12e, derived %.12e\n",
                static_cast<long long>(n), static_cast<long long>(k), withdraw.jump_losses, excess);
    EXPECT_GT(excess, 0.0);
    EXPECT_NEAR(withdraw.jump_losses, excess, 1e-9 * excess);
    // The cascade is the run's one jump, and it loses the contact.
    ASSERT_EQ(r.jumps.size(), 1u);
    EXPECT_FALSE(r.jumps[0].inward);
    EXPECT_EQ(r.jumps[0].springs, -k);
    EXPECT_EQ(r.jumps[0].glued_springs, -k);
    EXPECT_EQ(r.jumps[0].critical.normal_force, r.critical->normal_force);
    EXPECT_EQ(r.critical_stage, "withdraw");
    EXPECT_EQ(r.status, RunStatus::instability);
  }
}

TEST(ViscoelasticAdhesion, TheAdvancingFrontGluesAtTheGlassyGap) {
  // dgamma_a = 0.02: the spring outside the contact glues at g(x) - d = sqrt(2 pi x dgamma_a /
  // E_0), the first on touch. Near the axis that gap grows faster with x than g does, so the
  // springs after the first are already within theirs: they glue at once, a jump in.
  const double approach = 0.02;
  const CycleRun run = run_cycle({2.25e-4, 1.0e-3, 0.0, 1.0e-3, 200, approach});
  const RunResult& r = run.result;
  double worst = 0.0;
  double losses = 0.0;
  std::int64_t glues = 0;
  std::int64_t on_their_own = 0;
  double previous_time = -1.0;
  for (std::size_t i = 0; i < run.edge.kinds.size(); ++i) {
    if (run.edge.kinds[i] != EventKind::spring_glued || run.edge.stages[i] != "press") continue;
    const ContactSnapshot& s = run.edge.changes[i];
    const double x = s.contact_radius;
    const double gap = x * x / kRadius - s.indentation;
    const double limit = std::sqrt(2.0 * std::numbers::pi * x * approach / kGlassy);
    if (glues == 0) {
      EXPECT_NEAR(gap, 0.0, 1e-15) << "the first glues on touch";
    } else if (s.time != previous_time) {
      worst = std::max(worst, std::abs(gap - limit) / limit);
      ++on_their_own;
    } else {
      EXPECT_LT(gap, limit * (1.0 + 1e-12)) << "a jump in glues within the gap";
    }
    // Each glue costs the ring 2 pi x dgamma dx and stores E_0 gap^2 dx (both halves).
    const double dx = x / static_cast<double>(s.springs_in_contact);
    losses += 2.0 * std::numbers::pi * x * kDgamma * dx - kGlassy * gap * gap * dx;
    previous_time = s.time;
    ++glues;
  }
  std::printf(
      "advancing front: %lld glues, %lld on their own: largest |gap - glassy gap| / gap "
      "%.2e; %zu jump(s) in\n",
      static_cast<long long>(glues), static_cast<long long>(on_their_own), worst,
      static_cast<std::size_t>(std::count_if(r.jumps.begin(), r.jumps.end(),
                                             [](const JumpRecord& j) { return j.inward; })));
  EXPECT_GT(on_their_own, 100);
  // The gap is d's distance to g at the located time: rounding of d and g (~1e-16 of 2e-4 m)
  // against gaps of ~1e-6 m.
  EXPECT_LT(worst, 1e-8);
  ASSERT_FALSE(r.jumps.empty());
  EXPECT_TRUE(r.jumps[0].inward);
  ASSERT_TRUE(r.stages[0].energy.has_value());
  EXPECT_NEAR(r.stages[0].energy->jump_losses, losses, 1e-8 * losses);
  for (const StageRecord& s : r.stages) {
    EXPECT_LT(std::abs(s.energy->residual), 1e-12 * std::abs(s.energy->machine_work)) << s.name;
  }
}

TEST(ViscoelasticAdhesion, RebindingDecidesWhetherALetGoSpringGluesAgain) {
  for (const bool rebinding : {false, true}) {
    // Pressed, withdrawn part way (some springs let go, the contact stays), pressed back.
    Cycle c{2.25e-4, 1.0e-3, 0.0, 1.0e-3, 200};
    c.rebinding = rebinding;
    c.stop_at = 2.12e-4;
    const CycleRun run = run_cycle(c);
    const RunResult& r = run.result;
    const std::int64_t let_go = run.edge.count(EventKind::spring_detached, "withdraw");
    const std::int64_t touched = run.edge.count(EventKind::spring_touched, "press-again");
    const std::int64_t reglued = run.edge.count(EventKind::spring_glued, "press-again");
    std::printf("rebinding = %d: %lld let go, then %lld touched, %lld glued again\n", rebinding,
                static_cast<long long>(let_go), static_cast<long long>(touched),
                static_cast<long long>(reglued));
    EXPECT_GT(let_go, 0);
    EXPECT_GT(r.stages[1].end.springs_in_contact, 0);
    EXPECT_EQ(r.status, RunStatus::completed);
    if (rebinding) {
      EXPECT_EQ(touched, 0);
      EXPECT_GT(reglued, 0);
    } else {
      EXPECT_EQ(reglued, 0);
      EXPECT_GT(touched, 0);
    }
    for (const StageRecord& s : r.stages) {
      const double scale =
          std::max(std::abs(s.energy->machine_work), std::abs(s.energy->stored_change));
      EXPECT_LT(std::abs(s.energy->residual), 1e-12 * scale) << s.name;
      EXPECT_GT(s.energy->jump_losses, -1e-12 * scale) << s.name;
    }
  }
}

TEST(ViscoelasticAdhesion, AVanishingArmIsTheElasticProgram) {
  // E_1 = 1e-9 E_inf: E_0 = E_inf (1 + 1e-9). The elastic program row of E_inf, the same
  // stages, must report the same pull-off, critical point and jump to ~1e-9.
  for (const double approach : {0.0, 0.02}) {
    std::string text = cycle_text({2.25e-4, 1.0e-3, 1.0, 1.0e-3, 200, approach});
    const auto at = text.find(fmt::format("modulus = {}", kArm));
    ASSERT_NE(at, std::string::npos);
    const std::string viscous =
        std::string(text).replace(at, fmt::format("modulus = {}", kArm).size(), "modulus = 1.0e-3");
    const std::string line_start = "relaxation = ";
    const auto from = text.find(line_start);
    const std::string elastic = text.erase(from, text.find('\n', from) - from + 1);
    const Registries registries = Registries::builtin();
    const RunResult v =
        run_scene(SceneDocument::from_text(viscous, "v.toml").build(registries), {});
    const RunResult e =
        run_scene(SceneDocument::from_text(elastic, "e.toml").build(registries), {});
    ASSERT_TRUE(v.peak && e.peak && v.critical && e.critical);
    std::printf(
        "vanishing arm, dgamma_a = %g: pull-off %.12e (elastic %.12e), critical %.12e "
        "(%.12e), %zu jumps (%zu)\n",
        approach, v.peak->normal_force, e.peak->normal_force, v.critical->normal_force,
        e.critical->normal_force, v.jumps.size(), e.jumps.size());
    EXPECT_NEAR(v.peak->normal_force, e.peak->normal_force, 1e-8 * std::abs(e.peak->normal_force));
    EXPECT_NEAR(v.critical->normal_force, e.critical->normal_force,
                1e-8 * std::abs(e.critical->normal_force));
    EXPECT_EQ(v.critical->springs_in_contact, e.critical->springs_in_contact);
    EXPECT_EQ(v.status, e.status);
    ASSERT_EQ(v.jumps.size(), e.jumps.size());
    for (std::size_t i = 0; i < v.jumps.size(); ++i) {
      EXPECT_EQ(v.jumps[i].inward, e.jumps[i].inward) << i;
      EXPECT_EQ(v.jumps[i].springs, e.jumps[i].springs) << i;
    }
  }
}

TEST(ViscoelasticAdhesion, ReversibleAdhesionWithTwoArmsSettles) {
  // dgamma_a = dgamma: a spring glues at exactly the gap it lets go at, so a glue puts it on its
  // threshold and a let-go on its glue gap, both to rounding; with two arms a free spring's
  // creep may turn back toward the indenter. The row must neither chatter between the two nor
  // miss a glue: the cycle runs to separation, each stage's balance closes.
  const std::string text =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.05\n"
      "relaxation = [ { modulus = 9.0e6, time = 0.1 }, { modulus = 2.0e6, time = 1.0 } ]\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[loading]\nrebinding = true\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = 1e-4 }\n"
      "speed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"pull\"\nnormal = { by = -3e-5 }\nspeed = 1.0e-4\n"
      "[[loading.stage]]\nname = \"hold\"\nduration = 0.5\n"
      "[[loading.stage]]\nname = \"press2\"\nnormal = { to = 1e-4 }\nspeed = 1.0e-3\n"
      "[[loading.stage]]\nname = \"off\"\nnormal = { by = -1.0e-3 }\nuntil = \"separation\"\n"
      "speed = 1.0e-3\n[discretization]\nsprings = 300\n";
  const RunResult r =
      run_scene(SceneDocument::from_text(text, "rev.toml").build(Registries::builtin()), {});
  EXPECT_EQ(r.status, RunStatus::instability);
  EXPECT_LT(r.counts.events, 4 * 300);
  for (const StageRecord& s : r.stages) {
    const double scale =
        std::max(std::abs(s.energy->machine_work), std::abs(s.energy->stored_change));
    EXPECT_LT(std::abs(s.energy->residual), 1e-12 * scale) << s.name;
  }
}

TEST(ViscoelasticAdhesion, AStageBeyondItsEventsPerSpringStops) {
  Cycle c{2.25e-4, 1.0e-3, 0.0, 1.0e-3, 200};
  std::string text = cycle_text(c) + "max_events_per_spring = 1\n";
  const RunResult r =
      run_scene(SceneDocument::from_text(text, "limit.toml").build(Registries::builtin()), {});
  EXPECT_EQ(r.status, RunStatus::step_limit);
  ASSERT_TRUE(r.stop_reason.has_value());
  EXPECT_EQ(*r.stop_reason, StopReason::max_events_per_spring);
}

}  // namespace
}  // namespace mdrsim

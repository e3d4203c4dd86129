// A downstream project's own friction law, named by scene.toml and run by mdrsim.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "friction/friction_law.hpp"

namespace {

/// A velocity-independent law of its own: the springs inside r_in slide at mu_in f_z, those
/// outside at mu_out f_z (a lubricated centre). Each spring's coefficient is set by where it
/// sits, so the engine runs it spring by spring (docs/friction.md "Friction laws").
class LubricatedCentre final : public mdrsim::FrictionLaw {
 public:
  LubricatedCentre(double inner, double outer, double radius)
      : inner_(inner), outer_(outer), radius_(radius) {}
  mdrsim::SlipLimit limit_at(double x, double /*spacing*/) const override {
    return {coefficient(x), 0.0};
  }
  double coefficient(double x) const { return x < radius_ ? inner_ : outer_; }
  double inner_radius() const { return radius_; }

 private:
  double inner_;   ///< mu_in [1]
  double outer_;   ///< mu_out [1]
  double radius_;  ///< r_in [m]
};

mdrsim::Registries registries_with_own_law() {
  auto registries = mdrsim::Registries::builtin();
  registries.friction_laws.add(
      {.name = "lubricated-centre",
       .summary = "mu_in inside r_in, mu_out outside",
       .parameters =
           {{.key = "inner_coefficient", .help = "mu_in >= 0", .lower = mdrsim::Bound{0.0, true}},
            {.key = "outer_coefficient", .help = "mu_out >= 0", .lower = mdrsim::Bound{0.0, true}},
            {.key = "inner_radius", .help = "r_in [m]", .lower = mdrsim::Bound{0.0, true}}},
       .create = [](const mdrsim::ParameterValues& v) -> std::unique_ptr<mdrsim::FrictionLaw> {
         return std::make_unique<LubricatedCentre>(v.number("inner_coefficient"),
                                                   v.number("outer_coefficient"),
                                                   v.number("inner_radius"));
       }});
  return registries;
}

/// F_x = 2 int_0^a min(G* u, mu(x) E* (d - x^2/R)) dx, the row's continuum under a monotone
/// shear from rest (each spring sticks until its line load reaches its limit, then slides at
/// it): on each piece of constant mu, the limit falls with x and meets G* u at most once.
double independent_force(const LubricatedCentre& law, double e_star, double g_star, double radius,
                         double d, double u) {
  const double a = std::sqrt(radius * d);
  const auto limit_integral = [&](double mu, double from, double to) {  // int mu E* (d - x^2/R)
    return mu * e_star * (d * (to - from) - (to * to * to - from * from * from) / (3.0 * radius));
  };
  double sum = 0.0;
  const double pieces[][2] = {{0.0, std::min(law.inner_radius(), a)},
                              {std::min(law.inner_radius(), a), a}};
  for (const auto& piece : pieces) {
    const double from = piece[0], to = piece[1];
    if (to <= from) continue;
    const double mu = law.coefficient(from);
    // Sliding where mu E* (d - x^2/R) < G* u: x > x_s.
    const double below = d - g_star * u / (mu * e_star);
    const double xs = std::clamp(below > 0.0 ? std::sqrt(radius * below) : 0.0, from, to);
    sum += g_star * u * (xs - from) + limit_integral(mu, xs, to);
  }
  return 2.0 * sum;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : CUSTOM_FRICTION_SCENE;
  try {
    const auto scene = mdrsim::SceneDocument::from_file(path).build(registries_with_own_law());
    const auto result = mdrsim::run_scene(scene, mdrsim::ObserverList{});
    fmt::print("scene: {}\nstatus: {}\n", path, mdrsim::to_string(result.status));
    const auto* law =
        scene.friction ? dynamic_cast<const LubricatedCentre*>(scene.friction->law.get()) : nullptr;
    if (law == nullptr || result.stages.size() != 2) {
      fmt::print(stderr, "the scene must press, then shear under law = \"lubricated-centre\"\n");
      return 1;
    }
    const auto& end = result.stages[1].end;
    // The parabola's R from its image g(x) = x^2 / R.
    const double radius = 1e-8 / scene.profile->mdr_image(1e-4);
    const double independent = independent_force(*law, scene.material.effective_modulus,
                                                 scene.material.effective_shear_modulus, radius,
                                                 end.indentation, end.tangential_displacement);
    fmt::print("springs: {}, sliding at the end: {}, stick radius {:.6e} m\n", result.springs,
               end.springs_sliding, end.stick_radius);
    fmt::print("tangential force: {:.9e} N\n", end.tangential_force);
    fmt::print("independent value 2 int min(G* u, mu(x) E* (d - x^2/R)) dx: {:.9e} N\n",
               independent);
    fmt::print("relative difference: {:.2e}\n",
               std::abs(end.tangential_force - independent) / std::abs(independent));
    return 0;
  } catch (const mdrsim::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "custom_friction_law: %s\n", e.what());
    return 1;
  }
}

// A downstream project's own detachment law and profile, named by scene.toml and run by mdrsim.
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <numbers>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace {

/// Griffith's balance at the boundary spring with a critical energy release rate G_c of its
/// own (paper eq. 11 with G_c for dgamma, the tangential spring's energy added as in eq. 20):
/// the spring lets go once the energy it releases, (E* u_z^2 + G* u_x^2) dx, reaches the
/// energy 2 pi a G_c dx of the surface it frees. The margin is that balance per dx [N]:
/// finite at a = 0, continuous and non-increasing in the elongation. Only margin() is given,
/// so the engine root-finds every let-go.
class CriticalEnergyCriterion final : public mdrsim::DetachmentCriterion {
 public:
  CriticalEnergyCriterion(const mdrsim::InterfaceProperties& p, double critical_energy)
      : effective_modulus_(p.effective_modulus),
        effective_shear_modulus_(p.effective_shear_modulus),
        critical_energy_(critical_energy) {}

  double margin(const mdrsim::BoundarySpring& s) const override {
    const double released =
        effective_modulus_ * s.elongation * s.elongation +
        effective_shear_modulus_ * s.tangential_displacement * s.tangential_displacement;
    return 2.0 * std::numbers::pi * s.contact_radius * critical_energy_ - released;
  }

  double critical_energy() const { return critical_energy_; }  ///< G_c [J/m^2]

 private:
  double effective_modulus_;        ///< E* [Pa]
  double effective_shear_modulus_;  ///< G* [Pa]
  double critical_energy_;          ///< G_c [J/m^2]
};

/// The paraboloid f(r) = r^2 / (2R) with only the two required operations (paper eq. 6:
/// g(x) = x^2 / R); the Hertz radius and force come from the engine's numerical defaults.
class Paraboloid final : public mdrsim::Profile {
 public:
  explicit Paraboloid(double radius) : radius_(radius) {}
  double shape(double r) const override { return r * r / (2.0 * radius_); }
  double mdr_image(double x) const override { return x * x / radius_; }
  double radius() const { return radius_; }  ///< R [m]

 private:
  double radius_;  ///< R [m]
};

/// The built-in parts and the two of this project, each added by one call.
mdrsim::Registries registries_with_own_parts() {
  auto registries = mdrsim::Registries::builtin();
  registries.criteria.add(
      {.name = "critical-energy",
       .summary = "E* u_z^2 + G* u_x^2 >= 2 pi a G_c, with G_c of its own",
       .parameters = {{.key = "critical_energy_release_rate",
                       .help = "G_c [J/m^2]",
                       .lower = mdrsim::Bound{0.0, false}}},
       .create = [](const mdrsim::ParameterValues& v, const mdrsim::InterfaceProperties& p)
           -> std::unique_ptr<mdrsim::DetachmentCriterion> {
         return std::make_unique<CriticalEnergyCriterion>(p,
                                                          v.number("critical_energy_release_rate"));
       }});
  registries.profiles.add(
      {.name = "paraboloid",
       .summary = "r^2 / (2 R), numerical defaults only",
       .parameters = {{.key = "radius", .help = "R [m]", .lower = mdrsim::Bound{0.0, false}}},
       .create = [](const mdrsim::ParameterValues& v) -> std::unique_ptr<mdrsim::Profile> {
         return std::make_unique<Paraboloid>(v.number("radius"));
       }});
  return registries;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : CUSTOM_CRITERION_SCENE;
  try {
    const auto scene = mdrsim::SceneDocument::from_file(path).build(registries_with_own_parts());
    const auto result = mdrsim::run_scene(scene, mdrsim::ObserverList{});
    fmt::print("scene: {} (profile {}, criterion {}, normal control {})\n", path,
               scene.profile_name, scene.criterion_name, scene.normal.control);
    fmt::print("status: {}\n", mdrsim::to_string(result.status));
    if (!result.critical) {
      fmt::print(stderr, "no critical point: the contact did not jump off\n");
      return 1;
    }
    const auto* criterion = dynamic_cast<const CriticalEnergyCriterion*>(scene.criterion.get());
    const auto* profile = dynamic_cast<const Paraboloid*>(scene.profile.get());
    if (criterion == nullptr || profile == nullptr) {
      fmt::print(stderr, "the scene must name critical-energy and paraboloid\n");
      return 1;
    }
    // JKR under a fixed load (paper eqs. 14-17 with dgamma = G_c): F(a) = 4 E* a^3 / (3 R)
    // - sqrt(8 pi a^3 E* G_c) is least where dF/da = 0, at a0 = (9 pi R^2 G_c / (8 E*))^(1/3),
    // and there F = -3/2 pi G_c R, whatever E*, for any contact glued wider than a0.
    const double independent =
        -1.5 * std::numbers::pi * criterion->critical_energy() * profile->radius();
    const double force = result.critical->normal_force;
    fmt::print("springs: {} (finest row), root iterations: {}\n", result.springs,
               result.counts.root_iterations);
    fmt::print("pull-off force: {:.9e} N\n", force);
    if (result.accuracy.critical_error_estimate) {
      fmt::print("its error estimate: {:.2e} N\n", *result.accuracy.critical_error_estimate);
    }
    fmt::print("independent value -3/2 pi G_c R: {:.9e} N\n", independent);
    fmt::print("relative difference: {:.2e}\n",
               std::abs(force - independent) / std::abs(independent));
    return 0;
  } catch (const mdrsim::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "custom_criterion: %s\n", e.what());
    return 1;
  }
}

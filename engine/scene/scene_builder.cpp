// Reads a scene table into a Scene: every key checked, parts created by name, preload resolved
// (the loading programs' stages: program_reader.cpp).
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/model/dimensionless_scales.hpp"
#include "engine/model/preload.hpp"
#include "engine/model/viscoelastic_edge.hpp"
#include "engine/scene/adhesion_reader.hpp"
#include "engine/scene/dugdale_reader.hpp"
#include "engine/scene/embedded_table.hpp"
#include "engine/scene/friction_reader.hpp"
#include "engine/scene/front_speed_reader.hpp"
#include "engine/scene/grading_reader.hpp"
#include "engine/scene/program_reader.hpp"
#include "engine/scene/relaxation_reader.hpp"
#include "engine/scene/scene_document_impl.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/scene/shorthand_program.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {
namespace {

constexpr Bound kPositive{0.0, false};

/// Springs across the glued radius when the scene gives neither springs nor rtol.
constexpr std::int64_t kDefaultSprings = 2000;

/// An isotropic half-space has G*/E* = 2(1 - nu)/(2 - nu) in [2/3, 4/3) for -1 < nu <= 0.5
/// (paper eq. 8); a pair outside is accepted, with a warning.
void warn_moduli(TomlReader& t, const Material& m, std::vector<std::string>& warnings) {
  const double ratio = m.effective_shear_modulus / m.effective_modulus;
  constexpr double kSlack = 1e-12;
  if (ratio >= 2.0 / 3.0 * (1.0 - kSlack) && ratio <= 4.0 / 3.0 * (1.0 + kSlack)) return;
  warnings.push_back(t.message_at(
      "effective_shear_modulus",
      fmt::format("G*/E* = {:.6g} is outside [2/3, 4/3], the range of an isotropic half-space "
                  "(G*/E* = 2(1-nu)/(2-nu), -1 < nu <= 0.5)",
                  ratio)));
}

Material read_material(TomlReader& t, std::vector<std::string>& warnings,
                       FiniteRangeKeys& finite_range) {
  t.check_keys({"youngs_modulus", "poisson_ratio", "work_of_adhesion", "effective_modulus",
                "effective_shear_modulus", "approach_work_of_adhesion", "adhesive_stress",
                "maugis_parameter", "grading", "relaxation"});
  const bool youngs = t.has("youngs_modulus") || t.has("poisson_ratio");
  const bool effective = t.has("effective_modulus") || t.has("effective_shear_modulus");
  if (youngs && effective) {
    t.fail_at(t.has("effective_modulus") ? "effective_modulus" : "effective_shear_modulus",
              "give youngs_modulus and poisson_ratio, or effective_modulus (and "
              "effective_shear_modulus), not both");
  }
  const ReadAdhesion dgamma =
      read_adhesion(t, "work_of_adhesion", "work of adhesion dgamma [J/m^2], >= 0", std::nullopt);
  const ReadAdhesion approach = read_adhesion(t, "approach_work_of_adhesion",
                                              "dgamma_a [J/m^2], 0 <= dgamma_a <= dgamma", 0.0);
  finite_range = read_finite_range(t);
  if (effective) {
    const double e_star =
        t.number({.key = "effective_modulus", .help = "E* [Pa], > 0", .lower = kPositive});
    const auto g_star = t.optional_number(
        {.key = "effective_shear_modulus", .help = "G* [Pa], > 0", .lower = kPositive});
    if (!g_star) t.record("effective_shear_modulus", e_star);
    Material m{e_star, g_star.value_or(e_star), 0.0};
    apply_adhesion(t, dgamma, approach, m);
    warn_moduli(t, m, warnings);
    refuse_grading_without_poisson_ratio(t);
    if (auto terms = read_relaxation(t, 1.0)) m.relaxation = std::move(*terms);
    return m;
  }
  const double e = t.number({.key = "youngs_modulus",
                             .help = "Young's modulus E [Pa], > 0; or give effective_modulus",
                             .lower = kPositive});
  const double nu = t.number({.key = "poisson_ratio",
                              .help = "Poisson's ratio nu in (-1, 0.5]",
                              .lower = Bound{-1.0, false},
                              .upper = Bound{0.5, true}});
  Material m = Material::from_youngs_modulus(e, nu, 0.0);
  apply_adhesion(t, dgamma, approach, m);
  // Extreme E and nu near -1 overflow G = E/(2(1+nu)) (paper eq. 8).
  for (const double modulus : {m.effective_modulus, m.effective_shear_modulus}) {
    if (!std::isfinite(modulus) || !(modulus > 0.0)) {
      t.fail(
          fmt::format("youngs_modulus = {} and poisson_ratio = {} give E* = {} Pa, G* = {} Pa; "
                      "expected finite positive moduli",
                      e, nu, m.effective_modulus, m.effective_shear_modulus));
    }
  }
  if (const auto grading = read_grading(t, e, nu)) m.grading = *grading;
  if (auto terms = read_relaxation(t, 1.0 / ((1.0 - nu) * (1.0 + nu)))) {
    m.relaxation = std::move(*terms);
  }
  return m;
}

/// The controller's constraint a_u u + a_F F = rhs against the contact's stiffness k [N/m]:
/// a_u + a_F k must be finite, or the equilibrium of every step is NaN.
void check_constraint(TomlReader& t, const AxisLoading& axis, double contact_stiffness) {
  const AffineConstraint c = axis.controller->constraint();
  const double combined = c.displacement_coefficient + c.force_coefficient * contact_stiffness;
  if (!std::isfinite(c.displacement_coefficient) || !std::isfinite(c.force_coefficient) ||
      !std::isfinite(combined)) {
    t.fail(fmt::format(
        "control = \"{}\" is degenerate with these values (constraint a_u = {}, a_F = {} m/N "
        "against a contact stiffness of {} N/m)",
        axis.control, c.displacement_coefficient, c.force_coefficient, contact_stiffness));
  }
}

AxisLoading read_axis(TomlReader& t, const ControllerRegistry& controllers, bool holds_value) {
  AxisLoading axis;
  axis.control = t.name("control", controllers.names());
  const auto* entry = controllers.find(axis.control);
  // A controller names its held value only once created, so keys are checked against both
  // quantities an axis can hold, and the one this controller does not hold is refused below.
  const std::vector<std::string> held_keys{"displacement", "force"};
  check_part_keys(t, "control", axis.control, controllers,
                  holds_value ? held_keys : std::vector<std::string>{});
  const ParameterValues values = t.read_all(entry->parameters);
  axis.controller = create_part(t, "control", [&] { return entry->create(values); });
  if (holds_value) {
    const std::string key(axis.controller->held_value_key());
    for (const std::string& other : held_keys) {
      if (other != key && t.has(other)) {
        t.fail_at(other,
                  fmt::format("control = \"{}\" holds {}, not {}", axis.control, key, other));
      }
    }
    const char* unit = axis.controller->held_value_unit();
    axis.held_value = t.number({.key = key, .help = fmt::format("the held {} [{}]", key, unit)});
  }
  t.finish();
  return axis;
}

/// The preload on a graded half-space (docs/graded.md): g_k(a_g) = d, C_k nf_k(a_g) = F, or
/// a_g itself; a flat punch glues its face at d = F / (C_k A^(1+k)).
PreloadState graded_preload(const char* key, TomlReader& t, const Scene& scene) {
  const GradedImage& image = *scene.graded_image;
  const double ck = scene.material.grading.punch_constant;
  const double value = t.number({.key = key, .help = "[m] or [N]"});
  if (const auto radius = scene.profile->fixed_contact_radius()) {
    const std::string k(key);
    const double depth = k == "force"
                             ? value / (ck * std::pow(*radius, 1.0 + image.grading_exponent()))
                         : k == "depth" ? value
                                        : 0.0;
    return {*radius, depth};
  }
  const std::string k(key);
  const double a = k == "depth"   ? image.radius_at_depth(value)
                   : k == "force" ? image.radius_at_force(value, ck)
                                  : value;
  return {a, image.image(a)};
}

/// The preload's force without adhesion on a graded half-space [N]: C_k (d a^(1+k) - (1 + k)
/// int_0^a x^k g_k), i.e. C_k (nf_k(a) + (d - g_k(a)) a^(1+k)).
double graded_preload_force(const GradedImage& image, const PreloadState& p, const Material& m) {
  const double a = p.glued_radius;
  return m.grading.punch_constant *
         (image.nonadhesive_force_per_constant(a) +
          (p.depth - image.image(a)) * std::pow(a, 1.0 + image.grading_exponent()));
}

/// The glued radius and the preload depth, from the one preload quantity given.
void resolve_preload(TomlReader& t, Scene& scene) {
  const std::vector<std::string> keys{"depth", "force", "contact_radius"};
  t.check_keys(keys);
  int given = 0;
  for (const std::string& k : keys) given += t.has(k) ? 1 : 0;
  if (given != 1) t.fail("give exactly one of depth [m], force [N] or contact_radius [m]");
  const Profile& profile = *scene.profile;
  const double e_star = scene.material.effective_modulus;
  // The solve is the model's (engine/model/preload); here its keys and their locations.
  const auto solved = [&](const char* key, const auto& solve) {
    try {
      const PreloadState p = scene.graded_image ? graded_preload(key, t, scene) : solve();
      scene.glued_radius = p.glued_radius;
      scene.preload_depth = p.depth;
      scene.preload_force = scene.graded_image
                                ? graded_preload_force(*scene.graded_image, p, scene.material)
                                : preload_force(profile, p, e_star);
    } catch (const PreloadOutOfReach& e) {
      t.fail_range(key, e.what());
    } catch (const std::domain_error& e) {
      t.fail(e.what());
    }
  };
  if (const auto d = t.optional_number({.key = "depth", .help = "[m]", .lower = kPositive})) {
    solved("depth", [&] { return preload_at_depth(profile, *d); });
  } else if (const auto f =
                 t.optional_number({.key = "force", .help = "[N]", .lower = kPositive})) {
    // The dimensionless output divides forces by F0 (paper eq. 16).
    if (const auto scales = dimensionless_scales(profile, scene.material);
        scales && !std::isfinite(*f / scales->force)) {
      t.fail_range("force",
                   fmt::format("= {} overflows F/F0 (the JKR scale is {} N)", *f, scales->force));
    }
    solved("force", [&] { return preload_at_force(profile, *f, e_star); });
    if (!scene.graded_image) scene.preload_force = *f;
  } else {
    const double a = t.number({.key = "contact_radius", .help = "[m]", .lower = kPositive});
    solved("contact_radius", [&] { return preload_at_radius(profile, a); });
  }
  if (!(scene.glued_radius > 0.0) || !std::isfinite(scene.glued_radius)) {
    t.fail(fmt::format("the preload gives no glued contact (radius {} m)", scene.glued_radius));
  }
  // Extreme but in-range values overflow the force and elongation scales of the run.
  const double normal_stiffness = 2.0 * e_star * scene.glued_radius;
  const double shear_stiffness = 2.0 * scene.material.effective_shear_modulus * scene.glued_radius;
  if (!std::isfinite(normal_stiffness) || !(normal_stiffness > 0.0) ||
      !std::isfinite(shear_stiffness) || !(shear_stiffness > 0.0)) {
    t.fail(fmt::format(
        "the contact stiffnesses 2 E* a = {} N/m and 2 G* a = {} N/m at contact radius {} m are "
        "not finite and positive",
        normal_stiffness, shear_stiffness, scene.glued_radius));
  }
  const double force_scale = e_star * scene.glued_radius * std::abs(scene.preload_depth);
  const double adhesion_scale =
      2.0 * std::numbers::pi * scene.glued_radius * scene.material.work_of_adhesion;
  // The work of pressing the row in (the preload stage's, docs) is of the size E* a d^2.
  const double work_scale = force_scale * std::abs(scene.preload_depth);
  if (!std::isfinite(scene.preload_depth) || !std::isfinite(scene.preload_force) ||
      !std::isfinite(force_scale) || !std::isfinite(adhesion_scale) || !std::isfinite(work_scale)) {
    t.fail(fmt::format(
        "the preload overflows (contact radius {} m, depth {} m, E* a d = {} N, E* a d^2 = {} "
        "J, 2 pi a dgamma = {} N)",
        scene.glued_radius, scene.preload_depth, force_scale, work_scale, adhesion_scale));
  }
  t.finish();
}

void check_dimensionless_tangential(TomlReader& t, const Scene& scene);

/// The held tangential value must leave the tangential force and displacement of the glued
/// contact, Fx ~ 2 G* a ux, finite.
void check_tangential_scale(TomlReader& t, const Scene& scene) {
  const AxisLoading& axis = *scene.tangential;
  const std::string key(axis.controller->held_value_key());
  const double stiffness = 2.0 * scene.material.effective_shear_modulus * scene.glued_radius;
  const double other = axis.controller->holds_force() ? std::abs(axis.held_value) / stiffness
                                                      : std::abs(axis.held_value) * stiffness;
  if (!std::isfinite(other)) {
    t.fail_range(
        key, fmt::format("= {} overflows the tangential {} of the glued contact", axis.held_value,
                         axis.controller->holds_force() ? "displacement" : "force"));
  }
  // The dimensionless output divides the held value by F0 or d0 (paper eq. 16).
  check_dimensionless_tangential(t, scene);
  // The work of applying it, F_x u_x / 2 (the tangential stage's, docs).
  if (!std::isfinite(other * std::abs(axis.held_value))) {
    t.fail_range(
        key, fmt::format("= {} overflows the work of applying it (F_x u_x / 2)", axis.held_value));
  }
}

void check_dimensionless_tangential(TomlReader& t, const Scene& scene) {
  const AxisLoading& axis = *scene.tangential;
  const std::string key(axis.controller->held_value_key());
  const auto scales = dimensionless_scales(*scene.profile, scene.material);
  if (!scales) return;
  const double unit = axis.controller->holds_force() ? scales->force : scales->depth;
  if (!std::isfinite(axis.held_value / unit)) {
    t.fail_range(key, fmt::format("= {} overflows {} (the JKR scale is {} {})", axis.held_value,
                                  axis.controller->holds_force() ? "F/F0" : "u/d0", unit,
                                  axis.controller->holds_force() ? "N" : "m"));
  }
}

/// The paper's one path: the preload, the tangential load held during the pull-off, and the
/// pull-off's control.
void read_shorthand(TomlReader& loading, const ControllerRegistry& controllers, Scene& scene) {
  scene.preload_at = loading.message_at("preload", "");
  TomlReader preload = loading.table("preload");
  resolve_preload(preload, scene);
  if (auto tangential = loading.optional_table("tangential")) {
    scene.tangential = read_axis(*tangential, controllers, true);
    check_tangential_scale(*tangential, scene);
    check_constraint(*tangential, *scene.tangential,
                     2.0 * scene.material.effective_shear_modulus * scene.glued_radius);
  }
  TomlReader normal = loading.table("normal");
  scene.normal = read_axis(normal, controllers, false);
  check_constraint(normal, scene.normal,
                   2.0 * scene.material.effective_modulus * scene.glued_radius);
}

void read_solver(TomlReader& t, SolverOptions& solver) {
  t.check_keys(
      {"method", "step", "max_halvings", "max_steps", "max_events", "max_events_per_spring"});
  const std::string method = t.name("method", {"event", "stepping", "continuum"}, "event");
  solver.method = method == "event"       ? SolverMethod::event
                  : method == "continuum" ? SolverMethod::continuum
                                          : SolverMethod::stepping;
  if (solver.method != SolverMethod::stepping) {
    for (const char* k : {"step", "max_halvings", "max_steps"}) {
      if (t.has(k)) t.fail_at(k, "applies to method = \"stepping\" only");
    }
  } else {
    solver.step = t.optional_number(
        {.key = "step",
         .help = "increment of the normal control (SI), or of the stage parameter in a program",
         .lower = kPositive});
    if (t.has("max_halvings")) {
      solver.max_halvings = static_cast<int>(
          t.integer({.key = "max_halvings", .lower = Bound{0, true}, .upper = Bound{60, true}}));
    } else {
      t.record("max_halvings", solver.max_halvings);
    }
    if (t.has("max_steps")) {
      solver.max_steps =
          t.integer({.key = "max_steps", .lower = Bound{1, true}, .upper = Bound{1e15, true}});
    } else {
      t.record("max_steps", solver.max_steps);
    }
  }
  if (solver.method == SolverMethod::continuum) {
    for (const char* k : {"max_events", "max_events_per_spring"}) {
      if (t.has(k)) t.fail_at(k, "applies to method = \"event\" or \"stepping\" only");
    }
  } else {
    if (t.has("max_events")) {
      solver.max_events =
          t.integer({.key = "max_events", .lower = Bound{1, true}, .upper = Bound{1e15, true}});
    } else {
      t.record("max_events", solver.max_events);
    }
    if (t.has("max_events_per_spring")) {
      solver.max_events_per_spring = t.integer(
          {.key = "max_events_per_spring", .lower = Bound{1, true}, .upper = Bound{1e9, true}});
    } else {
      t.record("max_events_per_spring", solver.max_events_per_spring);
    }
  }
  t.finish();
}

/// [profile]: the part by its type, with the table a tabulated profile read embedded in the
/// result's scene, so that it reruns after the CSV moved.
void read_profile(TomlReader& root, const Registries& registries, nlohmann::json& resolved,
                  Scene& scene) {
  TomlReader profile = root.table("profile");
  scene.profile_name = profile.name("type", registries.profiles.names());
  scene.profile_at = profile.message_at("type", "");
  check_part_keys(profile, "type", scene.profile_name, registries.profiles);
  const auto* entry = registries.profiles.find(scene.profile_name);
  const ParameterValues values = profile.read_all(entry->parameters);
  scene.profile = create_part(profile, "type", [&] { return entry->create(values); });
  if (const auto file = scene.profile->source_table_file()) {
    embed_profile_table(resolved["profile"], *file);
  }
  profile.finish();
}

/// [detachment]: the criterion by name (mode-mixed where the table is not given), and the rate
/// law of the edge, whose key's place goes to `front_speed_at`.
void read_criterion(TomlReader& root, const Registries& registries, Scene& scene,
                    std::string& front_speed_at) {
  // A relaxing bulk lets go instantaneously, on its glassy modulus (docs/viscoelastic.md).
  const InterfaceProperties interface = scene.material.relaxes()
                                            ? glassy_material(scene.material)
                                            : scene.material.interface_properties();
  scene.criterion_name = "mode-mixed";
  if (auto detachment = root.optional_table("detachment")) {
    scene.criterion_name =
        detachment->name("criterion", registries.criteria.names(), scene.criterion_name);
    check_part_keys(*detachment, "criterion", scene.criterion_name, registries.criteria,
                    {"front_speed_law"});
    const auto* entry = registries.criteria.find(scene.criterion_name);
    const ParameterValues values = detachment->read_all(entry->parameters);
    scene.criterion =
        create_part(*detachment, "criterion", [&] { return entry->create(values, interface); });
    scene.front_speed_law = read_front_speed_law(*detachment, scene, front_speed_at);
    detachment->finish();
  } else {
    const auto* entry = registries.criteria.find(scene.criterion_name);
    scene.criterion = entry->create(ParameterValues{}, interface);
    root.record("detachment", {{"criterion", scene.criterion_name}});
  }
}

/// [discretization]: springs or rtol, and the extrapolation; the continuum route (named by
/// solver.method, read before) has no springs and defaults rtol.
void read_discretization(TomlReader& root, RouteKeys& route_keys, Scene& scene) {
  const bool continuum = scene.solver.method == SolverMethod::continuum;
  scene.springs = kDefaultSprings;
  if (auto discretization = root.optional_table("discretization")) {
    if (discretization->has("rtol")) route_keys.rtol_at = discretization->message_at("rtol", "");
    if (discretization->has("extrapolation")) {
      route_keys.extrapolation_at = discretization->message_at("extrapolation", "");
    }
    if (continuum) {
      for (const char* key : {"springs", "extrapolation"}) {
        if (discretization->has(key)) {
          discretization->fail_at(key,
                                  "the continuum route has no springs; give rtol (default "
                                  "1e-10) or use solver.method = \"event\"");
        }
      }
    }
    discretization->check_keys({"springs", "rtol", "extrapolation"});
    if (discretization->has("rtol") && discretization->has("springs")) {
      discretization->fail_at("rtol", "give springs or rtol, not both");
    }
    scene.discretization.rtol =
        discretization->optional_number({.key = "rtol",
                                         .help = "relative accuracy of the critical force",
                                         .lower = Bound{1e-12, true},
                                         .upper = Bound{0.1, true}});
    using Extrapolation = DiscretizationOptions::Extrapolation;
    if (discretization->has("extrapolation")) {
      scene.discretization.extrapolation =
          discretization->name("extrapolation", {"none", "richardson"}, std::string("none")) ==
                  "richardson"
              ? Extrapolation::richardson
              : Extrapolation::none;
    }
    if (discretization->has("springs")) {
      scene.springs = discretization->integer({.key = "springs",
                                               .help = "springs across the glued radius",
                                               .lower = Bound{1, true},
                                               .upper = Bound{1e9, true}});
      if (scene.discretization.richardson() && scene.springs < kMinRichardsonSprings) {
        discretization->fail_at(
            "springs", fmt::format("{} springs are too few to extrapolate (richardson needs at "
                                   "least {})",
                                   scene.springs, kMinRichardsonSprings));
      }
    } else if (continuum && !scene.discretization.rtol) {
      scene.discretization.rtol = kContinuumRtol;
      discretization->record("rtol", kContinuumRtol);
    } else if (!scene.discretization.rtol) {
      discretization->record("springs", scene.springs);
    }
    discretization->finish();
  } else if (continuum) {
    scene.discretization.rtol = kContinuumRtol;
    root.record("discretization", {{"rtol", kContinuumRtol}});
  } else {
    root.record("discretization", {{"springs", scene.springs}});
  }
}

/// Finite-range adhesion runs on the continuum route unless solver.method = "event" takes the
/// spring row; the resolved scene names the route, and leaves out the defaults it would refuse
/// given (a criterion, an approach work of adhesion).
void use_dugdale_route(nlohmann::json& resolved, Scene& scene, const RouteKeys& keys) {
  resolved.erase("detachment");
  if (auto material = resolved.find("material"); material != resolved.end()) {
    material->erase("approach_work_of_adhesion");
  }
  if (keys.method_given && scene.solver.method == SolverMethod::event) return;
  scene.solver.method = SolverMethod::continuum;
  nlohmann::json& solver = resolved["solver"];
  if (solver.is_object()) {
    for (const char* key : {"max_events", "max_events_per_spring"}) solver.erase(key);
  }
  solver["method"] = "continuum";
}

/// [friction], then the route: the plan of route_plan.hpp, with the resolved scene leaving
/// `method` out where the input did and rtol alone chose the continuum route, so that rerunning
/// it takes the same route.
void read_friction_and_plan(TomlReader& root, const Registries& registries, RouteKeys& route_keys,
                            nlohmann::json& resolved, Scene& scene) {
  // [friction] before the route: a scene with friction stays on the row.
  if (auto friction = root.optional_table("friction")) {
    scene.friction = read_friction(*friction, registries.friction_laws);
    refuse_friction_with_relaxation(*friction, scene);
    if (scene.friction) {
      route_keys.friction_at = friction->message_at(friction_acting_key(*scene.friction), "");
    }
    friction->finish();
    // Friction runs on programs: the shorthand as its three stages (docs/friction.md).
    if (scene.friction && !scene.program) {
      scene.program = shorthand_program(scene, registries.controllers);
    }
  }
  if (scene.shorthand() && !scene.program) {
    scene.plan.shorthand_stages = shorthand_program(scene, registries.controllers);
  }
  plan_route(scene, route_keys);
  if (scene.plan.continuum_by_rtol) {
    if (auto solver = resolved.find("solver"); solver != resolved.end()) {
      // The route has no events: the row's limits go with the method.
      for (const char* key : {"method", "max_events", "max_events_per_spring"}) solver->erase(key);
      if (solver->empty()) resolved.erase(solver);
    }
  }
}

}  // namespace

Scene build_scene(const toml::table& root_table, const std::string& source_name,
                  const std::filesystem::path& base_dir, const Registries& registries) {
  auto resolved = std::make_shared<nlohmann::json>(nlohmann::json::object());
  TomlReader root(root_table, "", source_name, base_dir, resolved.get());
  root.check_keys({"title", "material", "profile", "loading", "detachment", "discretization",
                   "solver", "friction"});
  Scene scene;
  scene.title = root.optional_text("title").value_or("");

  TomlReader material = root.table("material");
  FiniteRangeKeys finite_range;
  scene.material = read_material(material, scene.warnings, finite_range);
  material.finish();

  read_profile(root, registries, *resolved, scene);
  apply_finite_range(material, finite_range, scene);
  apply_grading(material, *resolved, scene);

  TomlReader loading = root.table("loading");
  if (is_program(loading)) {
    scene.program = read_program(loading, registries.controllers);
  } else {
    check_shorthand_keys(loading, material, scene.material);
    read_shorthand(loading, registries.controllers, scene);
  }
  loading.finish();

  std::string front_speed_at;
  read_criterion(root, registries, scene, front_speed_at);

  RouteKeys route_keys;
  if (auto solver = root.optional_table("solver")) {
    route_keys.method_given = solver->has("method");
    if (route_keys.method_given) route_keys.method_at = solver->message_at("method", "");
    read_solver(*solver, scene.solver);
  } else if (!scene.material.finite_range()) {
    root.record("solver", {{"method", "event"},
                           {"max_events", scene.solver.max_events},
                           {"max_events_per_spring", scene.solver.max_events_per_spring}});
  }
  refuse_outside_relaxation_scope(loading, material, route_keys, scene);
  refuse_outside_dugdale_scope(root, loading, route_keys, scene);
  if (scene.material.finite_range()) use_dugdale_route(*resolved, scene, route_keys);
  refuse_outside_grading_scope(root, loading, material, scene);
  use_graded_route(*resolved, route_keys, scene);
  read_discretization(root, route_keys, scene);
  read_friction_and_plan(root, registries, route_keys, *resolved, scene);
  refuse_outside_front_speed_scope(scene, front_speed_at);
  root.finish();
  scene.resolved = std::move(resolved);
  return scene;
}

}  // namespace mdrsim

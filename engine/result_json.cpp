// Field names and order as in SPEC; dimensionless values only where the JKR scales exist.
#include "engine/result_json.hpp"

namespace mdrsim {

std::optional<JkrScales> dimensionless_scales(const Scene& scene) {
  const auto radius = scene.profile->jkr_scale_radius();
  if (!radius) return std::nullopt;
  return JkrScales::of(*radius, scene.material.effective_modulus, scene.material.work_of_adhesion);
}

nlohmann::ordered_json result_to_json(const Scene& scene, const RunResult& result) {
  using nlohmann::ordered_json;
  const ContactSnapshot& c = result.critical;
  ordered_json j;
  j["status"] = to_string(result.status);
  j["control"] = {{"normal", scene.normal.control},
                  {"tangential", scene.tangential ? scene.tangential->control : "fixed-grips"}};
  j["criterion"] = scene.criterion_name;
  j["method"] = scene.solver.method == SolverMethod::event ? "event" : "stepping";
  j["springs"] = result.springs;
  if (scene.discretization.rtol) j["rtol"] = *scene.discretization.rtol;
  if (scene.discretization.richardson) {
    j["extrapolation"] = {{"method", "richardson"}, {"springs", result.resolutions}};
  }
  j["critical"] = {{"normal_force", c.normal_force},
                   {"tangential_force", c.tangential_force},
                   {"contact_radius", c.contact_radius},
                   {"indentation", c.indentation},
                   {"tangential_displacement", c.tangential_displacement},
                   {"springs_in_contact", c.springs_in_contact}};
  if (const auto s = dimensionless_scales(scene)) {
    j["dimensionless"] = {{"normal_force", c.normal_force / s->force},
                          {"tangential_force", c.tangential_force / s->force},
                          {"contact_radius", c.contact_radius / s->radius},
                          {"indentation", c.indentation / s->depth},
                          {"tangential_displacement", c.tangential_displacement / s->depth}};
  }
  j["counts"] = {{"events", result.counts.events},
                 {"steps", result.counts.steps},
                 {"halvings", result.counts.halvings},
                 {"root_iterations", result.counts.root_iterations}};
  j["wall_time_s"] = result.wall_time_s;
  return j;
}

}  // namespace mdrsim

// Field names and order as in docs; dimensionless values only where the JKR scales exist.
#include "engine/output/result_json.hpp"

#include <algorithm>
#include <span>

#include "engine/events/program_version.hpp"
#include "engine/model/dugdale_material.hpp"
#include "engine/model/snapshot_fields.hpp"

namespace mdrsim {
namespace {

/// What a state says beyond the fields every state has.
struct StateKeys {
  bool friction = false;  ///< how much of it slides (docs/friction.md)
  bool cohesive = false;  ///< the cohesive zone's radius (docs/maugis.md)
  bool time = false;      ///< a timed program's clock (docs/programs.md "Time")
};

nlohmann::ordered_json snapshot_json(const ContactSnapshot& c, StateKeys keys) {
  nlohmann::ordered_json j;
  for (const SnapshotField& f : kSnapshotFields) j[f.name] = c.*f.member;
  if (keys.time) j["time"] = c.time;
  if (keys.cohesive) j["cohesive_radius"] = c.cohesive_radius;
  j["springs_in_contact"] = c.springs_in_contact;
  j["disk_valid"] = c.disk_valid;
  if (keys.friction) {
    j["springs_sliding"] = c.springs_sliding;
    j["stick_radius"] = c.stick_radius;
  }
  return j;
}

nlohmann::ordered_json dimensionless_json(const ContactSnapshot& c, const PullOffScales& s) {
  nlohmann::ordered_json j;
  for (const SnapshotField& f : kSnapshotFields) j[f.name] = c.*f.member / scale_of(s, f.scale);
  return j;
}

/// A snapshot with its dimensionless values nested, where the scales exist.
nlohmann::ordered_json state_json(const ContactSnapshot& c, const std::optional<PullOffScales>& s,
                                  StateKeys keys) {
  nlohmann::ordered_json j = snapshot_json(c, keys);
  if (s) j["dimensionless"] = dimensionless_json(c, *s);
  return j;
}

/// A jump's `after`: its state, or only how the indenter left when nothing held it.
nlohmann::ordered_json after_json(const JumpRecord& jump, const std::optional<PullOffScales>& s,
                                  StateKeys keys) {
  if (jump.end != JumpEnd::state) return {{to_string(jump.end), true}};
  nlohmann::ordered_json j = state_json(jump.after, s, keys);
  // A jump takes no time: a state refined between springs might say otherwise by rounding.
  if (keys.time) j["time"] = jump.critical.time;
  return j;
}

/// With friction the work says what of it friction dissipated.
/// Field names as in docs/outputs.md ("energy").
/// With a relaxing bulk both say what its dashpots dissipated (docs/viscoelastic.md).
nlohmann::ordered_json energy_json(const EnergyBalance& e, bool bulk = false) {
  nlohmann::ordered_json j = {{"machine_work", e.machine_work},
                              {"stored_change", e.stored_change},
                              {"surface_change", e.surface_change},
                              {"dissipated_by_friction", e.dissipated_by_friction}};
  if (bulk) j["dissipated_by_bulk"] = e.dissipated_by_bulk;
  j["jump_losses"] = e.jump_losses;
  j["residual"] = e.residual;
  return j;
}

nlohmann::ordered_json work_json(const AxisWork& w, bool friction = false,
                                 bool front_speed_law = false, bool bulk = false) {
  nlohmann::ordered_json j = {{"normal", w.normal}, {"tangential", w.tangential}};
  if (friction) j["dissipated_by_friction"] = w.friction;
  if (front_speed_law) j["dissipated_at_front"] = w.front;
  if (bulk) j["dissipated_by_bulk"] = w.bulk;
  return j;
}

}  // namespace

std::pair<std::string, std::string> final_controls(const Scene& scene, std::size_t stages_run) {
  if (!scene.program) {
    return {scene.normal.control, scene.tangential ? scene.tangential->control : "fixed-grips"};
  }
  std::pair<std::string, std::string> controls{"fixed-grips", "fixed-grips"};
  const auto& stages = scene.program->stages;
  const std::size_t n = std::min(std::max<std::size_t>(stages_run, 1), stages.size());
  for (const Stage& stage : std::span(stages).first(n)) {
    if (stage.normal) controls.first = stage.normal->control;
    if (stage.tangential) controls.second = stage.tangential->control;
  }
  return controls;
}

namespace {

const char* route_name(Accuracy::Route route) {
  switch (route) {
    case Accuracy::Route::richardson:
      return "richardson";
    case Accuracy::Route::continuum:
      return "continuum";
    case Accuracy::Route::row:
      break;
  }
  return "row";
}

/// The continuum route has no springs to count: its states and jumps leave the counts out.
void drop_spring_counts(nlohmann::ordered_json& j) {
  for (const char* key : {"critical", "peak_adhesion"}) {
    if (j.contains(key)) j[key].erase("springs_in_contact");
  }
  if (j.contains("stages")) {
    for (auto& stage : j["stages"]) stage["end"].erase("springs_in_contact");
  }
  if (j.contains("jumps")) {
    for (auto& jump : j["jumps"]) {
      jump["critical"].erase("springs_in_contact");
      jump["after"].erase("springs_in_contact");
      jump.erase("springs");
      jump.erase("glued_springs");
    }
  }
}

/// What produced the result: the effective material, the preload, the scales, the rows run,
/// the version and the resolved scene, which run again gives the same numbers.
void add_provenance(nlohmann::ordered_json& j, const Scene& scene, const RunResult& result,
                    const std::optional<PullOffScales>& scales) {
  const Material& m = scene.material;
  j["material"] = {{"effective_modulus", m.effective_modulus},
                   {"effective_shear_modulus", m.effective_shear_modulus},
                   {"work_of_adhesion", m.work_of_adhesion},
                   {"approach_work_of_adhesion", m.approach_work_of_adhesion}};
  // Where dgamma varies, the numbers above are its scale values; say what varies.
  if (m.work_of_adhesion_by_radius) {
    j["material"]["work_of_adhesion_by_radius"] = m.work_of_adhesion_by_radius->describe();
  }
  if (m.approach_work_of_adhesion_by_radius) {
    j["material"]["approach_work_of_adhesion_by_radius"] =
        m.approach_work_of_adhesion_by_radius->describe();
  }
  if (scene.shorthand()) {
    j["preload"] = {{"glued_radius", scene.glued_radius},
                    {"depth", scene.preload_depth},
                    {"force", scene.preload_force}};
  }
  if (scales) {
    j["scales"] = {{"force", scales->force},
                   {"radius", scales->radius},
                   {"depth", scales->depth},
                   {"basis", scales->basis}};
  }
  const Accuracy& a = result.accuracy;
  if (a.route == Accuracy::Route::continuum) {
    j["resolution"] = {{"route", route_name(a.route)}};
  } else {
    j["resolution"] = {
        {"route", route_name(a.route)},
        {"rows", a.rows.empty() ? std::vector<std::int64_t>{result.springs}
                                : std::vector<std::int64_t>(a.rows.begin(), a.rows.end())}};
  }
  j["mdrsim_version"] = program_version();
  if (scene.resolved) j["scene"] = nlohmann::ordered_json::parse(scene.resolved->dump());
}

}  // namespace

std::optional<PullOffScales> dimensionless_scales(const Scene& scene) {
  return dimensionless_scales(*scene.profile, scene.material);
}

std::optional<double> maugis_parameter(const Scene& scene) {
  const auto radius = scene.profile->jkr_scale_radius();
  if (!scene.material.finite_range() || !radius ||
      (scene.profile_name != "parabolic" && scene.profile_name != "sphere")) {
    return std::nullopt;
  }
  const Material& m = scene.material;
  return maugis_parameter_of(m.adhesive_stress, m.work_of_adhesion, m.effective_modulus, *radius);
}

nlohmann::ordered_json result_to_json(const Scene& scene, const RunResult& result) {
  using nlohmann::ordered_json;
  const auto scales = dimensionless_scales(scene);
  const Accuracy& accuracy = result.accuracy;
  const bool friction = scene.friction.has_value();
  // The viscoelastic rows estimate friction's work as they do the other works; the elastic
  // program's leave it the finest row's (a warning says so).
  const bool friction_estimated = friction && scene.material.relaxes();
  const bool bulk = scene.material.relaxes();
  const StateKeys keys{.friction = friction,
                       .cohesive = scene.material.finite_range(),
                       .time = scene.program && scene.program->timed()};
  ordered_json j;
  j["status"] = to_string(result.status);
  if (result.stop_reason) j["stop_reason"] = to_string(*result.stop_reason);
  if (result.sliding) j["sliding"] = true;
  j["disk_valid"] = result.disk_valid;
  const auto [normal_control, tangential_control] = final_controls(scene, result.stages.size());
  j["control"] = {{"normal", normal_control}, {"tangential", tangential_control}};
  j["criterion"] = scene.detachment_law();
  const bool continuum = accuracy.route == Accuracy::Route::continuum;
  j["method"] = continuum ? "continuum" : to_string(scene.solver.method);
  if (!continuum) j["springs"] = result.springs;
  if (scene.discretization.rtol) j["rtol"] = *scene.discretization.rtol;
  if (accuracy.route == Accuracy::Route::richardson) {
    j["extrapolation"] = {{"method", "richardson"}, {"springs", accuracy.rows}};
  }
  // A viscoelastic program's rows may estimate neither (no glue): their stages' estimates.
  if (scene.discretization.rtol || accuracy.critical_error_estimate ||
      accuracy.peak_error_estimate || (bulk && accuracy.route == Accuracy::Route::richardson)) {
    ordered_json a;
    a["route"] = route_name(accuracy.route);
    if (!continuum) {
      a["rows"] = accuracy.rows;
      a["outer_radius"] = accuracy.outer_radius;
    }
    if (accuracy.critical_error_estimate) {
      a["critical_error_estimate"] = *accuracy.critical_error_estimate;
    }
    if (accuracy.peak_error_estimate) a["peak_error_estimate"] = *accuracy.peak_error_estimate;
    if (accuracy.work_error_estimate) {
      a["work_error_estimate"] = work_json(*accuracy.work_error_estimate, friction_estimated,
                                           scene.front_speed_law.has_value(), bulk);
    }
    if (accuracy.critical_zoom) {
      a["critical_zoom"] = {{"outer_radius", accuracy.critical_zoom->outer_radius},
                            {"rows", accuracy.critical_zoom->rows}};
    }
    if (scene.discretization.rtol) a["rtol_met"] = accuracy.rtol_met;
    a["covers"] = accuracy.covers.empty() ? std::vector<std::string>{"critical.normal_force",
                                                                     "peak_adhesion.normal_force"}
                                          : accuracy.covers;
    j["accuracy"] = a;
  }
  if (result.critical) {
    j["critical"] = snapshot_json(*result.critical, keys);
    if (scales) j["dimensionless"] = dimensionless_json(*result.critical, *scales);
  }
  if (const auto lambda = maugis_parameter(scene)) j["dimensionless"]["maugis_parameter"] = *lambda;
  if (result.peak) {
    ordered_json p = snapshot_json(*result.peak, keys);
    if (scales) p["dimensionless"] = dimensionless_json(*result.peak, *scales);
    j["peak_adhesion"] = p;
  }
  if (result.tangential_strength) {
    j["tangential_strength"] = *result.tangential_strength;
    if (scales)
      j["dimensionless_tangential_strength"] = *result.tangential_strength / scales->force;
  }
  if (result.work) {
    ordered_json stages = ordered_json::array();
    double stage_start = 0.0;  // a stage starts where the one before it ended
    for (const StageRecord& stage : result.stages) {
      ordered_json record = {{"name", stage.name}};
      if (keys.time) {
        record["start_time"] = stage_start;
        record["end_time"] = stage.end.time;
        stage_start = stage.end.time;
      }
      record["end"] = state_json(stage.end, scales, keys);
      record["work"] = work_json(stage.work, friction, scene.front_speed_law.has_value(), bulk);
      if (stage.normal_force_error_estimate) {
        record["end_error_estimate"] = {
            {"normal_force", *stage.normal_force_error_estimate},
            {"tangential_force", stage.tangential_force_error_estimate.value_or(0.0)}};
        if (stage.time_error_estimate) {
          record["end_error_estimate"]["time"] = *stage.time_error_estimate;
        }
      }
      if (stage.work_error_estimate) {
        record["work_error_estimate"] = work_json(*stage.work_error_estimate, friction_estimated,
                                                  scene.front_speed_law.has_value(), bulk);
      }
      if (stage.energy) record["energy"] = energy_json(*stage.energy, bulk);
      stages.push_back(record);
    }
    j["stages"] = stages;
    ordered_json jumps = ordered_json::array();
    for (const JumpRecord& jump : result.jumps) {
      jumps.push_back({{"stage", jump.stage},
                       {"kind", jump.inward ? "in" : "out"},
                       {"critical", state_json(jump.critical, scales, keys)},
                       {"after", after_json(jump, scales, keys)},
                       {"springs", jump.springs},
                       {"glued_springs", jump.glued_springs},
                       {"by_shear", jump.by_shear}});
      if (jump.critical_error_estimate) {
        jumps.back()["critical_error_estimate"] = *jump.critical_error_estimate;
        if (jump.end == JumpEnd::state) {
          jumps.back()["after_error_estimate"] = jump.after_error_estimate.value_or(0.0);
        }
      }
    }
    j["jumps"] = jumps;
    j["work"] = work_json(*result.work, friction, scene.front_speed_law.has_value(), bulk);
    if (result.energy) j["energy"] = energy_json(*result.energy, bulk);
  }
  if (continuum) drop_spring_counts(j);
  j["warnings"] = result.warnings;
  j["counts"] = {{"events", result.counts.events},
                 {"steps", result.counts.steps},
                 {"halvings", result.counts.halvings},
                 {"root_iterations", result.counts.root_iterations}};
  j["wall_time_s"] = result.wall_time_s;
  add_provenance(j, scene, result, scales);
  return j;
}

}  // namespace mdrsim

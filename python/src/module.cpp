// mdrsim._core: scene documents, runs and their results, for the Python package mdrsim.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/base/text.hpp"
#include "engine/model/snapshot_fields.hpp"
#include "engine/output/finite_check.hpp"
#include "engine/output/result_json.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/run_label.hpp"
#include "python/src/afm.hpp"
#include "python/src/interrupt_check.hpp"
#include "python/src/python_parts.hpp"
#include "python/src/python_sweep.hpp"
#include "python/src/trajectory_recorder.hpp"

namespace py = pybind11;

namespace mdrsim::python {
namespace {

/// A scene document and the Scene it builds, shared with the results of its runs. Built as
/// soon as the document is made, so that bad input fails where it was given.
struct SceneHandle {
  SceneDocument document;
  std::shared_ptr<const Scene> scene;
};

/// Builds without the GIL; Python parts take it back in their factories.
SceneHandle built(SceneDocument document) {
  const auto registries = current_registries();
  SceneHandle handle{std::move(document), nullptr};
  py::gil_scoped_release release;
  handle.scene = std::make_shared<const Scene>(handle.document.build(*registries));
  return handle;
}

struct ResultHandle {
  std::shared_ptr<const Scene> scene;
  RunResult result;
  /// The recorded trajectory until its arrays are made; null without one.
  std::unique_ptr<TrajectoryRows> rows;
  py::object trajectory;                   ///< the dict of arrays, made on first access
  std::uint64_t trajectory_rows_seen = 0;  ///< rows the run gave, held or not
  std::uint64_t trajectory_stride = 1;     ///< 1, or the thinning of the ordinary rows
};

/// `trajectory_rows`: the row budget of the trajectory (TrajectoryRecorder), none without one.
/// `samples`: points of the continuum route's branch in the trajectory (`sample` rows).
std::unique_ptr<ResultHandle> run(const SceneHandle& handle,
                                  std::optional<std::uint64_t> trajectory_rows,
                                  std::int64_t samples) {
  auto out = std::make_unique<ResultHandle>();
  out->scene = handle.scene;
  std::optional<std::string> not_finite;
  {
    const InterruptibleRun interruptible;
    py::gil_scoped_release release;
    TrajectoryRecorder recorder(trajectory_rows.value_or(1));
    ObserverList observers;
    if (trajectory_rows) observers.add(recorder);
    out->result = run_scene(*out->scene, observers, samples);
    not_finite = first_not_finite(*out->scene, out->result);
    if (trajectory_rows) {
      out->rows = std::make_unique<TrajectoryRows>(recorder.take());
      out->trajectory_rows_seen = out->rows->rows_seen;
      out->trajectory_stride = out->rows->stride;
    }
  }
  if (not_finite) {
    throw std::runtime_error(fmt::format(
        "the run gave {}, not a finite number; the scene's values may be too extreme for double "
        "precision",
        *not_finite));
  }
  return out;
}

/// A NumPy array over the column's own buffer: the capsule owns it, nothing is copied.
template <class T>
py::array take_column(std::vector<T>& column, const py::dtype& dtype) {
  if (column.empty()) return py::array(dtype, std::vector<py::ssize_t>{0});
  auto* owned = new std::vector<T>(std::move(column));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  py::array array(dtype, {static_cast<py::ssize_t>(owned->size())}, {sizeof(T)}, owned->data(),
                  owner);
  // One array per column and result: writes through it would change the result itself.
  array.attr("flags").attr("writeable") = false;
  return array;
}

/// What a run's states say beyond the fields every state has, as the JSON's do.
struct PyStateKeys {
  bool friction = false;  ///< how much of it slides (docs/friction.md)
  bool cohesive = false;  ///< the cohesive zone's radius (docs/maugis.md)
  bool time = false;      ///< a timed program's clock (docs/programs.md "Time")
};

/// With friction the arrays gain `sliding`, with finite-range adhesion `cohesive_radius`, and
/// for a timed program `time`, as the CSV gains its columns (docs/friction.md, docs/maugis.md,
/// docs/programs.md).
py::dict take_trajectory(TrajectoryColumns& c, const PyStateKeys& keys) {
  std::vector<py::str> stage_names;
  for (const std::string& name : c.stage_names) stage_names.emplace_back(name);
  py::list stage(c.stage.size());
  for (std::size_t i = 0; i < c.stage.size(); ++i) {
    stage[i] = stage_names[static_cast<std::size_t>(c.stage[i])];
  }
  // One name per kind, up to the last (engine/events/event.hpp).
  std::vector<py::object> kind_names(static_cast<std::size_t>(EventKind::spring_stuck) + 1);
  py::list event(c.event.size());
  for (std::size_t i = 0; i < c.event.size(); ++i) {
    py::object& name = kind_names[static_cast<std::size_t>(c.event[i])];
    if (!name) name = py::str(to_string(c.event[i]));
    event[i] = name;
  }
  const auto f8 = py::dtype::of<double>();
  py::dict t;
  t["stage"] = stage;
  t["event"] = event;
  t["in_cascade"] = take_column(c.in_cascade, py::dtype::of<bool>());
  for (std::size_t i = 0; i < kTrajectoryFields.size(); ++i) {
    t[kTrajectoryFields[i].name] = take_column(c.state[i], f8);
  }
  t["springs_in_contact"] = take_column(c.springs_in_contact, py::dtype::of<std::int64_t>());
  t["normal_control"] = take_column(c.normal_control, f8);
  if (keys.friction) {
    t["sliding"] = take_column(c.springs_sliding, py::dtype::of<std::int64_t>());
  }
  if (keys.cohesive) t["cohesive_radius"] = take_column(c.cohesive_radius, f8);
  if (keys.time) t["time"] = take_column(c.time, f8);
  return t;
}

/// With friction a state also says how much of it slides, with finite-range adhesion the
/// cohesive zone's radius, and in a timed program its time, as the JSON's states do.
py::dict snapshot(const ContactSnapshot& s, const PyStateKeys& keys) {
  py::dict d;
  d["normal_control"] = s.normal_control;
  for (const SnapshotField& f : kSnapshotFields) d[f.name] = s.*f.member;
  if (keys.cohesive) d["cohesive_radius"] = s.cohesive_radius;
  if (keys.time) d["time"] = s.time;
  d["springs_in_contact"] = s.springs_in_contact;
  d["disk_valid"] = s.disk_valid;
  if (keys.friction) {
    d["springs_sliding"] = s.springs_sliding;
    d["stick_radius"] = s.stick_radius;
  }
  return d;
}

py::object optional_snapshot(const std::optional<ContactSnapshot>& s, const PyStateKeys& keys) {
  return s ? py::object(snapshot(*s, keys)) : py::object(py::none());
}

/// Which parts of the work a result names, as the JSON's `work` does: friction's, the rate
/// law's front's and a relaxing bulk's dashpots' dissipation.
struct PyWorkKeys {
  bool friction = false;
  bool front = false;  ///< detachment.front_speed_law (docs/rate_law.md)
  bool bulk = false;   ///< material.relaxation (docs/viscoelastic.md)
};

/// The work on each axis and the dissipations the scene has, keyed as the JSON's `work`.
py::dict work(const AxisWork& w, PyWorkKeys keys) {
  py::dict d;
  d["normal"] = w.normal;
  d["tangential"] = w.tangential;
  if (keys.friction) d["dissipated_by_friction"] = w.friction;
  if (keys.front) d["dissipated_at_front"] = w.front;
  if (keys.bulk) d["dissipated_by_bulk"] = w.bulk;
  return d;
}

bool has_friction(const ResultHandle& r) { return r.scene->friction.has_value(); }
PyWorkKeys work_keys(const ResultHandle& r) {
  return {.friction = has_friction(r),
          .front = r.scene->front_speed_law.has_value(),
          .bulk = r.scene->material.relaxes()};
}
bool has_zone(const ResultHandle& r) { return r.scene->material.finite_range(); }
PyStateKeys state_keys(const ResultHandle& r) {
  return {.friction = has_friction(r),
          .cohesive = has_zone(r),
          .time = r.scene->program && r.scene->program->timed()};
}

void bind_scenes(py::module_& m) {
  py::class_<SceneHandle>(m, "Document", "A parsed scene and the Scene it builds (internal).")
      .def_static(
          "from_file",
          [](const std::string& path) { return built(SceneDocument::from_file(path)); },
          py::arg("path"))
      .def_static(
          "from_text",
          [](const std::string& text, const std::string& source_name, const std::string& base_dir) {
            return built(SceneDocument::from_scene_text(text, source_name, base_dir));
          },
          py::arg("text"), py::arg("source_name"), py::arg("base_dir"))
      .def(
          "with_values",
          [](const SceneHandle& h, const std::vector<std::pair<std::string, std::string>>& values) {
            SceneDocument document = h.document;
            for (const auto& [key, value] : values) document.set_value(key, value);
            return built(std::move(document));
          },
          py::arg("values"), "Overrides as (dotted key, TOML value text), checked like --set.")
      .def_property_readonly("source_name",
                             [](const SceneHandle& h) { return h.document.source_name(); })
      .def("to_toml", [](const SceneHandle& h) { return h.document.to_toml(); })
      .def_property_readonly("title", [](const SceneHandle& h) { return h.scene->title; })
      .def_property_readonly("springs", [](const SceneHandle& h) { return h.scene->springs; })
      .def_property_readonly("method",
                             [](const SceneHandle& h) { return to_string(h.scene->solver.method); })
      .def_property_readonly("material", [](const SceneHandle& h) { return h.scene->material; })
      .def_property_readonly("profile", [](const SceneHandle& h) { return h.scene->profile_name; })
      .def_property_readonly("criterion",
                             [](const SceneHandle& h) { return h.scene->detachment_law(); })
      .def_property_readonly("control",
                             [](const SceneHandle& h) { return final_controls(*h.scene); });
}

void bind_results(py::module_& m) {
  py::class_<ResultHandle>(m, "RunResult", "The engine's result of one run (internal).")
      .def_property_readonly("status",
                             [](const ResultHandle& r) { return to_string(r.result.status); })
      .def_property_readonly("stop_reason",
                             [](const ResultHandle& r) -> std::optional<std::string> {
                               if (!r.result.stop_reason) return std::nullopt;
                               return to_string(*r.result.stop_reason);
                             })
      .def_property_readonly("title", [](const ResultHandle& r) { return r.scene->title; })
      .def_property_readonly(
          "critical",
          [](const ResultHandle& r) { return optional_snapshot(r.result.critical, state_keys(r)); })
      .def_property_readonly(
          "peak",
          [](const ResultHandle& r) { return optional_snapshot(r.result.peak, state_keys(r)); })
      .def_property_readonly("sliding", [](const ResultHandle& r) { return r.result.sliding; })
      .def_property_readonly("tangential_strength",
                             [](const ResultHandle& r) { return r.result.tangential_strength; })
      .def_property_readonly("stages",
                             [](const ResultHandle& r) {
                               py::list out;
                               const PyStateKeys keys = state_keys(r);
                               double start = 0.0;  // where the stage before it ended
                               for (const StageRecord& s : r.result.stages) {
                                 py::dict d;
                                 d["name"] = s.name;
                                 if (keys.time) {
                                   d["start_time"] = start;
                                   d["end_time"] = s.end.time;
                                   start = s.end.time;
                                 }
                                 d["end"] = snapshot(s.end, keys);
                                 d["work"] = work(s.work, work_keys(r));
                                 out.append(d);
                               }
                               return out;
                             })
      .def_property_readonly("jumps",
                             [](const ResultHandle& r) {
                               py::list out;
                               for (const JumpRecord& j : r.result.jumps) {
                                 py::dict d;
                                 d["stage"] = j.stage;
                                 d["kind"] = j.inward ? "in" : "out";
                                 const PyStateKeys keys = state_keys(r);
                                 d["critical"] = snapshot(j.critical, keys);
                                 // A flight (docs/programs.md "A fixed load that loses the
                                 // contact") has no state after it; a jump takes no time.
                                 ContactSnapshot after = j.after;
                                 after.time = j.critical.time;
                                 d["after"] = j.end == JumpEnd::state
                                                  ? py::object(snapshot(after, keys))
                                                  : py::object(py::none());
                                 d["end"] = to_string(j.end);
                                 d["springs"] = j.springs;
                                 d["glued_springs"] = j.glued_springs;
                                 d["by_shear"] = j.by_shear;
                                 out.append(d);
                               }
                               return out;
                             })
      .def_property_readonly("work",
                             [](const ResultHandle& r) {
                               return r.result.work ? py::object(work(*r.result.work, work_keys(r)))
                                                    : py::object(py::none());
                             })
      .def_property_readonly("warnings", [](const ResultHandle& r) { return r.result.warnings; })
      .def_property_readonly("disk_valid",
                             [](const ResultHandle& r) { return r.result.disk_valid; })
      .def_property_readonly("has_warnings",
                             [](const ResultHandle& r) { return !r.result.warnings.empty(); })
      .def_property_readonly("counts",
                             [](const ResultHandle& r) {
                               py::dict d;
                               d["events"] = r.result.counts.events;
                               d["steps"] = r.result.counts.steps;
                               d["halvings"] = r.result.counts.halvings;
                               d["root_iterations"] = r.result.counts.root_iterations;
                               return d;
                             })
      .def_property_readonly("springs", [](const ResultHandle& r) { return r.result.springs; })
      .def_property_readonly("wall_time_s",
                             [](const ResultHandle& r) { return r.result.wall_time_s; })
      .def_property_readonly(
          "scales",
          [](const ResultHandle& r) -> py::object {
            const auto s = dimensionless_scales(*r.scene);
            if (!s) return py::none();
            py::dict d;
            for (const ScaleKind kind : {ScaleKind::force, ScaleKind::radius, ScaleKind::depth}) {
              d[scale_key(kind)] = scale_of(*s, kind);
            }
            d["basis"] = s->basis;
            return d;
          })
      .def_property_readonly("maugis_parameter",
                             [](const ResultHandle& r) { return maugis_parameter(*r.scene); })
      .def_readonly("trajectory_rows_seen", &ResultHandle::trajectory_rows_seen)
      .def_readonly("trajectory_stride", &ResultHandle::trajectory_stride)
      .def("json", [](const ResultHandle& r) { return result_to_json(*r.scene, r.result).dump(); })
      .def("trajectory", [](ResultHandle& r) -> py::object {
        // Under the GIL throughout: another thread may ask for the same result's arrays.
        if (!r.trajectory && r.rows) {
          TrajectoryColumns columns = r.rows->columns();
          r.rows.reset();
          r.trajectory = take_trajectory(columns, state_keys(r));
        }
        return r.trajectory ? r.trajectory : py::object(py::none());
      });
  m.def("run", &run, py::arg("scene"), py::arg("trajectory"), py::arg("samples") = 0,
        "Runs the scene with the GIL released; Python parts take it back for each call.");
  // The states' fields and the scale each is divided by, so that the package names none.
  py::tuple fields(kSnapshotFields.size());
  for (std::size_t i = 0; i < kSnapshotFields.size(); ++i) {
    fields[i] = py::make_tuple(kSnapshotFields[i].name, scale_key(kSnapshotFields[i].scale));
  }
  m.attr("SNAPSHOT_FIELDS") = fields;
}

}  // namespace
}  // namespace mdrsim::python

PYBIND11_MODULE(_core, m) {
  m.doc() = "The C++ engine of mdrsim; use the package mdrsim, not this module.";
  mdrsim::python::remember_main_thread();
  // Never freed: a static py::object would be released after the interpreter is gone.
  static PyObject* scene_error =
      (new py::exception<mdrsim::SceneError>(m, "SceneError", PyExc_ValueError))->ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const mdrsim::SceneError& e) {
      PyErr_SetString(scene_error, mdrsim::one_line(e.what()).c_str());
    }
  });

  // The engine logs through spdlog's default logger: to standard error, silent until
  // mdrsim.set_log_level; a run's warnings reach Python in its result.
  auto logger =
      std::make_shared<spdlog::logger>("mdrsim", std::make_shared<spdlog::sinks::stderr_sink_mt>());
  logger->set_formatter(mdrsim::cli::labelled_formatter("[mdrsim %l] %*%v"));  // %*: a sweep's row
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::off);
  m.def(
      "set_log_level",
      [](const std::string& level) {
        const auto parsed = spdlog::level::from_str(level);
        if (level != "off" && parsed == spdlog::level::off) {
          throw py::value_error(fmt::format(
              "unknown log level '{}' (known: trace, debug, info, warn, error, off)", level));
        }
        spdlog::set_level(parsed);
      },
      py::arg("level"));

  mdrsim::python::bind_parts(m);
  mdrsim::python::bind_scenes(m);
  mdrsim::python::bind_results(m);
  mdrsim::python::bind_sweep(m);
  mdrsim::python::bind_afm(m);
}

// The rows of mdrsim.sweep, parsed, built, checked and written by `mdrsim sweep`'s own code
// (engine/sweep/, engine/output/), so that each row is the command's, byte for byte.
#include "python/src/python_sweep.hpp"

#include <pybind11/stl.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/base/available_cpus.hpp"
#include "engine/output/sweep_csv.hpp"
#include "engine/output/sweep_rows.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/sweep_design.hpp"
#include "engine/sweep/sweep_grid.hpp"
#include "engine/sweep/sweep_progress.hpp"
#include "engine/sweep/usage_error.hpp"
#include "engine/sweep/vary_spec.hpp"
#include "python/src/interrupt_check.hpp"
#include "python/src/python_parts.hpp"

namespace py = pybind11;

namespace mdrsim::python {
namespace {

using cli::check_values;
using cli::SweepGrid;
using cli::VarySpec;
using cli::VaryValue;

/// What mdrsim.sweep's grid and design arguments become: the command's flags as text.
struct GridFlags {
  std::vector<std::string> vary;  ///< KEY=VALUES, each a --vary or (linked) a --link
  std::vector<bool> linked;       ///< empty: none is linked
  std::vector<std::string> where;
  std::string design;
  std::string samples;
  std::string seed;
};

/// The command's --vary, --link, --where and --design parsers; their UsageError (exit 2
/// there) is a SceneError here.
SweepGrid parse_grid(const GridFlags& flags) {
  try {
    const cli::SweepDesign design = cli::parse_design(flags.design, flags.samples, flags.seed);
    std::vector<VarySpec> specs;
    for (std::size_t k = 0; k < flags.vary.size(); ++k) {
      const bool linked = k < flags.linked.size() && flags.linked[k];
      specs.push_back(cli::parse_vary(flags.vary[k], design.drawn(), linked ? "--link" : "--vary"));
      specs.back().linked = linked;
    }
    return SweepGrid(std::move(specs), flags.where, design);
  } catch (const cli::UsageError& e) {
    throw SceneError(e.what());
  }
}

using Overrides = std::vector<std::pair<std::string, std::string>>;

/// A sweep of one scene (its text and with_values overrides, as mdrsim.Scene keeps them) over
/// the --vary texts. Made once by the caller, which checks the values, and again wherever
/// rows run (a Dask worker), told the columns (dimensionless, friction, work, bulk, front) so
/// that it checks nothing.
class SweepPlan {
 public:
  SweepPlan(const std::string& text, const std::string& source_name, const std::string& base_dir,
            const Overrides& overrides, const GridFlags& flags, std::optional<bool> dimensionless,
            std::optional<bool> friction, std::optional<bool> work, std::optional<bool> bulk,
            std::optional<bool> front)
      : grid_(parse_grid(flags)), registries_(current_registries()) {
    std::vector<std::string> sets;
    for (const auto& [key, value] : overrides) sets.push_back(key + "=" + value);
    scene_hash_ = cli::scene_hash(text, sets);
    py::gil_scoped_release release;  // Python parts take the GIL back in their factories
    base_.emplace(SceneDocument::from_scene_text(text, source_name, base_dir));
    for (const auto& [key, value] : overrides) base_->set_value(key, value);
    if (dimensionless && friction && work && bulk && front) {
      columns_ = {*dimensionless, *friction, *work, *bulk, *front};
    } else {
      columns_ = check_values(*base_, grid_, *registries_);
    }
  }

  std::uint64_t rows() const { return grid_.rows(); }
  bool dimensionless() const { return columns_.dimensionless; }
  bool friction() const { return columns_.friction; }
  bool work() const { return columns_.work; }
  bool bulk() const { return columns_.bulk; }
  bool front() const { return columns_.front; }
  std::string header() const { return cli::csv_header(grid_, columns_); }
  std::string identity() const {
    return cli::identity_line({scene_hash_, grid_.hash(), grid_.rows(), cli::Shard{}});
  }

  /// Each key's values as (CSV text, value): a float where it is set as a number, else the
  /// name; None for a range a random design draws from (its values are numbers).
  py::list values() const {
    py::list out;
    for (const VarySpec& spec : grid_.keys()) {
      if (spec.drawn()) {
        out.append(py::none());
        continue;
      }
      py::list values;
      for (const VaryValue& v : spec.values) {
        values.append(py::make_tuple(
            v.text, v.number ? py::object(py::float_(*v.number)) : py::object(py::str(v.text))));
      }
      out.append(values);
    }
    return out;
  }

  /// The CSV lines of rows first .. first + count - 1, each with its newline; the first
  /// failing row in row order raises (SceneError for a bad combination of values).
  std::vector<std::string> run_rows(std::uint64_t first, std::uint64_t count) const {
    if (first > grid_.rows() || count > grid_.rows() - first) {
      throw py::index_error("SweepPlan.run_rows: rows beyond the grid");
    }
    std::vector<std::string> lines;
    const InterruptibleRun interruptible;
    py::gil_scoped_release release;
    SceneDocument document = *base_;  // a copy re-parses: once per call, as once per worker
    for (std::uint64_t row = first; row < first + count; ++row) {
      lines.push_back(cli::run_row(document, grid_, row, *registries_, columns_));
    }
    return lines;
  }

 private:
  SweepGrid grid_;
  std::shared_ptr<const Registries> registries_;
  std::optional<SceneDocument> base_;
  std::uint64_t scene_hash_ = 0;
  cli::SweepColumns columns_;
};

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("available_cpus", &available_cpus,
        "The CPUs this process may run on (its affinity mask): sweep()'s default thread count, "
        "as `mdrsim sweep` takes it.");
  py::class_<SweepPlan>(m, "SweepPlan",
                        "The rows of a sweep, as `mdrsim sweep` makes them (internal).")
      .def(py::init([](const std::string& text, const std::string& source_name,
                       const std::string& base_dir, const Overrides& overrides,
                       const std::vector<std::string>& vary, const std::vector<bool>& linked,
                       const std::vector<std::string>& where, const std::string& design,
                       const std::string& samples, const std::string& seed,
                       std::optional<bool> dimensionless, std::optional<bool> friction,
                       std::optional<bool> work, std::optional<bool> bulk,
                       std::optional<bool> front) {
             return SweepPlan(text, source_name, base_dir, overrides,
                              {vary, linked, where, design, samples, seed}, dimensionless, friction,
                              work, bulk, front);
           }),
           py::arg("text"), py::arg("source_name"), py::arg("base_dir"), py::arg("overrides"),
           py::arg("vary"), py::arg("linked") = std::vector<bool>{},
           py::arg("where") = std::vector<std::string>{}, py::arg("design") = "",
           py::arg("samples") = "", py::arg("seed") = "", py::arg("dimensionless") = py::none(),
           py::arg("friction") = py::none(), py::arg("work") = py::none(),
           py::arg("bulk") = py::none(), py::arg("front") = py::none())
      .def_property_readonly("rows", &SweepPlan::rows)
      .def_property_readonly("dimensionless", &SweepPlan::dimensionless)
      .def_property_readonly("friction", &SweepPlan::friction)
      .def_property_readonly("work", &SweepPlan::work)
      .def_property_readonly("bulk", &SweepPlan::bulk)
      .def_property_readonly("front", &SweepPlan::front)
      .def_property_readonly("header", &SweepPlan::header)
      .def_property_readonly("identity", &SweepPlan::identity)
      .def("values", &SweepPlan::values)
      .def("run_rows", &SweepPlan::run_rows, py::arg("first"), py::arg("count"));

  using Clock = cli::SweepProgress::Clock;
  py::class_<cli::SweepProgress>(m, "SweepProgress",
                                 "The command's progress lines of a sweep (internal).")
      .def(py::init([](std::uint64_t rows, double interval_s) {
             return cli::SweepProgress(0, rows, Clock::now(),
                                       std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(interval_s)));
           }),
           py::arg("rows"), py::arg("interval_s"))
      .def(
          "line",
          [](cli::SweepProgress& progress, std::uint64_t written) {
            return progress.line(written, Clock::now());
          },
          py::arg("written"));
}

}  // namespace mdrsim::python

// Python callables behind the DetachmentCriterion and Profile interfaces. mdrsim.run releases
// the GIL while the engine runs, so every call into Python takes it back first.
#include "python/src/python_parts.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "profiles/mdr_transform.hpp"
#include "python/src/octave_image.hpp"

namespace py = pybind11;

namespace mdrsim::python {
namespace {

bool interpreter_alive() {
#if PY_VERSION_HEX >= 0x030D0000
  return Py_IsInitialized() && !Py_IsFinalizing();
#else
  return Py_IsInitialized() && !_Py_IsFinalizing();
#endif
}

/// A Python object that C++ may drop without the GIL (a Scene freed after a run): the
/// reference is released under the GIL, or left alone once the interpreter is going away.
template <class Object>
class Held {
 public:
  explicit Held(Object object) : object_(std::move(object)) {}
  Held(const Held&) = delete;
  Held& operator=(const Held&) = delete;
  ~Held() {
    if (object_.ptr() == nullptr) return;
    if (interpreter_alive()) {
      py::gil_scoped_acquire gil;
      object_.dec_ref();
    }
    object_.release();  // the member's own destructor must not touch the count again
  }
  const Object& get() const { return object_; }

 private:
  Object object_;
};

/// One registered part's callables. Registrations live as long as the process: a spec is
/// never freed, so the registries' factories can point at it from any thread.
struct PartSpec {
  std::string name;
  std::string summary;
  std::vector<ParameterSpec> parameters;
  py::object first;   ///< criterion: margin; profile: shape
  py::object second;  ///< criterion: critical_elongation; profile: image; or None
  py::object third;   ///< profile: tip_radius(**parameters); or None
};

/// The scene's values of the declared parameters, as keyword arguments.
py::dict keyword_arguments(const std::vector<ParameterSpec>& specs, const ParameterValues& v) {
  py::dict kwargs;
  for (const ParameterSpec& spec : specs) {
    if (!v.has(spec.key)) continue;
    const py::str key(spec.key);
    switch (spec.kind) {
      case ParameterKind::number:
        kwargs[key] = v.number(spec.key);
        break;
      case ParameterKind::integer:
        kwargs[key] = static_cast<long long>(v.number(spec.key));
        break;
      case ParameterKind::number_list:
        kwargs[key] = py::cast(v.numbers(spec.key));
        break;
      case ParameterKind::text:
      case ParameterKind::path:
        kwargs[key] = v.text(spec.key);
        break;
    }
  }
  return kwargs;
}

/// A callable's answer as a finite double; a TypeError or ValueError naming the part if not.
double finite_number(const py::handle value, const PartSpec& spec, const char* function) {
  const double x = PyFloat_AsDouble(value.ptr());
  if (x == -1.0 && PyErr_Occurred()) throw py::error_already_set();
  if (!std::isfinite(x)) {
    throw py::value_error(
        fmt::format("'{}': {} returned {}, not a finite number", spec.name, function, x));
  }
  return x;
}

template <class... Args>
py::object call(const py::object& fn, const py::dict& kwargs, Args&&... args) {
  if (kwargs.empty()) return fn(std::forward<Args>(args)...);
  return fn(std::forward<Args>(args)..., **kwargs);
}

class PythonCriterion final : public DetachmentCriterion {
 public:
  PythonCriterion(const PartSpec& spec, py::object material, py::dict kwargs)
      : spec_(&spec), material_(std::move(material)), kwargs_(std::move(kwargs)) {}

  double margin(const BoundarySpring& s) const override {
    py::gil_scoped_acquire gil;
    return finite_number(call(spec_->first, kwargs(), s.elongation, s.tangential_displacement,
                              s.contact_radius, material_.get()),
                         *spec_, "margin");
  }

  std::optional<double> critical_elongation(double contact_radius,
                                            double tangential_displacement) const override {
    if (spec_->second.is_none()) return std::nullopt;
    py::gil_scoped_acquire gil;
    const py::object e =
        call(spec_->second, kwargs(), contact_radius, tangential_displacement, material_.get());
    if (e.is_none()) return std::nullopt;
    return finite_number(e, *spec_, "critical_elongation");
  }

 private:
  const py::dict& kwargs() const { return kwargs_.get(); }
  const PartSpec* spec_;
  Held<py::object> material_;  ///< mdrsim.Material
  Held<py::dict> kwargs_;      ///< the parameters' values
};

/// A registered shape with the scene's parameters: f(r), and g(x) by eq. 4 from f alone.
class PythonShape {
 public:
  PythonShape(const PartSpec& spec, py::dict kwargs) : spec_(&spec), kwargs_(std::move(kwargs)) {}

  /// f(r), the GIL held.
  double shape_held(double radius) const {
    return finite_number(call(spec_->first, kwargs(), radius), *spec_, "shape");
  }

  /// Eq. 4 from f alone: f'(r) by a fourth-order central difference of f(|r|) (an
  /// axisymmetric f is even), integrated by tanh-sinh (profiles/mdr_transform). Takes the GIL.
  double image(double x) const {
    py::gil_scoped_acquire gil;
    const auto slope = [&](double r) {
      const double h = 1e-4 * std::max(r, 1e-3 * x);
      const auto f = [&](double at) { return shape_held(std::abs(at)); };
      return (8.0 * (f(r + h) - f(r - h)) - (f(r + 2 * h) - f(r - 2 * h))) / (12.0 * h);
    };
    return mdr_transform(slope, x);
  }

  const py::dict& kwargs() const { return kwargs_.get(); }
  const PartSpec& spec() const { return *spec_; }

 private:
  const PartSpec* spec_;
  Held<py::dict> kwargs_;
};

/// The image tables of the last few (profile, parameters) built: a sweep or with_values builds
/// a scene per value from the same shape. Read and written with the GIL held.
std::shared_ptr<const OctaveImage> shared_image(const std::shared_ptr<const PythonShape>& shape) {
  static constexpr std::size_t kKept = 8;
  struct Entry {
    const PartSpec* spec;
    std::string parameters;
    std::shared_ptr<const OctaveImage> image;
  };
  static auto* cache = new std::vector<Entry>;  // never freed: see parts()
  std::string parameters = py::repr(shape->kwargs());
  for (const Entry& e : *cache) {
    if (e.spec == &shape->spec() && e.parameters == parameters) return e.image;
  }
  auto image = std::make_shared<const OctaveImage>([shape](double x) { return shape->image(x); });
  if (cache->size() == kKept) cache->erase(cache->begin());
  cache->push_back({&shape->spec(), std::move(parameters), image});
  return image;
}

class PythonProfile final : public Profile {
 public:
  PythonProfile(std::shared_ptr<const PythonShape> shape, std::optional<double> tip_radius)
      : shape_(std::move(shape)), tip_radius_(tip_radius) {
    if (shape_->spec().second.is_none()) image_table_ = shared_image(shape_);
  }

  double shape(double radius) const override {
    py::gil_scoped_acquire gil;
    return shape_->shape_held(radius);
  }

  double mdr_image(double x) const override {
    if (image_table_) return (*image_table_)(x);
    py::gil_scoped_acquire gil;
    return finite_number(call(shape_->spec().second, shape_->kwargs(), x), shape_->spec(), "image");
  }

  std::optional<double> jkr_scale_radius() const override { return tip_radius_; }

 private:
  std::shared_ptr<const PythonShape> shape_;
  /// Without an `image` callable: eq. 4, tabulated (octave_image.hpp).
  std::shared_ptr<const OctaveImage> image_table_;
  std::optional<double> tip_radius_;  ///< [m]
};

/// Parameters as mdrsim/_parts.py passes them: (key, kind, help, required, default, lower,
/// upper), a bound as (value, inclusive) or None.
std::vector<ParameterSpec> parameter_specs(const py::list& specs) {
  static const std::map<std::string, ParameterKind> kinds{
      {"number", ParameterKind::number},
      {"integer", ParameterKind::integer},
      {"number_list", ParameterKind::number_list},
      {"text", ParameterKind::text},
      {"path", ParameterKind::path}};
  const auto bound = [](const py::handle b) -> std::optional<Bound> {
    if (b.is_none()) return std::nullopt;
    const auto [value, inclusive] = b.cast<std::pair<double, bool>>();
    return Bound{value, inclusive};
  };
  std::vector<ParameterSpec> out;
  for (const py::handle item : specs) {
    const auto t = item.cast<py::tuple>();
    const auto kind = kinds.find(t[1].cast<std::string>());
    if (kind == kinds.end()) {
      throw py::value_error(
          fmt::format("unknown parameter kind '{}' (known: integer, number, "
                      "number_list, path, text)",
                      t[1].cast<std::string>()));
    }
    out.push_back({.key = t[0].cast<std::string>(),
                   .kind = kind->second,
                   .help = t[2].cast<std::string>(),
                   .required = t[3].cast<bool>(),
                   .default_value =
                       t[4].is_none() ? std::nullopt : std::optional<double>(t[4].cast<double>()),
                   .lower = bound(t[5]),
                   .upper = bound(t[6])});
  }
  return out;
}

struct PythonParts {
  std::map<std::string, const PartSpec*> criteria;
  std::map<std::string, const PartSpec*> profiles;
  std::shared_ptr<const Registries> registries =
      std::make_shared<const Registries>(Registries::builtin());
};

/// Never freed: the interpreter may be gone by the time static objects are destroyed.
PythonParts& parts() {
  static auto* p = new PythonParts;
  return *p;
}

CriterionRegistry::Entry criterion_entry(const PartSpec* spec) {
  return {.name = spec->name,
          .summary = spec->summary,
          .parameters = spec->parameters,
          .create = [spec](const ParameterValues& v,
                           const InterfaceProperties& p) -> std::unique_ptr<DetachmentCriterion> {
            py::gil_scoped_acquire gil;
            return std::make_unique<PythonCriterion>(*spec, py::cast(Material(p)),
                                                     keyword_arguments(spec->parameters, v));
          }};
}

ProfileRegistry::Entry profile_entry(const PartSpec* spec) {
  return {.name = spec->name,
          .summary = spec->summary,
          .parameters = spec->parameters,
          .create = [spec](const ParameterValues& v) -> std::unique_ptr<Profile> {
            py::gil_scoped_acquire gil;
            py::dict kwargs = keyword_arguments(spec->parameters, v);
            std::optional<double> tip;
            if (!spec->third.is_none()) {
              const py::object r = call(spec->third, kwargs);
              if (!r.is_none()) tip = finite_number(r, *spec, "tip_radius");
            }
            return std::make_unique<PythonProfile>(
                std::make_shared<const PythonShape>(*spec, std::move(kwargs)), tip);
          }};
}

/// Registries anew from the built-in parts and every Python registration (the latest under
/// each name), so that registering a name again replaces the part.
void rebuild() {
  auto r = std::make_shared<Registries>(Registries::builtin());
  for (const auto& [name, spec] : parts().criteria) r->criteria.add(criterion_entry(spec));
  for (const auto& [name, spec] : parts().profiles) r->profiles.add(profile_entry(spec));
  parts().registries = std::move(r);
}

void register_part(const std::string& kind, const std::string& name, const std::string& summary,
                   const py::list& parameters, py::object first, py::object second,
                   py::object third) {
  const Registries builtin = Registries::builtin();
  const bool taken = kind == "criterion" ? builtin.criteria.find(name) != nullptr
                                         : builtin.profiles.find(name) != nullptr;
  if (name.empty()) throw py::value_error(fmt::format("a {} needs a name", kind));
  if (taken) throw py::value_error(fmt::format("{} '{}' is built in", kind, name));
  const auto* spec = new PartSpec{name,
                                  summary,
                                  parameter_specs(parameters),
                                  std::move(first),
                                  std::move(second),
                                  std::move(third)};
  (kind == "criterion" ? parts().criteria : parts().profiles)[name] = spec;
  rebuild();
}

template <class Registry>
py::dict summaries_of(const Registry& registry) {
  py::dict out;
  for (const std::string& name : registry.names())
    out[py::str(name)] = registry.find(name)->summary;
  return out;
}

}  // namespace

std::shared_ptr<const Registries> current_registries() { return parts().registries; }

void bind_parts(py::module_& m) {
  py::class_<Material>(m, "Material",
                       "The half-space and interface a criterion sees (SI units, read-only).")
      .def_readonly("effective_modulus", &Material::effective_modulus, "E* [Pa]")
      .def_readonly("effective_shear_modulus", &Material::effective_shear_modulus, "G* [Pa]")
      .def_readonly("work_of_adhesion", &Material::work_of_adhesion, "dgamma [J/m^2]")
      .def_readonly("approach_work_of_adhesion", &Material::approach_work_of_adhesion,
                    "dgamma_a [J/m^2]")
      // A float first: a criterion's call finds it in the first pass of the overloads. An
      // array (or a list) of radii gives an array of the values, element by element.
      .def("work_of_adhesion_at", &Material::work_of_adhesion_at, py::arg("r"),
           "dgamma at the radius r [m] of a spring [J/m^2] (a criterion lets go with this)")
      .def("work_of_adhesion_at", py::vectorize(&Material::work_of_adhesion_at), py::arg("r"),
           "dgamma at each radius of an array r [m] [J/m^2]")
      .def("approach_work_of_adhesion_at", &Material::approach_work_of_adhesion_at, py::arg("r"),
           "dgamma_a at the radius r [m] [J/m^2]")
      .def("approach_work_of_adhesion_at", py::vectorize(&Material::approach_work_of_adhesion_at),
           py::arg("r"), "dgamma_a at each radius of an array r [m] [J/m^2]")
      .def("__repr__", [](const Material& p) {
        std::string text = fmt::format(
            "Material(effective_modulus={}, effective_shear_modulus={}, work_of_adhesion={}, "
            "approach_work_of_adhesion={}",
            p.effective_modulus, p.effective_shear_modulus, p.work_of_adhesion,
            p.approach_work_of_adhesion);
        // Where dgamma varies with r the numbers above are its scale values: say so.
        if (p.work_of_adhesion_by_radius) {
          text += fmt::format(", work_of_adhesion_by_radius='{}'",
                              p.work_of_adhesion_by_radius->describe());
        }
        if (p.approach_work_of_adhesion_by_radius) {
          text += fmt::format(", approach_work_of_adhesion_by_radius='{}'",
                              p.approach_work_of_adhesion_by_radius->describe());
        }
        return text + ")";
      });
  m.def(
      "register_criterion",
      [](const std::string& name, const std::string& summary, const py::list& parameters,
         py::object margin, py::object critical_elongation) {
        register_part("criterion", name, summary, parameters, std::move(margin),
                      std::move(critical_elongation), py::none());
      },
      py::arg("name"), py::arg("summary"), py::arg("parameters"), py::arg("margin"),
      py::arg("critical_elongation"));
  m.def(
      "register_profile",
      [](const std::string& name, const std::string& summary, const py::list& parameters,
         py::object shape, py::object image, py::object tip_radius) {
        register_part("profile", name, summary, parameters, std::move(shape), std::move(image),
                      std::move(tip_radius));
      },
      py::arg("name"), py::arg("summary"), py::arg("parameters"), py::arg("shape"),
      py::arg("image"), py::arg("tip_radius"));
  m.def("parts", [] {
    const auto r = current_registries();
    py::dict out;
    out["profiles"] = summaries_of(r->profiles);
    out["criteria"] = summaries_of(r->criteria);
    out["controllers"] = summaries_of(r->controllers);
    return out;
  });
}

}  // namespace mdrsim::python

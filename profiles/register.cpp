// Registration of the built-in profiles: one explicit call, no static self-registration.
// Adding a profile, in three steps:
// 1. Write a class implementing Profile (profiles/profile.hpp: shape() and mdr_image() are
//    required, the closed forms optional) in profiles/NAME_profile.{hpp,cpp}; list the .cpp in
//    profiles/CMakeLists.txt.
// 2. Register it in register_builtin_profiles below with one call, its keys declared:
//      registry.add({.name = "NAME", .summary = "f = ...", .parameters = {{.key = "radius",
//                    .help = "R [m]", .lower = kPositive, .example = 0.01}},
//                    .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {...}});
// 3. `[profile] type = "NAME"` then works. Give each number key an `example` (a working value
//    in the tests' JKR scene, engine/reference/part_examples.cpp), a sample in
//    tests/profiles/profile_registry_test.cpp (EveryProfile runs the image's invariants over
//    every registered profile and fails for one without a sample), a row in docs/scene.md's
//    [profile] table, and tests of its own in tests/profiles/NAME_profile_test.cpp.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "profiles/cone_profile.hpp"
#include "profiles/flat_punch_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/profile_registry.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"
#include "profiles/wavy_profile.hpp"

namespace mdrsim {
namespace {

constexpr Bound kPositive{0.0, false};

/// The table of a `tabulated` profile from r and f, or from file; every problem is reported
/// at the key that holds it: r or f (with the point's index) or file (with the CSV line).
std::unique_ptr<Profile> make_tabulated(const ParameterValues& p) {
  const bool arrays = p.has("r") || p.has("f");
  if (p.has("file") && arrays) {
    throw ParameterError("file", "give file or the arrays r and f, not both");
  }
  ProfileTable table;
  std::string source;  // the file as shown in messages; empty for arrays
  if (p.has("file")) {
    try {
      table = read_profile_table(p.text("file"));
    } catch (const std::invalid_argument& e) {
      throw ParameterError("file", e.what());
    }
    source = std::filesystem::path(p.text("file")).lexically_normal().string();
  } else {
    for (const char* key : {"r", "f"}) {
      if (!p.has(key)) {
        throw ParameterError(key,
                             "missing, expected r = [...] and f = [...] (radii and gaps "
                             "[m]), or file = \"table.csv\"");
      }
    }
    table.radii = p.numbers("r");
    table.gaps = p.numbers("f");
  }
  if (const auto problem = find_table_problem(table)) {
    if (source.empty()) {
      const std::string key = problem->column == "count" ? "r" : problem->column;
      if (!problem->point) throw ParameterError(key, problem->message);
      const auto& column = key == "r" ? table.radii : table.gaps;
      throw ParameterError(key, fmt::format("{}[{}] = {} {}", key, *problem->point,
                                            column[*problem->point], problem->message));
    }
    if (!problem->point)
      throw ParameterError("file", fmt::format("'{}' {}", source, problem->message));
    const auto& column = problem->column == "r" ? table.radii : table.gaps;
    throw ParameterError(
        "file", fmt::format("line {} of '{}': {} = {} {}", table.lines[*problem->point], source,
                            problem->column, column[*problem->point], problem->message));
  }
  try {
    const auto built = TabulatedProfile::shared(table);
    if (p.has("file")) return std::make_unique<TabulatedProfile>(*built, p.text("file"));
    return std::make_unique<TabulatedProfile>(*built);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(source.empty() ? "r" : "file", e.what());
  }
}

}  // namespace

void register_builtin_profiles(ProfileRegistry& registry) {
  registry.add({.name = "parabolic",
                .summary = "f = r^2/(2R), the paper's profile (eq. 6)",
                .parameters = {{.key = "radius",
                                .help = "radius of curvature R [m]",
                                .lower = kPositive,
                                .example = 0.01}},
                .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
                  return std::make_unique<ParabolicProfile>(p.number("radius"));
                }});
  registry.add(
      {.name = "sphere",
       .summary = "f = R - sqrt(R^2 - r^2), the exact spherical cap",
       .parameters =
           {{.key = "radius", .help = "sphere radius R [m]", .lower = kPositive, .example = 0.01}},
       .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
         return std::make_unique<SphereProfile>(p.number("radius"));
       }});
  registry.add({.name = "cone",
                .summary = "f = r tan(theta)",
                .parameters = {{.key = "slope_angle_deg",
                                .help = "angle theta between flank and surface [degrees]",
                                .lower = kPositive,
                                .upper = Bound{90.0, false},
                                .example = 10.0}},
                .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
                  return std::make_unique<ConeProfile>(p.number("slope_angle_deg"));
                }});
  registry.add(
      {.name = "flat_punch",
       .summary = "f = 0 for r <= A, a wall outside",
       .parameters =
           {{.key = "radius", .help = "punch radius A [m]", .lower = kPositive, .example = 5e-4}},
       .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
         return std::make_unique<FlatPunchProfile>(p.number("radius"));
       }});
  registry.add(
      {.name = "power_law",
       .summary = "f = c r^n",
       .parameters =
           {{.key = "coefficient",
             .help = "coefficient c [m^(1-n)]",
             .lower = kPositive,
             .example = 0.8},
            {.key = "exponent", .help = "exponent n [1]", .lower = kPositive, .example = 1.5}},
       .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
         try {
           return std::make_unique<PowerLawProfile>(p.number("coefficient"), p.number("exponent"));
         } catch (const std::invalid_argument& e) {
           throw ParameterError("coefficient", e.what());
         }
       }});
  registry.add({.name = "wavy",
                .summary = "f = r^2/(2R) + A (1 - cos(2 pi r / lambda)), Guduru's wavy sphere",
                .parameters = {{.key = "radius",
                                .help = "radius of curvature R of the underlying parabola [m]",
                                .lower = kPositive,
                                .example = 0.01},
                               {.key = "amplitude",
                                .help = "ripple amplitude A [m] (0: the parabola)",
                                .lower = Bound{0.0, true},
                                .example = 1e-7},
                               {.key = "wavelength",
                                .help = "ripple wavelength lambda [m]",
                                .lower = kPositive,
                                .example = 1e-4}},
                .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
                  // A = 0 is the parabola itself, so that its results are `parabolic`'s bit for bit.
                  if (p.number("amplitude") == 0.0) {
                    return std::make_unique<ParabolicProfile>(p.number("radius"));
                  }
                  try {
                    return std::make_unique<WavyProfile>(p.number("radius"), p.number("amplitude"),
                                                         p.number("wavelength"));
                  } catch (const std::invalid_argument& e) {
                    throw ParameterError("wavelength", e.what());
                  }
                }});
  registry.add({.name = "tabulated",
                .summary = "f given at points r_i, a monotone cubic between them",
                .parameters = {{.key = "r",
                                .kind = ParameterKind::number_list,
                                .help = "radii r_i [m], from 0 and increasing",
                                .required = false,
                                .lower = Bound{0.0, true}},
                               {.key = "f",
                                .kind = ParameterKind::number_list,
                                .help = "gaps f(r_i) [m], from 0 and non-decreasing",
                                .required = false,
                                .lower = Bound{0.0, true}},
                               {.key = "file",
                                .kind = ParameterKind::path,
                                .help = "CSV file with columns r,f [m]",
                                .required = false}},
                .create = make_tabulated});
}

}  // namespace mdrsim

// mdrsim list: every registered profile, criterion and controller with its keys and units.
#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "engine/scene/registries.hpp"

namespace mdrsim::cli {
namespace {

/// "(0, 90)", "[0, 1]", "> 0": the range a number must lie in, as the scene reader checks it.
std::string range(const ParameterSpec& spec) {
  if (!spec.lower && !spec.upper) return {};
  if (!spec.upper) {
    return fmt::format("{} {}", spec.lower->inclusive ? ">=" : ">", spec.lower->value);
  }
  if (!spec.lower) {
    return fmt::format("{} {}", spec.upper->inclusive ? "<=" : "<", spec.upper->value);
  }
  return fmt::format("in {}{}, {}{}", spec.lower->inclusive ? "[" : "(", spec.lower->value,
                     spec.upper->value, spec.upper->inclusive ? "]" : ")");
}

const char* kind_name(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::number:
      return "number";
    case ParameterKind::integer:
      return "whole number";
    case ParameterKind::number_list:
      return "array of numbers";
    case ParameterKind::text:
      return "string";
    case ParameterKind::path:
      return "file path, relative to the scene (to the working directory from --set)";
  }
  return "?";
}

void print_parameters(std::FILE* out, const std::vector<ParameterSpec>& specs) {
  for (const ParameterSpec& spec : specs) {
    std::string line = fmt::format("      {} = {}: {}", spec.key, kind_name(spec.kind), spec.help);
    if (const std::string r = range(spec); !r.empty() && spec.kind != ParameterKind::path) {
      line += "; " + r;
    }
    if (spec.default_value) {
      line += fmt::format("; default {}", *spec.default_value);
    } else if (!spec.required) {
      line += "; optional";
    }
    fmt::print(out, "{}\n", line);
  }
}

/// The controller's held value, from one made with its parameters' examples (none: left out).
std::string held_value(const ControllerRegistry::Entry& entry) {
  ParameterValues values;
  for (const ParameterSpec& spec : entry.parameters) {
    if (const auto v = spec.example ? spec.example : spec.default_value) values.set(spec.key, *v);
  }
  try {
    const auto controller = entry.create(values);
    return fmt::format(" (holds its axis's {} [{}])", controller->held_value_key(),
                       controller->held_value_unit());
  } catch (const std::exception&) {
    return {};
  }
}

template <class Registry, class Extra>
void print_parts(std::FILE* out, const Registry& registry, const Extra& extra) {
  for (const std::string& name : registry.names()) {
    const auto* entry = registry.find(name);
    fmt::print(out, "  {}: {}{}\n", name, entry->summary, extra(*entry));
    print_parameters(out, entry->parameters);
  }
}

}  // namespace

int list_command() {
  const Registries registries = Registries::builtin();
  std::FILE* out = stdout;
  const auto nothing = [](const auto&) { return std::string(); };
  fmt::print(out, "profiles ([profile] type = NAME, then its keys):\n");
  print_parts(out, registries.profiles, nothing);
  fmt::print(
      out, "\ncriteria ([detachment] criterion = NAME, default \"mode-mixed\", then its keys):\n");
  print_parts(out, registries.criteria, nothing);
  fmt::print(out,
             "\ncontrollers (control = NAME in loading.normal, loading.tangential and each "
             "stage's axes, then its keys):\n");
  print_parts(out, registries.controllers,
              [](const ControllerRegistry::Entry& e) { return held_value(e); });
  fmt::print(out, "\nfriction laws ([friction] law = NAME, default \"coulomb\", then its keys):\n");
  print_parts(out, registries.friction_laws, nothing);
  fmt::print(out,
             "\nThe scene's other tables ([material], [loading], [discretization], [solver]) are "
             "described in docs/scene.md.\n");
  std::fflush(out);
  return std::ferror(out) ? 1 : 0;
}

}  // namespace mdrsim::cli

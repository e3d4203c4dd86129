// Example keys from the registries' declarations: no test switches on a part's name.
#include "engine/reference/part_examples.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <vector>

#include "engine/scene/registries.hpp"

namespace mdrsim::test {
namespace {

std::string join(const std::vector<ParameterSpec>& parameters, std::string_view separator) {
  std::string out;
  for (const ParameterSpec& p : parameters) {
    if (!p.example) continue;
    if (!out.empty()) out += separator;
    out += fmt::format("{} = {:.17g}", p.key, *p.example);
  }
  return out;
}

template <class Registry>
std::string keys_of(const Registry& registry, std::string_view name, std::string_view separator) {
  const auto* entry = registry.find(name);
  if (entry == nullptr) throw std::invalid_argument(fmt::format("no part named {}", name));
  return join(entry->parameters, separator);
}

}  // namespace

std::string example_keys(std::string_view kind, std::string_view name, std::string_view separator) {
  static const Registries registries = Registries::builtin();
  if (kind == "criterion") return keys_of(registries.criteria, name, separator);
  if (kind == "controller") return keys_of(registries.controllers, name, separator);
  if (kind == "profile") return keys_of(registries.profiles, name, separator);
  throw std::invalid_argument(fmt::format("no kind of part named {}", kind));
}

}  // namespace mdrsim::test

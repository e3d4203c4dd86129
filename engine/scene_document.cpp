// Parsing scene files and applying --set / --vary overrides at dotted keys.
#include "engine/scene_document.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "engine/scene_document_impl.hpp"
#include "engine/scene_error.hpp"

namespace mdrsim {
namespace {

std::vector<std::string> split_key(std::string_view origin, std::string_view dotted) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted.find('.', start);
    const std::string_view part =
        dotted.substr(start, dot == std::string_view::npos ? dotted.npos : dot - start);
    if (part.empty()) {
      throw SceneError(fmt::format("{}: '{}' is not a dotted scene key like material.poisson_ratio",
                                   origin, dotted));
    }
    parts.emplace_back(part);
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

/// The table that holds the last part of a dotted key, created as needed.
toml::table& parent_table(toml::table& root, const std::vector<std::string>& parts,
                          std::string_view origin, std::string_view dotted) {
  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i]);
    if (!next) next = &table->insert_or_assign(parts[i], toml::table{}).first->second;
    table = next->as_table();
    if (!table) {
      throw SceneError(fmt::format("{}: {}: '{}' is not a table", origin, dotted, parts[i]));
    }
  }
  return *table;
}

}  // namespace

SceneDocument::SceneDocument(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SceneDocument::SceneDocument(const SceneDocument& other)
    : impl_(std::make_unique<Impl>(*other.impl_)) {}
SceneDocument& SceneDocument::operator=(const SceneDocument& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}
SceneDocument::SceneDocument(SceneDocument&&) noexcept = default;
SceneDocument& SceneDocument::operator=(SceneDocument&&) noexcept = default;
SceneDocument::~SceneDocument() = default;

const std::string& SceneDocument::source_name() const { return impl_->source_name; }

SceneDocument SceneDocument::from_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw SceneError(fmt::format("{}: cannot read the scene file (it is a directory)", name));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError(
        fmt::format("{}: cannot read the scene file ({})", name, std::strerror(errno)));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return from_text(text.str(), name, path.parent_path().empty() ? "." : path.parent_path());
}

SceneDocument SceneDocument::from_text(std::string_view text, const std::string& source_name,
                                       const std::filesystem::path& base_dir) {
  auto impl = std::make_unique<Impl>();
  impl->source_name = source_name;
  impl->base_dir = base_dir;
  try {
    impl->root = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    throw SceneError(fmt::format("{}:{}:{}: malformed TOML: {}", source_name, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  return SceneDocument(std::move(impl));
}

void SceneDocument::set_value(std::string_view dotted_key, std::string_view value_text) {
  const auto parts = split_key("--set", dotted_key);
  toml::table& parent = parent_table(impl_->root, parts, "--set", dotted_key);
  toml::table parsed;
  try {
    parsed = toml::parse(fmt::format("v = {}", value_text), std::string_view("--set"));
  } catch (const toml::parse_error&) {
    // A bare word such as fixed-load: read it as a TOML string.
    std::string quoted = "\"";
    for (const char c : value_text) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    quoted += '"';
    try {
      parsed = toml::parse("v = " + quoted, std::string_view("--set"));
    } catch (const toml::parse_error& e) {
      throw SceneError(fmt::format("--set: {}: cannot read value '{}' ({})", dotted_key, value_text,
                                   e.description()));
    }
  }
  parsed.get("v")->visit([&](auto&& node) { parent.insert_or_assign(parts.back(), node); });
}

void SceneDocument::set_number(std::string_view dotted_key, double value, std::string_view origin) {
  const auto parts = split_key(origin, dotted_key);
  toml::table& parent = parent_table(impl_->root, parts, origin, dotted_key);
  toml::table parsed = toml::parse(fmt::format("v = {:.17g}", value), std::string(origin));
  parsed.get("v")->visit([&](auto&& node) { parent.insert_or_assign(parts.back(), node); });
}

Scene SceneDocument::build(const Registries& registries) const {
  return build_scene(impl_->root, impl_->source_name, impl_->base_dir, registries);
}

}  // namespace mdrsim

// The table as the profile read it (profiles/tabulated_profile), the hash over the file's bytes.
#include "engine/scene/embedded_table.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>

#include "engine/scene/scene_error.hpp"
#include "profiles/tabulated_profile.hpp"

namespace mdrsim {
namespace {

/// FNV-1a (64 bits) of the file's bytes in 16 hex digits; nullopt when it cannot be read.
std::optional<std::string> file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
    hash = (hash ^ static_cast<unsigned char>(*it)) * 0x100000001b3ULL;
  }
  if (in.bad()) return std::nullopt;
  return fmt::format("{:016x}", hash);
}

}  // namespace

void embed_profile_table(nlohmann::json& profile, const std::string& path) {
  const ProfileTable table = read_profile_table(path);
  profile["table"] = {
      {"r", table.radii}, {"f", table.gaps}, {"fnv1a", file_hash(path).value_or("")}};
}

void use_embedded_table(nlohmann::json& scene, const std::string& source_name) {
  const auto profile = scene.find("profile");
  if (profile == scene.end() || !profile->is_object()) return;
  const auto table = profile->find("table");
  if (table == profile->end() || !table->is_object()) return;
  const auto r = table->find("r");
  const auto f = table->find("f");
  if (r == table->end() || f == table->end() || !r->is_array() || !f->is_array()) return;
  const auto file = profile->find("file");
  if (file != profile->end() && file->is_string()) {
    const auto hash = table->find("fnv1a");
    const std::optional<std::string> now = file_hash(file->get<std::string>());
    if (now && hash != table->end() && hash->is_string() && *now == hash->get<std::string>()) {
      profile->erase("table");
      return;
    }
    spdlog::warn("{}: profile.file '{}' is {}; running the table embedded in the result",
                 source_name, printable(file->get<std::string>()),
                 now ? "not the file it was (another hash)" : "gone");
  }
  (*profile)["r"] = *r;
  (*profile)["f"] = *f;
  profile->erase("table");
  profile->erase("file");
}

}  // namespace mdrsim

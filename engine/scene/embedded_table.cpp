// The tables a scene read from files (a profile's r,f; a work of adhesion's r,value) and the
// hash over each file's bytes, carried in the result so that it reruns without them.
#include "engine/scene/embedded_table.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>

#include "engine/base/engine_logger.hpp"
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

nlohmann::json adhesion_table_record(const std::string& path, const TwoColumnFile& table) {
  return {{"r", table.first}, {"value", table.second}, {"fnv1a", file_hash(path).value_or("")}};
}

namespace {

/// One table holder (`profile`, or a work of adhesion given as a file): its file while it holds
/// the very bytes hashed, else its embedded columns r and `column`, with a warning.
void use_embedded(nlohmann::json& holder, const char* column, const std::string& shown,
                  const std::string& source_name) {
  if (!holder.is_object()) return;
  const auto table = holder.find("table");
  if (table == holder.end() || !table->is_object()) return;
  const auto r = table->find("r");
  const auto values = table->find(column);
  if (r == table->end() || values == table->end() || !r->is_array() || !values->is_array()) {
    return;
  }
  const auto file = holder.find("file");
  if (file != holder.end() && file->is_string()) {
    const auto hash = table->find("fnv1a");
    const std::optional<std::string> now = file_hash(file->get<std::string>());
    if (now && hash != table->end() && hash->is_string() && *now == hash->get<std::string>()) {
      holder.erase("table");
      return;
    }
    engine_logger().warn("{}: {}.file '{}' is {}; running the table embedded in the result",
                         source_name, shown, printable(file->get<std::string>()),
                         now ? "not the file it was (another hash)" : "gone");
  }
  holder["r"] = *r;
  holder[column] = *values;
  holder.erase("table");
  holder.erase("file");
}

}  // namespace

void use_embedded_table(nlohmann::json& scene, const std::string& source_name) {
  if (const auto profile = scene.find("profile"); profile != scene.end()) {
    use_embedded(*profile, "f", "profile", source_name);
  }
  const auto material = scene.find("material");
  if (material == scene.end() || !material->is_object()) return;
  for (const char* key : {"work_of_adhesion", "approach_work_of_adhesion"}) {
    if (const auto w = material->find(key); w != material->end()) {
      use_embedded(*w, "value", std::string("material.") + key, source_name);
    }
  }
}

}  // namespace mdrsim

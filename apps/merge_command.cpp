// mdrsim merge: the shards of one sweep joined into exactly the CSV the unsharded sweep writes.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/output_file.hpp"
#include "engine/output/sweep_csv.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

struct ShardFile {
  std::string path;
  SweepIdentity identity;
  SweepFile file;
};

std::string quoted(const std::string& path) { return fmt::format("'{}'", printable(path)); }

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec);
}

}  // namespace

int merge_command(const MergeOptions& options) {
  if (options.out.empty()) throw UsageError("merge: OUT needs a file path or -");
  std::vector<ShardFile> shards;
  for (const std::string& path : options.shards) {
    if (same_file(path, options.out)) {
      throw UsageError(fmt::format("merge: OUT {} is one of the shards", quoted(path)));
    }
    SweepFile file = read_sweep_file(path, "merge");
    const auto identity = parse_identity_line(file.first_line);
    if (!identity) {
      throw UsageError(
          fmt::format("merge: {} is not a sweep CSV (its first line is not '# mdrsim sweep: ...')",
                      quoted(path)));
    }
    shards.push_back({path, *identity, std::move(file)});
  }
  const ShardFile& first = shards.front();
  const std::uint64_t count = first.identity.shard.count;
  std::vector<const ShardFile*> by_index(count, nullptr);
  for (const ShardFile& s : shards) {
    const SweepIdentity& id = s.identity;
    const auto other = [&](const char* what) {
      throw UsageError(fmt::format("merge: {} is a sweep of another {} than {}", quoted(s.path),
                                   what, quoted(first.path)));
    };
    if (id.scene != first.identity.scene) other("scene");
    if (id.grid != first.identity.grid || id.rows != first.identity.rows) other("grid");
    if (id.shard.count != count) {
      throw UsageError(fmt::format("merge: {} is shard {}/{}, but {} is shard {}/{}",
                                   quoted(s.path), id.shard.index, id.shard.count,
                                   quoted(first.path), first.identity.shard.index, count));
    }
    if (by_index[id.shard.index]) {
      throw UsageError(fmt::format("merge: {} and {} are both shard {}/{}",
                                   quoted(by_index[id.shard.index]->path), quoted(s.path),
                                   id.shard.index, count));
    }
    by_index[id.shard.index] = &s;
    const std::uint64_t expected = id.shard.rows_of(id.rows);
    if (s.file.header.empty() || s.file.rows != expected || s.file.complete_bytes != s.file.size) {
      throw UsageError(fmt::format(
          "merge: {} (shard {}/{}) has {} of its {} rows; mdrsim sweep --resume finishes it",
          quoted(s.path), id.shard.index, count, s.file.rows, expected));
    }
    if (s.file.header != first.file.header) {
      throw UsageError(
          fmt::format("merge: {} has other columns than {}", quoted(s.path), quoted(first.path)));
    }
  }
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!by_index[i]) {
      throw UsageError(fmt::format("merge: shard {}/{} is missing", i, count));
    }
  }

  // Row r of the sweep is row r / N of shard r % N.
  std::vector<std::unique_ptr<std::ifstream>> inputs;
  for (const ShardFile* s : by_index) {
    auto in = std::make_unique<std::ifstream>(s->path, std::ios::binary);
    std::string skipped;
    std::getline(*in, skipped);
    std::getline(*in, skipped);
    inputs.push_back(std::move(in));
  }
  OutputFile out("merge", options.out);
  SweepIdentity merged = first.identity;
  merged.shard = Shard{};
  out.stream() << identity_line(merged) << first.file.header;
  std::string line;
  for (std::uint64_t row = 0; row < merged.rows; ++row) {
    std::ifstream& in = *inputs[row % count];
    if (!std::getline(in, line)) {
      throw std::runtime_error(
          fmt::format("merge: {} changed while it was read", quoted(by_index[row % count]->path)));
    }
    out.stream() << line << '\n';
  }
  out.commit();
  spdlog::info("merge: {} rows from {} shards", merged.rows, count);
  return 0;
}

}  // namespace mdrsim::cli

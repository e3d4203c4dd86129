// Outputs appear whole or not at all: written beside the target, renamed when complete.
#include "apps/output_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <iostream>
#include <stdexcept>

#include "apps/interrupt_cleanup.hpp"
#include "apps/write_error.hpp"
#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

/// Whether two paths name the same file, existing or not.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  const auto ca = std::filesystem::weakly_canonical(a, ec);
  if (ec) return false;
  const auto cb = std::filesystem::weakly_canonical(b, ec);
  return !ec && ca == cb;
}

}  // namespace

void require_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                              const std::string& scene_path) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [flag, path] = outputs[i];
    if (path.empty() || path == "-") continue;
    if (!scene_path.empty() && same_file(path, scene_path)) {
      throw UsageError(fmt::format("{}: '{}' is the scene file", flag, printable(path)));
    }
    for (std::size_t j = 0; j < i; ++j) {
      const auto& [other_flag, other_path] = outputs[j];
      if (other_path.empty() || other_path == "-") continue;
      if (same_file(path, other_path)) {
        throw UsageError(
            fmt::format("{}: '{}' is the {} output as well", flag, printable(path), other_flag));
      }
    }
  }
}

OutputFile::OutputFile(std::string flag, const std::string& path)
    : flag_(std::move(flag)), to_stdout_(path == "-"), path_(path) {
  if (to_stdout_) return;
  if (path.empty()) throw UsageError(fmt::format("{}: needs a file path or -", flag_));
  const auto cannot_write = [&](const std::string& why) {
    throw UsageError(fmt::format("{}: cannot write '{}' ({})", flag_, printable(path), why));
  };
  std::error_code ec;
  const auto status = std::filesystem::status(path_, ec);
  if (std::filesystem::is_directory(status)) cannot_write("it is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    // Renaming a file over /dev/null or a fifo would replace the device with a file.
    file_.open(path_, std::ios::binary | std::ios::out);
    if (!file_) cannot_write(system_reason(errno));
    return;
  }
  // The new file goes where a link points (also a dangling one), so the link survives.
  target_ = path_;
  for (int hops = 0; std::filesystem::is_symlink(std::filesystem::symlink_status(target_, ec));
       ++hops) {
    if (hops == 40) cannot_write(system_reason(ELOOP));
    const std::filesystem::path link = std::filesystem::read_symlink(target_, ec);
    if (ec) cannot_write(system_reason(ec.value()));
    target_ = link.is_absolute() ? link : target_.parent_path() / link;
  }
  partial_ = target_;
  partial_ += ".partial";
  file_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!file_) cannot_write(system_reason(errno));
  interrupt_slot_ = remove_on_interrupt(partial_.string());
}

OutputFile::~OutputFile() {
  if (!to_stdout_ && !committed_) {
    file_.close();
    std::error_code ec;
    if (!partial_.empty()) std::filesystem::remove(partial_, ec);
  }
  forget_on_interrupt(interrupt_slot_);
}

std::ostream& OutputFile::stream() { return to_stdout_ ? std::cout : file_; }

void OutputFile::commit() {
  if (to_stdout_) {
    std::cout.flush();
    if (!std::cout) {
      if (standard_output_reader_gone()) throw StandardOutputClosed();
      throw WriteError(fmt::format("{}: writing standard output failed", flag_));
    }
    return;
  }
  file_.close();
  if (!file_) {
    throw WriteError(fmt::format("{}: writing '{}' failed", flag_, printable(path_.string())));
  }
  if (!partial_.empty()) std::filesystem::rename(partial_, target_);
  committed_ = true;
  forget_on_interrupt(interrupt_slot_);
  interrupt_slot_ = -1;
}

}  // namespace mdrsim::cli

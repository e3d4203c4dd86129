// An output that is standard output for "-", else a file that appears only when complete.
#pragma once

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mdrsim::cli {

/// Output flags and their paths ("" = not given, "-" = standard output): throws UsageError
/// when two name the same file or one names the scene file, which a run would overwrite.
void require_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                              const std::string& scene_path);

/// Writes to PATH.partial and renames it to PATH on commit(); an uncommitted file is removed,
/// so a failed run leaves no partial output behind, nor one stopped by a signal where
/// install_interrupt_cleanup() holds (interrupt_cleanup.hpp). A symbolic link keeps pointing at the
/// new file; a device or pipe (/dev/null, a fifo) is written in place, never replaced by a file.
class OutputFile {
 public:
  /// `flag` names the option in messages; throws UsageError when the file cannot be created.
  OutputFile(std::string flag, const std::string& path);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  std::ostream& stream();
  void commit();

 private:
  std::string flag_;
  bool to_stdout_;
  std::filesystem::path path_;
  std::filesystem::path target_;   ///< the file renamed into place: PATH or where its link points
  std::filesystem::path partial_;  ///< empty when written in place
  std::ofstream file_;
  bool committed_ = false;
  int interrupt_slot_ = -1;  ///< the partial file's place in interrupt_cleanup, or -1
};

}  // namespace mdrsim::cli

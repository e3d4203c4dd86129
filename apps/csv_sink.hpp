// The --csv target of a command that writes rows as they are done (sweep, fit --resume): a
// file written in place (not renamed on completion) or standard output, one write() per line,
// so that whatever kills the command leaves whole lines behind.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

namespace mdrsim::cli {

class CsvSink {
 public:
  explicit CsvSink(std::string path) : path_(std::move(path)) {}
  CsvSink(const CsvSink&) = delete;
  CsvSink& operator=(const CsvSink&) = delete;
  ~CsvSink();

  /// Creates (or empties) the file and writes `head`.
  void open_fresh(const std::string& head);
  /// Opens the file to append after its first `keep` bytes (a torn last line is cut off).
  void open_resumed(std::uint64_t keep);
  /// Writes all of `text`; throws WriteError (StandardOutputClosed for a closed pipe on -).
  void write_all(std::string_view text);

 private:
  [[noreturn]] void cannot_write(const std::string& why) const;

  std::string path_;
  int fd_ = -1;
};

}  // namespace mdrsim::cli

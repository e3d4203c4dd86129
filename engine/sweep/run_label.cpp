// The thread-local run label and its spdlog flag.
#include "engine/sweep/run_label.hpp"

#include <fmt/format.h>
#include <spdlog/sinks/base_sink.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <set>
#include <utility>

namespace mdrsim::cli {
namespace {

thread_local std::string current_label;

class RunLabelFlag final : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg& /*message*/, const std::tm& /*time*/,
              spdlog::memory_buf_t& out) override {
    if (current_label.empty()) return;
    out.append(current_label.data(), current_label.data() + current_label.size());
    out.push_back(':');
    out.push_back(' ');
  }
  std::unique_ptr<custom_flag_formatter> clone() const override {
    return std::make_unique<RunLabelFlag>();
  }
};

}  // namespace

ScopedRunLabel::ScopedRunLabel(std::string label)
    : previous_(std::exchange(current_label, std::move(label))) {}

ScopedRunLabel::~ScopedRunLabel() { current_label = std::move(previous_); }

/// Forwards to the logger's own sinks, a labelled thread's lines at debug level.
class QuietRuns::Sink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  Sink(std::vector<spdlog::sink_ptr> sinks, spdlog::level::level_enum shown)
      : sinks_(std::move(sinks)), shown_(shown) {}

  std::optional<std::string> summary() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (runs_.empty()) return std::nullopt;
    std::vector<std::pair<std::size_t, std::string>> kinds;
    for (const auto& [kind, count] : kinds_) kinds.emplace_back(count, kind);
    std::stable_sort(kinds.begin(), kinds.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string line =
        fmt::format("sweep: {} run{} warned:", runs_.size(), runs_.size() == 1 ? "" : "s");
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      line += fmt::format("{} {} x '{}'", i == 0 ? "" : ",", kinds[i].first, kinds[i].second);
    }
    return line;
  }

 protected:
  void sink_it_(const spdlog::details::log_msg& message) override {
    if (current_label.empty()) {
      for (const auto& sink : sinks_) {
        if (sink->should_log(message.level)) sink->log(message);
      }
      return;
    }
    if (message.level >= spdlog::level::warn) {
      runs_.insert(current_label);
      ++kinds_[kind_of(std::string_view(message.payload.data(), message.payload.size()))];
    }
    if (shown_ > spdlog::level::debug) return;
    spdlog::details::log_msg demoted = message;
    demoted.level = spdlog::level::debug;
    for (const auto& sink : sinks_) {
      if (sink->should_log(demoted.level)) sink->log(demoted);
    }
  }
  void flush_() override {
    for (const auto& sink : sinks_) sink->flush();
  }

 private:
  /// A warning's text up to its first digit (the numbers differ from run to run).
  static std::string kind_of(std::string_view text) {
    const auto digit = std::find_if(text.begin(), text.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    });
    std::string kind(text.begin(), digit);
    while (!kind.empty() && kind.back() == ' ') kind.pop_back();
    if (digit != text.end()) kind += " ...";
    return kind;
  }

  std::vector<spdlog::sink_ptr> sinks_;
  spdlog::level::level_enum shown_;
  std::set<std::string> runs_;
  std::map<std::string, std::size_t> kinds_;
};

QuietRuns::QuietRuns(spdlog::logger& logger)
    : logger_(logger),
      sinks_(logger.sinks()),
      sink_(std::make_shared<Sink>(sinks_, logger.level())) {
  logger_.sinks() = {sink_};
}

QuietRuns::~QuietRuns() { logger_.sinks() = sinks_; }

std::optional<std::string> QuietRuns::summary() const { return sink_->summary(); }

std::unique_ptr<spdlog::formatter> labelled_formatter(const std::string& pattern) {
  auto formatter = std::make_unique<spdlog::pattern_formatter>();
  formatter->add_flag<RunLabelFlag>('*').set_pattern(pattern);
  return formatter;
}

}  // namespace mdrsim::cli

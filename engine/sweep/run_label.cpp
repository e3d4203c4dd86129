// The thread-local run label and its spdlog flag.
#include "engine/sweep/run_label.hpp"

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

std::unique_ptr<spdlog::formatter> labelled_formatter(const std::string& pattern) {
  auto formatter = std::make_unique<spdlog::pattern_formatter>();
  formatter->add_flag<RunLabelFlag>('*').set_pattern(pattern);
  return formatter;
}

}  // namespace mdrsim::cli

// The engine's logs on standard error unless the program has given spdlog a logger of its own.
#include "engine/base/engine_logger.hpp"

#include <spdlog/sinks/ansicolor_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <memory>

namespace mdrsim {
namespace {

/// spdlog's built-in default logger: named "" with one sink on standard output.
bool is_builtin_default(const spdlog::logger& logger) {
  if (!logger.name().empty() || logger.sinks().size() != 1) return false;
  const spdlog::sinks::sink* sink = logger.sinks().front().get();
  return dynamic_cast<const spdlog::sinks::ansicolor_stdout_sink_mt*>(sink) != nullptr ||
         dynamic_cast<const spdlog::sinks::stdout_sink_mt*>(sink) != nullptr;
}

struct EngineLoggers {
  /// spdlog's built-in default logger (or null if a program had replaced it before), held so
  /// that no logger the program sets later can take its address and be mistaken for it.
  std::shared_ptr<spdlog::logger> builtin;
  std::shared_ptr<spdlog::logger> own;
};

EngineLoggers& engine_loggers() {
  static EngineLoggers loggers = [] {
    EngineLoggers l;
    std::shared_ptr<spdlog::logger> current = spdlog::default_logger();
    if (current && is_builtin_default(*current)) l.builtin = std::move(current);
    l.own = std::make_shared<spdlog::logger>(
        "mdrsim", std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
    l.own->set_pattern("[mdrsim %^%l%$] %v");
    return l;
  }();
  return loggers;
}

// Set up before main(), while spdlog's default logger is its built-in one: a program that sets
// its own later and then puts the built-in back gets the engine's logs on standard error again.
[[maybe_unused]] const EngineLoggers& kSetUpAtStart = engine_loggers();

}  // namespace

spdlog::logger& engine_logger() {
  EngineLoggers& loggers = engine_loggers();
  spdlog::logger* current = spdlog::default_logger_raw();
  if (current != nullptr && current != loggers.builtin.get()) return *current;
  if (loggers.builtin && loggers.own->level() != loggers.builtin->level()) {
    loggers.own->set_level(loggers.builtin->level());
  }
  return *loggers.own;
}

}  // namespace mdrsim

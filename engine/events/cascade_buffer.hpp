// Holds a cascade's rows back until the cascade ends: one that ends in a flight is not shown.
#pragma once

#include <cstddef>
#include <cstdio>
#include <memory>
#include <type_traits>
#include <vector>

#include "engine/events/observer.hpp"

namespace mdrsim {

/// Holds every event for `inner` until flush() (the cascade, or the step, ended in an
/// equilibrium) or discard_flight() (it ended with the indenter flying off under a fixed load,
/// docs/programs.md "A fixed load that loses the contact": no rows beyond the critical point).
/// Memory is bounded: past `in_memory` events the rest wait in an anonymous temporary file
/// (a fixed-load pull-off of 1e7 springs holds 5e6 let-gos, 1 GB in memory).
class CascadeBuffer final : public Observer {
 public:
  static constexpr std::size_t kInMemory = std::size_t{1} << 15;  ///< events (about 4 MB)

  explicit CascadeBuffer(const ObserverList& inner, std::size_t in_memory = kInMemory)
      : inner_(&inner), in_memory_(in_memory) {}

  void on_event(const Event& event) override;
  bool wants(EventKind kind) const override { return inner_->wants(kind); }

  std::size_t held() const { return held_.size() + spilled_; }
  /// Passes on the first `count` held events (those before a new equilibrium).
  void flush(std::size_t count);
  void flush() { flush(held()); }
  /// Drops the held rows but those at the critical state: a halved step's (taken back to
  /// it) and, with `keep_first_let_go`, the let-go that starts the cascade (the event
  /// method's is at the critical state; a stepping step's detachments are all past it).
  void discard_flight(bool keep_first_let_go);

 private:
  struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  using File = std::unique_ptr<std::FILE, FileCloser>;
  // Spilled as bytes and read back within the same run: the stage names the events point to
  // outlive it.
  static_assert(std::is_trivially_copyable_v<Event>);

  /// Calls `pass` on every held event in order and leaves the buffer empty.
  template <class Pass>
  void drain(Pass&& pass);

  const ObserverList* inner_;
  std::size_t in_memory_;
  std::vector<Event> held_;
  File file_;  ///< the events past in_memory_, in order
  std::size_t spilled_ = 0;
};

}  // namespace mdrsim

// Holds a cascade's rows back until the cascade ends, in memory and then in a temporary file.
#include "engine/events/cascade_buffer.hpp"

#include <stdexcept>
#include <utility>

namespace mdrsim {

void CascadeBuffer::on_event(const Event& event) {
  if (spilled_ == 0 && held_.size() < in_memory_) {
    held_.push_back(event);
    return;
  }
  if (!file_) {
    file_.reset(std::tmpfile());
    if (!file_) throw std::runtime_error("cannot open a temporary file for a cascade's rows");
  }
  if (std::fwrite(&event, sizeof(Event), 1, file_.get()) != 1) {
    throw std::runtime_error("cannot write a cascade's rows to a temporary file");
  }
  ++spilled_;
}

template <class Pass>
void CascadeBuffer::drain(Pass&& pass) {
  std::vector<Event> held = std::move(held_);
  held_.clear();
  File file = std::move(file_);
  const std::size_t spilled = std::exchange(spilled_, 0);
  for (const Event& e : held) pass(e);
  if (!file) return;
  std::rewind(file.get());
  Event e{};
  for (std::size_t i = 0; i < spilled; ++i) {
    if (std::fread(&e, sizeof(Event), 1, file.get()) != 1) {
      throw std::runtime_error("cannot read a cascade's rows back from a temporary file");
    }
    pass(e);
  }
}

void CascadeBuffer::flush(std::size_t count) {
  std::size_t n = 0;
  // The events past `count` are held again, in order (on_event refills memory, then a file).
  drain([&](const Event& e) {
    if (n++ < count) {
      inner_->emit(e);
    } else {
      on_event(e);
    }
  });
}

void CascadeBuffer::discard_flight(bool keep_first_let_go) {
  drain([&](const Event& e) {
    const bool first = e.kind == EventKind::spring_detached && !e.in_cascade;
    if (e.kind == EventKind::step_halved || (keep_first_let_go && first)) inner_->emit(e);
  });
}

}  // namespace mdrsim

// fmt formatters for events and snapshots, used by the logger and by test failure messages.
#pragma once

#include <fmt/format.h>

#include "engine/events/event.hpp"

template <>
struct fmt::formatter<mdrsim::ContactSnapshot> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(const mdrsim::ContactSnapshot& s, Context& ctx) const {
    return fmt::format_to(ctx.out(),
                          "d={:.6g} m F={:.6g} N a={:.6g} m ux={:.6g} m Fx={:.6g} N n={}",
                          s.indentation, s.normal_force, s.contact_radius,
                          s.tangential_displacement, s.tangential_force, s.springs_in_contact);
  }
};

template <>
struct fmt::formatter<mdrsim::Event> : fmt::formatter<std::string_view> {
  template <class Context>
  auto format(const mdrsim::Event& e, Context& ctx) const {
    using mdrsim::EventKind;
    switch (e.kind) {
      case EventKind::spring_detached:
        return fmt::format_to(ctx.out(), "spring {} detached{}: {}", e.spring,
                              e.in_cascade ? " (cascade)" : "", e.state);
      case EventKind::step_accepted:
      case EventKind::step_halved:
        return fmt::format_to(ctx.out(), "{} (step {:.6g}): {}", mdrsim::to_string(e.kind), e.step,
                              e.state);
      case EventKind::instability:
      case EventKind::finished:
        return fmt::format_to(ctx.out(), "{} ({}): {}", mdrsim::to_string(e.kind),
                              mdrsim::to_string(e.status), e.state);
      default:
        return fmt::format_to(ctx.out(), "{}: {}", mdrsim::to_string(e.kind), e.state);
    }
  }
};

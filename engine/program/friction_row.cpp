// The springs in contact under friction: tangential force, slip events, frictional work.
#include "engine/program/friction_row.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mdrsim {

FrictionRow::FrictionRow(const Material& material, const FrictionSettings& settings, double spacing)
    : settings_(settings),
      normal_stiffness_(material.effective_modulus * spacing),
      tangential_stiffness_(material.effective_shear_modulus * spacing),
      ratio_(settings.coefficient * material.effective_modulus / material.effective_shear_modulus),
      spacing_(spacing),
      individual_(settings.law != nullptr) {}

void FrictionRow::reserve(std::int64_t springs) {
  if (springs <= 0) return;
  springs_.reserve(static_cast<std::size_t>(springs));
  if (individual_) {
    laws_.reserve(static_cast<std::size_t>(springs));
  } else {
    keys_.reserve(springs);
  }
}

SpringGeometry FrictionRow::geometry(std::int64_t i) const {
  return {normal_stiffness_, tangential_stiffness_, springs_[index(i)].image};
}

std::optional<SlipLimit> FrictionRow::law(std::int64_t i) const {
  if (i > glued_) return individual_ ? laws_[index(i)] : SlipLimit{settings_.coefficient, 0.0};
  if (settings_.glued == GluedShear::unlimited) return std::nullopt;
  return SlipLimit{settings_.coefficient, glued_adhesive_limit(i)};
}

double FrictionRow::glued_adhesive_limit(std::int64_t i) const {
  // 2 tau_0 sqrt(a_g^2 - x_i^2) dx with a_g = x_k, x_i = i dx: in whole spacings, exactly.
  const double k = static_cast<double>(glued_);
  const double x = static_cast<double>(i);
  return 2.0 * settings_.shear_strength * spacing_ * spacing_ *
         std::sqrt(std::max(k * k - x * x, 0.0));
}

double FrictionRow::glued_stretch(std::int64_t i, double indentation, double tangential) const {
  const StickSlipSpring& state = springs_[index(i)].state;
  if (state.sliding == 0) return tangential - state.offset;
  return state.sliding * slip_limit(*law(i), geometry(i), indentation) / tangential_stiffness_;
}

double FrictionRow::limit_glued_springs() {
  if (settings_.glued != GluedShear::limited || settings_.shear_strength == 0.0) return 0.0;
  double dissipated = 0.0;
  for (std::int64_t i = 1; i <= glued_; ++i) {
    StickSlipSpring& state = springs_[index(i)].state;
    // Every glued spring leaves its set and joins the one it ends in, so that the sticking
    // offsets lose the offset they hold, before the slip moves it.
    if (state.sliding != 0) {
      remove_sliding(i);
    } else {
      remove_sticking(i);
    }
    // Within its new limit a spring sticks where it is (a slide goes on only at the limit);
    // over it, it slips to the limit at once.
    state.sliding = 0;
    dissipated += slip_to_limit(state, *law(i), geometry(i), indentation_, tangential_);
    if (state.sliding != 0) {
      add_sliding(i);
    } else {
      add_sticking(i);
    }
  }
  return 2.0 * dissipated;
}

StickSlipSpring FrictionRow::spring(std::int64_t i) const {
  StickSlipSpring state = springs_[index(i)].state;
  if (keyed(i) && state.sliding != 0)
    state.offset = tangential_ - state.sliding * ratio_ * (indentation_ - springs_[index(i)].image);
  return state;
}

double FrictionRow::limit_sum(std::size_t s, double indentation) const {
  const auto count = static_cast<double>(sliders_[s].size());
  return settings_.coefficient * normal_stiffness_ *
         (count * indentation - slider_images_[s].value());
}

void FrictionRow::add_sticking(std::int64_t i, int stuck_from) {
  const Spring& s = springs_[index(i)];
  ++sticking_;
  sticking_offsets_.add(s.state.offset);
  if (!keyed(i)) return;
  double forward = s.state.offset - ratio_ * s.image;
  double backward = s.state.offset + ratio_ * s.image;
  // A slider sticks where its p reverses: that p is its key on the side it slid to, the same
  // bits for every slider that sticks with it (o -+ r g would scatter them by rounding, and the
  // runs of neighbours SlipKeys keeps would break into pieces), the same value to rounding.
  if (stuck_from > 0) forward = tangential_ - ratio_ * indentation_;
  if (stuck_from < 0) backward = tangential_ + ratio_ * indentation_;
  keys_.insert(i, forward, backward);
}

void FrictionRow::remove_sticking(std::int64_t i) {
  const Spring& s = springs_[index(i)];
  --sticking_;
  sticking_offsets_.add(-s.state.offset);
  if (keyed(i)) keys_.erase(i);
}

void FrictionRow::add_sliding(std::int64_t i) {
  if (!keyed(i)) {
    ++own_sliding_;
    return;
  }
  const Spring& s = springs_[index(i)];
  sliders_[side(s.state.sliding)].insert(i);
  slider_images_[side(s.state.sliding)].add(s.image);
}

void FrictionRow::remove_sliding(std::int64_t i) {
  if (!keyed(i)) {
    --own_sliding_;
    return;
  }
  const Spring& s = springs_[index(i)];
  sliders_[side(s.state.sliding)].erase(i);
  slider_images_[side(s.state.sliding)].add(-s.image);
}

std::int64_t FrictionRow::first_own_sliding() const {
  if (own_sliding_ == 0) return 0;
  for (std::int64_t i = 1; i <= own_springs(); ++i)
    if (springs_[index(i)].state.sliding != 0) return i;
  return 0;
}

void FrictionRow::touch(double image, double tangential) {
  springs_.push_back({StickSlipSpring{tangential, 0}, image});
  if (individual_) {
    laws_.push_back(settings_.law->limit_at(position(in_contact()), spacing_));
  }
  add_sticking(in_contact());
}

void FrictionRow::lift_outer() {
  const std::int64_t i = in_contact();
  if (i <= glued_) throw std::logic_error("FrictionRow::lift_outer: spring m is glued");
  if (springs_[index(i)].state.sliding != 0) {
    remove_sliding(i);
  } else {
    remove_sticking(i);
  }
  springs_.pop_back();
  if (individual_) laws_.pop_back();
}

void FrictionRow::glue_next() {
  if (glued_ >= in_contact()) throw std::logic_error("FrictionRow::glue_next: no spring k+1");
  // A sliding spring glues only once it sticks (docs/friction.md).
  const std::int64_t i = glued_ + 1;
  if (springs_[index(i)].state.sliding != 0)
    throw std::logic_error("FrictionRow::glue_next: spring k+1 slides");
  remove_sticking(i);
  ++glued_;
  add_sticking(i);
  // Every glued spring's adhesive limit grows with a_g: nothing slips, sliders stick.
  if (own_sliding_ > 0) limit_glued_springs();
}

double FrictionRow::let_go_boundary(double indentation, double tangential) {
  if (glued_ == 0) throw std::logic_error("FrictionRow::let_go_boundary: nothing glued");
  indentation_ = indentation;
  tangential_ = tangential;
  const std::int64_t i = glued_;
  Spring& s = springs_[index(i)];
  // A glued spring sliding at its glued limit (GluedShear::limited) sticks for the moment: its
  // offset is up to date (the glued springs are advanced spring by spring).
  if (s.state.sliding != 0) {
    remove_sliding(i);
    s.state.sliding = 0;
  } else {
    remove_sticking(i);
  }
  --glued_;
  const double dissipated = slip_to_limit(s.state, *law(i), geometry(i), indentation, tangential);
  if (s.state.sliding != 0) {
    add_sliding(i);
  } else {
    add_sticking(i);
  }
  // The glued springs' adhesive limits fall with a_g: those over theirs slip at once.
  return 2.0 * dissipated + limit_glued_springs();
}

double FrictionRow::tangential_force(double indentation, double tangential) const {
  double sum = tangential_stiffness_ *
               (static_cast<double>(sticking_) * tangential - sticking_offsets_.value());
  sum += limit_sum(0, indentation) - limit_sum(1, indentation);
  if (own_sliding_ > 0) {
    for (std::int64_t i = 1; i <= own_springs(); ++i) {
      const StickSlipSpring& state = springs_[index(i)].state;
      if (state.sliding != 0)
        sum += spring_tangential_force(state, *law(i), geometry(i), indentation, tangential);
    }
  }
  return 2.0 * sum;
}

double FrictionRow::tangential_stiffness() const {
  return 2.0 * tangential_stiffness_ * static_cast<double>(sticking_);
}

double FrictionRow::tangential_force_per_indentation(double indentation) const {
  const double per_spring = settings_.coefficient * normal_stiffness_;
  double slope = per_spring * static_cast<double>(sliders_[0].size() - sliders_[1].size());
  if (own_sliding_ > 0) {
    for (std::int64_t i = 1; i <= own_springs(); ++i) {
      const Spring& s = springs_[index(i)];
      if (s.state.sliding != 0 && indentation > s.image)
        slope += s.state.sliding * law(i)->coefficient * normal_stiffness_;
    }
  }
  return 2.0 * slope;
}

double FrictionRow::sliding_stick_radius() const {
  std::int64_t first = first_own_sliding();
  for (const auto& side : sliders_)
    if (!side.empty() && (first == 0 || side.first() < first)) first = side.first();
  return first == 0 ? position(in_contact()) : position(first - 1);
}

std::optional<RowFrictionEvent> FrictionRow::next_event(const LinearMotion& motion,
                                                        double end) const {
  std::optional<RowFrictionEvent> first;
  const auto consider = [&](std::int64_t i, const FrictionEvent& event) {
    if (event.at > end) return;
    if (!first || event.at < first->event.at || (event.at == first->event.at && i < first->spring))
      first = RowFrictionEvent{i, event};
  };
  for (std::int64_t i = 1; i <= own_springs(); ++i) {
    const auto l = law(i);
    if (!l) continue;  // a glued `unlimited` spring under a law of its own never slips
    const auto event = next_friction_event(springs_[index(i)].state, *l, geometry(i), motion, end);
    if (event) consider(i, *event);
  }
  const double t0 = motion.start;
  const double forward_rate = motion.tangential_rate - ratio_ * motion.indentation_rate;
  const double backward_rate = motion.tangential_rate + ratio_ * motion.indentation_rate;
  // Sliders stick at once where their common slip velocity reverses.
  if (!sliders_[0].empty() && forward_rate < 0.0)
    consider(sliders_[0].first(), {FrictionEventKind::stick, t0, 1});
  if (!sliders_[1].empty() && backward_rate > 0.0)
    consider(sliders_[1].first(), {FrictionEventKind::stick, t0, -1});
  // A sticking spring slips where p+ rises to its key (p- falls to it); on its limit already
  // (rounding, or a spring just stuck) it slips at once if the motion goes that way.
  if (!keys_.empty() && forward_rate > 0.0) {
    const SlipKey key = keys_.forward_first();
    const double p = motion.tangential - ratio_ * motion.indentation;
    consider(key.spring,
             {FrictionEventKind::slip, t0 + std::max(key.value - p, 0.0) / forward_rate, 1});
  }
  if (!keys_.empty() && backward_rate < 0.0) {
    const SlipKey key = keys_.backward_last();
    const double p = motion.tangential + ratio_ * motion.indentation;
    consider(key.spring,
             {FrictionEventKind::slip, t0 + std::max(p - key.value, 0.0) / (-backward_rate), -1});
  }
  return first;
}

double FrictionRow::advance_sliding(const LinearMotion& motion, double t) {
  double dissipated = 0.0;
  if (own_sliding_ > 0) {
    for (std::int64_t i = 1; i <= own_springs(); ++i) {
      Spring& s = springs_[index(i)];
      if (s.state.sliding != 0)
        dissipated += advance_spring(s.state, *law(i), geometry(i), motion, t);
    }
  }
  if (t > motion.start) {
    const double d1 = motion.indentation_at(t);
    const double span = t - motion.start;
    // Each slider of a side slips by the same |p(t) - p(t0)|; its limit is linear in t.
    for (std::size_t s = 0; s < 2; ++s) {
      if (sliders_[s].empty()) continue;
      const double direction = s == 0 ? 1.0 : -1.0;
      const double slip =
          std::abs((motion.tangential_rate - direction * ratio_ * motion.indentation_rate) * span);
      dissipated += slip * 0.5 * (limit_sum(s, motion.indentation) + limit_sum(s, d1));
    }
  }
  indentation_ = motion.indentation_at(t);
  tangential_ = motion.tangential_at(t);
  return 2.0 * dissipated;
}

void FrictionRow::apply(const RowFrictionEvent& event) {
  const std::int64_t i = event.spring;
  Spring& s = springs_[index(i)];
  const FrictionEventKind kind = event.event.kind;
  if (kind == FrictionEventKind::limit_kink) return;
  if (!keyed(i)) {
    if (kind == FrictionEventKind::slip && s.state.sliding == 0) {
      remove_sticking(i);
      add_sliding(i);
    } else if (kind == FrictionEventKind::stick && s.state.sliding != 0) {
      remove_sliding(i);
      apply_friction_event(s.state, event.event);
      add_sticking(i);
      return;
    }
    apply_friction_event(s.state, event.event);
    return;
  }
  if (kind == FrictionEventKind::slip && s.state.sliding == 0) {
    remove_sticking(i);
    s.state.sliding = event.event.direction;
    add_sliding(i);
  } else if (kind == FrictionEventKind::stick && s.state.sliding != 0) {
    remove_sliding(i);
    s.state.offset = spring(i).offset;
    const int direction = s.state.sliding;
    s.state.sliding = 0;
    add_sticking(i, direction);
  }
}

}  // namespace mdrsim

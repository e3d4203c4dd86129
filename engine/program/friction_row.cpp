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
      glued_keyed_(settings.glued == GluedShear::limited && settings.law == nullptr),
      individual_(settings.law != nullptr) {}

void FrictionRow::reserve(std::int64_t springs) {
  if (springs <= 0) return;
  springs_.reserve(static_cast<std::size_t>(springs));
  if (individual_) {
    laws_.reserve(static_cast<std::size_t>(springs));
  } else {
    keys_.reserve(springs);
  }
  if (glued_keyed_) {
    tension_keys_.reserve(springs);
    glued_images_.reserve(springs);
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
    dissipated += settle_at_limit(i);
  }
  return 2.0 * dissipated;
}

double FrictionRow::settle_at_limit(std::int64_t i) {
  // Within its new limit a spring sticks where it is (a slide goes on only at the limit);
  // over it, it slips to the limit at once.
  StickSlipSpring& state = springs_[index(i)].state;
  state.sliding = 0;
  const double dissipated = slip_to_limit(state, *law(i), geometry(i), indentation_, tangential_);
  if (state.sliding != 0) {
    add_sliding(i);
  } else {
    add_sticking(i);
  }
  return dissipated;
}

void FrictionRow::detach_glued(std::int64_t n) {
  for (std::int64_t i = 1; i <= n; ++i) {
    Spring& s = springs_[index(i)];
    if (s.state.sliding != 0) {
      s.state.offset = spring(i).offset;
      remove_sliding(i);
    } else {
      remove_sticking(i);
    }
  }
  // Only glued sliders add to these: what is left is rounding.
  if (glued_keyed_) {
    slider_adhesion_ = tension_limits_ = {};
    energy_.slider_adhesion_images = energy_.slider_adhesion_squares =
        energy_.tension_limit_squares = {};
  }
}

double FrictionRow::attach_glued(std::int64_t n, bool relimit_sticking) {
  double dissipated = 0.0;
  for (std::int64_t i = 1; i <= n; ++i) {
    StickSlipSpring& state = springs_[index(i)].state;
    if (state.sliding == 0 && !relimit_sticking) {
      add_sticking(i);
      continue;
    }
    dissipated += settle_at_limit(i);
  }
  return 2.0 * dissipated;
}

void FrictionRow::classify(std::int64_t i, bool tension) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double g = springs_[index(i)].image;
  glued_images_.erase(i);
  glued_images_.insert(i, tension ? g : kInf, tension ? -kInf : g);
}

void FrictionRow::change_class(std::int64_t i) {
  const Spring& s = springs_[index(i)];
  const bool tension = !in_tension(i);
  if (s.state.sliding != 0) {
    remove_sliding(i);
    classify(i, tension);
    add_sliding(i);
    return;
  }
  // A sticking spring keeps its offset: only its keys move.
  keys_.erase(i);
  tension_keys_.erase(i);
  classify(i, tension);
  insert_keys(i, 0);
}

bool FrictionRow::classes_hold(double indentation) const {
  // A sticking spring's force does not depend on its class: only sliders' classes count.
  if (glued_sliding_ == 0) return true;
  return glued_images_.backward_last().value <= indentation &&
         glued_images_.forward_first().value >= indentation;
}

double FrictionRow::misclassed_force(double indentation) const {
  double sum = 0.0;
  for (std::int64_t i = 1; i <= glued_; ++i) {
    const Spring& s = springs_[index(i)];
    if (s.state.sliding == 0) continue;
    const double c = glued_adhesive_limit(i);
    const double keyed_limit =
        in_tension(i) ? c : settings_.coefficient * normal_stiffness_ * (indentation - s.image) + c;
    sum += s.state.sliding * (slip_limit(*law(i), geometry(i), indentation) - keyed_limit);
  }
  return sum;
}

double FrictionRow::misclassed_slope(double indentation) const {
  double slope = 0.0;
  for (std::int64_t i = 1; i <= glued_; ++i) {
    const Spring& s = springs_[index(i)];
    if (s.state.sliding == 0) continue;
    const double exact = indentation > s.image ? 1.0 : 0.0;
    const double keyed_slope = in_tension(i) ? 0.0 : 1.0;
    slope += s.state.sliding * (exact - keyed_slope) * settings_.coefficient * normal_stiffness_;
  }
  return slope;
}

StickSlipSpring FrictionRow::spring(std::int64_t i) const {
  StickSlipSpring state = springs_[index(i)].state;
  if (!keyed(i) || state.sliding == 0) return state;
  if (keyed_glued(i)) {
    state.offset = tangential_ - state.sliding * slip_limit(*law(i), geometry(i), indentation_) /
                                     tangential_stiffness_;
  } else {
    state.offset = tangential_ - state.sliding * ratio_ * (indentation_ - springs_[index(i)].image);
  }
  return state;
}

double FrictionRow::limit_sum(std::size_t s, double indentation) const {
  const auto count = static_cast<double>(sliders_[s].size());
  const double coulomb =
      settings_.coefficient * normal_stiffness_ * (count * indentation - slider_images_[s].value());
  return glued_keys_move() ? coulomb + slider_adhesion_[s].value() : coulomb;
}

void FrictionRow::add_sticking(std::int64_t i, int stuck_from) {
  ++sticking_;
  const double offset = springs_[index(i)].state.offset;
  sticking_offsets_.add(offset);
  energy_.sticking_offset_squares.add(offset * offset);
  if (keyed(i)) insert_keys(i, stuck_from);
}

void FrictionRow::insert_keys(std::int64_t i, int stuck_from) {
  const Spring& s = springs_[index(i)];
  if (keyed_glued(i) && in_tension(i)) {
    const double reach = glued_adhesive_limit(i) / tangential_stiffness_;
    tension_keys_.insert(i, stuck_from > 0 ? tangential_ : s.state.offset + reach,
                         stuck_from < 0 ? tangential_ : s.state.offset - reach);
    return;
  }
  double forward = s.state.offset - ratio_ * s.image;
  double backward = s.state.offset + ratio_ * s.image;
  if (keyed_glued(i) && glued_keys_move()) {
    const double reach = glued_adhesive_limit(i) / tangential_stiffness_;
    forward += reach;
    backward -= reach;
  }
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
  energy_.sticking_offset_squares.add(-s.state.offset * s.state.offset);
  if (!keyed(i)) return;
  keys_.erase(i);
  if (keyed_glued(i)) tension_keys_.erase(i);
}

void FrictionRow::add_sliding(std::int64_t i) {
  if (!keyed(i)) {
    ++own_sliding_;
    return;
  }
  const Spring& s = springs_[index(i)];
  const std::size_t at = side(s.state.sliding);
  if (keyed_glued(i)) {
    ++glued_sliding_;
    const double c = glued_keys_move() ? glued_adhesive_limit(i) : 0.0;
    if (in_tension(i)) {
      tension_sliders_[at].insert(i);
      if (c != 0.0) {
        tension_limits_[at].add(c);
        energy_.tension_limit_squares[at].add(c * c);
      }
      return;
    }
    if (c != 0.0) {
      slider_adhesion_[at].add(c);
      energy_.slider_adhesion_images[at].add(c * s.image);
      energy_.slider_adhesion_squares[at].add(c * c);
    }
  }
  sliders_[at].insert(i);
  slider_images_[at].add(s.image);
  energy_.slider_image_squares[at].add(s.image * s.image);
}

void FrictionRow::remove_sliding(std::int64_t i) {
  if (!keyed(i)) {
    --own_sliding_;
    return;
  }
  const Spring& s = springs_[index(i)];
  const std::size_t at = side(s.state.sliding);
  if (keyed_glued(i)) {
    --glued_sliding_;
    const double c = glued_keys_move() ? glued_adhesive_limit(i) : 0.0;
    if (in_tension(i)) {
      tension_sliders_[at].erase(i);
      if (c != 0.0) {
        tension_limits_[at].add(-c);
        energy_.tension_limit_squares[at].add(-c * c);
      }
      return;
    }
    if (c != 0.0) {
      slider_adhesion_[at].add(-c);
      energy_.slider_adhesion_images[at].add(-c * s.image);
      energy_.slider_adhesion_squares[at].add(-c * c);
    }
  }
  sliders_[at].erase(i);
  slider_images_[at].add(-s.image);
  energy_.slider_image_squares[at].add(-s.image * s.image);
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

void FrictionRow::glue_next(double indentation) {
  if (glued_ >= in_contact()) throw std::logic_error("FrictionRow::glue_next: no spring k+1");
  // A sliding spring glues only once it sticks (docs/friction.md).
  const std::int64_t i = glued_ + 1;
  if (springs_[index(i)].state.sliding != 0)
    throw std::logic_error("FrictionRow::glue_next: spring k+1 slides");
  // Every glued spring's adhesive limit grows with a_g: nothing slips, sliders stick, and the
  // keys of the keyed ones move.
  const std::int64_t before = glued_;
  if (glued_keys_move()) detach_glued(before);
  remove_sticking(i);
  ++glued_;
  if (keyed_glued(i)) classify(i, !(indentation > springs_[index(i)].image));
  add_sticking(i);
  if (glued_keys_move()) {
    attach_glued(before, false);
  } else if (own_sliding_ > 0) {
    limit_glued_springs();
  }
}

double FrictionRow::let_go_boundary(double indentation, double tangential) {
  if (glued_ == 0) throw std::logic_error("FrictionRow::let_go_boundary: nothing glued");
  indentation_ = indentation;
  tangential_ = tangential;
  const std::int64_t i = glued_;
  Spring& s = springs_[index(i)];
  // A glued spring sliding at its glued limit (GluedShear::limited) sticks for the moment, at
  // its offset of now. With tau_0 > 0 every glued spring's limit falls with a_g: all leave
  // their sets before it changes.
  if (glued_keys_move()) {
    detach_glued(glued_);
  } else if (s.state.sliding != 0) {
    s.state.offset = spring(i).offset;
    remove_sliding(i);
  } else {
    remove_sticking(i);
  }
  s.state.sliding = 0;
  if (keyed_glued(i)) glued_images_.erase(i);
  --glued_;
  const double dissipated = slip_to_limit(s.state, *law(i), geometry(i), indentation, tangential);
  if (s.state.sliding != 0) {
    add_sliding(i);
  } else {
    add_sticking(i);
  }
  // The glued springs' adhesive limits fall with a_g: those over theirs slip at once.
  if (glued_keys_move()) return 2.0 * dissipated + attach_glued(glued_, true);
  return 2.0 * dissipated + limit_glued_springs();
}

double FrictionRow::tangential_force(double indentation, double tangential) const {
  double sum = tangential_stiffness_ *
               (static_cast<double>(sticking_) * tangential - sticking_offsets_.value());
  sum += limit_sum(0, indentation) - limit_sum(1, indentation);
  if (glued_keyed_) {
    if (glued_keys_move()) sum += tension_limits_[0].value() - tension_limits_[1].value();
    if (!classes_hold(indentation)) sum += misclassed_force(indentation);
  }
  if (own_sliding_ > 0) {
    for (std::int64_t i = 1; i <= own_springs(); ++i) {
      const StickSlipSpring& state = springs_[index(i)].state;
      if (state.sliding != 0)
        sum += spring_tangential_force(state, *law(i), geometry(i), indentation, tangential);
    }
  }
  return 2.0 * sum;
}

double FrictionRow::stored_energy(double indentation, double tangential) const {
  const double u = tangential;
  const double d = indentation;
  const double n = static_cast<double>(sticking_);
  // Each term is f_x^2 / kx, both halves of f_x^2 / (2 kx). A sticking spring's sum (u - o)^2
  // = n u^2 - 2 u sum o + sum o^2: the sums the force already keeps, and one more.
  double twice = tangential_stiffness_ * (n * u * u - 2.0 * u * sticking_offsets_.value() +
                                          energy_.sticking_offset_squares.value());
  // A keyed pressed slider is at its limit mu kz (d - g_i) + c_i (c_i of a glued one only).
  const double per_slider = settings_.coefficient * normal_stiffness_;
  for (std::size_t s = 0; s < 2; ++s) {
    if (sliders_[s].empty()) continue;
    const auto count = static_cast<double>(sliders_[s].size());
    twice += per_slider * per_slider *
             (count * d * d - 2.0 * d * slider_images_[s].value() +
              energy_.slider_image_squares[s].value()) /
             tangential_stiffness_;
  }
  if (glued_keys_move()) {
    for (std::size_t s = 0; s < 2; ++s) {
      // 2 mu kz (d - g_i) c_i + c_i^2 of the pressed glued sliders; c_i^2 in tension.
      twice +=
          (2.0 * per_slider *
               (d * slider_adhesion_[s].value() - energy_.slider_adhesion_images[s].value()) +
           energy_.slider_adhesion_squares[s].value() + energy_.tension_limit_squares[s].value()) /
          tangential_stiffness_;
    }
  }
  if (glued_keyed_ && !classes_hold(d)) twice += misclassed_energy(d);
  if (own_sliding_ > 0) {
    for (std::int64_t i = 1; i <= own_springs(); ++i) {
      const StickSlipSpring& state = springs_[index(i)].state;
      if (state.sliding == 0) continue;
      const double f = spring_tangential_force(state, *law(i), geometry(i), d, u);
      twice += f * f / tangential_stiffness_;
    }
  }
  return twice;
}

double FrictionRow::misclassed_energy(double indentation) const {
  double sum = 0.0;
  for (std::int64_t i = 1; i <= glued_; ++i) {
    const Spring& s = springs_[index(i)];
    if (s.state.sliding == 0) continue;
    const double c = glued_keys_move() ? glued_adhesive_limit(i) : 0.0;
    const double keyed_limit =
        in_tension(i) ? c : settings_.coefficient * normal_stiffness_ * (indentation - s.image) + c;
    const double exact = slip_limit(*law(i), geometry(i), indentation);
    sum += (exact * exact - keyed_limit * keyed_limit) / tangential_stiffness_;
  }
  return sum;
}

double FrictionRow::tangential_stiffness() const {
  return 2.0 * tangential_stiffness_ * static_cast<double>(sticking_);
}

double FrictionRow::tangential_force_per_indentation(double indentation) const {
  const double per_spring = settings_.coefficient * normal_stiffness_;
  double slope = per_spring * static_cast<double>(sliders_[0].size() - sliders_[1].size());
  if (glued_keyed_ && !classes_hold(indentation)) slope += misclassed_slope(indentation);
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
  for (const auto* sets : {&sliders_, &tension_sliders_})
    for (const auto& side : *sets)
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
  if (glued_keyed_) glued_events(motion, end, first);
  return first;
}

void FrictionRow::glued_events(const LinearMotion& motion, double end,
                               std::optional<RowFrictionEvent>& first) const {
  const double t0 = motion.start;
  const double rate = motion.tangential_rate;
  const auto consider = [&](std::int64_t i, const FrictionEvent& event) {
    if (event.at > end) return;
    if (!first || event.at < first->event.at || (event.at == first->event.at && i < first->spring))
      first = RowFrictionEvent{i, event};
  };
  // In tension the limit is c_i alone: the slip velocity is u_x' and the slip where u_x
  // reaches o +- c/kx.
  if (!tension_sliders_[0].empty() && rate < 0.0)
    consider(tension_sliders_[0].first(), {FrictionEventKind::stick, t0, 1});
  if (!tension_sliders_[1].empty() && rate > 0.0)
    consider(tension_sliders_[1].first(), {FrictionEventKind::stick, t0, -1});
  if (!tension_keys_.empty() && rate > 0.0) {
    const SlipKey key = tension_keys_.forward_first();
    consider(key.spring, {FrictionEventKind::slip,
                          t0 + std::max(key.value - motion.tangential, 0.0) / rate, 1});
  }
  if (!tension_keys_.empty() && rate < 0.0) {
    const SlipKey key = tension_keys_.backward_last();
    consider(key.spring, {FrictionEventKind::slip,
                          t0 + std::max(motion.tangential - key.value, 0.0) / (-rate), -1});
  }
  if (glued_images_.empty()) return;
  // A class change goes before any slip or stick at its t: they are found in the new class.
  const double d = motion.indentation;
  const double vd = motion.indentation_rate;
  std::optional<RowFrictionEvent> crossing;
  const auto cross = [&](std::int64_t i, double at) {
    if (at <= end && (!crossing || at < crossing->event.at))
      crossing = RowFrictionEvent{
          i, {FrictionEventKind::limit_kink, at, springs_[index(i)].state.sliding}};
  };
  // A spring on the wrong side of d changes class at once, unless d's motion brings it back
  // within the rounding of t (it is at its crossing: changing it there would go back and
  // forth at one t).
  const SlipKey deepest = glued_images_.backward_last();  // pressed, of the largest image
  if (std::isfinite(deepest.value)) {
    if (vd < 0.0) {
      cross(deepest.spring, t0 + std::max(d - deepest.value, 0.0) / (-vd));
    } else if (deepest.value > d && !(vd > 0.0 && t0 + (deepest.value - d) / vd == t0)) {
      cross(deepest.spring, t0);
    }
  }
  const SlipKey shallowest = glued_images_.forward_first();  // in tension, of the smallest
  if (std::isfinite(shallowest.value)) {
    if (vd > 0.0) {
      cross(shallowest.spring, t0 + std::max(shallowest.value - d, 0.0) / vd);
    } else if (shallowest.value < d && !(vd < 0.0 && t0 + (d - shallowest.value) / (-vd) == t0)) {
      cross(shallowest.spring, t0);
    }
  }
  if (crossing && (!first || crossing->event.at <= first->event.at)) first = crossing;
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
    // Glued springs in tension slide at their constant c_i by |u_x(t) - u_x(t0)| each.
    if (glued_keys_move()) {
      const double slip = std::abs(motion.tangential_rate * span);
      dissipated += slip * (tension_limits_[0].value() + tension_limits_[1].value());
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
  if (kind == FrictionEventKind::limit_kink) {
    if (keyed_glued(i)) change_class(i);
    return;
  }
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

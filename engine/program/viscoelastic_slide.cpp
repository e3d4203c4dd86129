// A sliding viscoelastic spring's response at its slip limit, in closed form.
#include "engine/program/viscoelastic_slide.hpp"

#include <cmath>

#include "engine/model/prony_load_drive.hpp"

namespace mdrsim {
namespace {

/// f'(s) of an exponential sum.
ExponentialSum slide_slope_of(const ExponentialSum& f) {
  ExponentialSum slope{f.slope, 0.0, {}};
  for (const ExponentialDecay& d : f.decays) {
    slope.decays.push_back({-d.amplitude / d.time, d.time});
  }
  return slope;
}

}  // namespace

ViscoelasticSlide::ViscoelasticSlide(const RetardationModes& modes,
                                     std::span<const double> stresses,
                                     const ExponentialSum& normal_load, double coefficient,
                                     std::int8_t direction, double tangential_rate, double since)
    : direction_(direction), rate_(tangential_rate), since_(since) {
  const double scale = coefficient * direction;
  load_ = {scale * normal_load.constant, scale * normal_load.slope, {}};
  for (const ExponentialDecay& d : normal_load.decays) {
    load_.decays.push_back({scale * d.amplitude, d.time});
  }
  response_ = response_to_load(modes, stresses, load_);
}

FewValues<double> ViscoelasticSlide::stresses(double t) const {
  FewValues<double> out(response_.stresses.size());
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = response_.stresses[j].at(t - since_);
  return out;
}

SlideCount ViscoelasticSlide::count(std::span<const PronyTerm> terms, double from,
                                    double to) const {
  const double h = to - from;
  if (!(h > 0.0)) return {};
  const double a = from - since_;
  const ExponentialSum load = shifted(load_, a);
  const ExponentialSum stretch_rate = slide_slope_of(shifted(response_.stretch, a));
  const ExponentialSum one{1.0, 0.0, {}};
  SlideCount c;
  c.work = rate_ * integral_of_product(load, one, h);
  // The slip rate u_x' - w' has the load's sign while it slides: f_x times it is what is lost.
  c.friction = c.work - integral_of_product(load, stretch_rate, h);
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const ExponentialSum s = shifted(response_.stresses[j], a);
    c.bulk += integral_of_product(s, s, h) / (terms[j].modulus * terms[j].time);
  }
  return c;
}

std::optional<double> ViscoelasticSlide::stick_delay(double now, double span,
                                                     bool just_slipped) const {
  // direction (u_x' - w'(s)): positive while it slides.
  ExponentialSum slip = slide_slope_of(shifted(response_.stretch, now - since_));
  const double sign = direction_;
  slip.constant = sign * (rate_ - slip.constant);
  for (ExponentialDecay& d : slip.decays) d.amplitude = -sign * d.amplitude;
  const double at = slip.at(0.0);
  // Just slipped at a tangency its velocity starts at zero to rounding: the level is where it
  // stands, so that it is not taken for a turn at once.
  double scale = std::abs(rate_) + std::abs(slip.constant);
  for (const ExponentialDecay& d : slip.decays) scale += std::abs(d.amplitude);
  if (just_slipped && std::abs(at) <= 1e-9 * scale) return first_crossing(slip, at, span);
  // Turned already (the drive reversed at a segment's start), or turning now.
  if (at < 0.0 || (at == 0.0 && slip.slope_at(0.0) < 0.0)) return 0.0;
  return first_crossing(slip, std::min(at, 0.0), span);
}

}  // namespace mdrsim

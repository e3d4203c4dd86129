// Octaves built on first use and published with one compare-and-swap: readers take no lock.
#include "python/src/octave_image.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace mdrsim::python {
namespace {

/// Largest |spline - exact| at the odd knots of a spline through the even ones.
double skipped_error(const std::vector<double>& knots, const std::vector<double>& values) {
  std::vector<double> even_knots, even_values;
  for (std::size_t i = 0; i < knots.size(); i += 2) {
    even_knots.push_back(knots[i]);
    even_values.push_back(values[i]);
  }
  const ShapePreservingCubic coarse = ShapePreservingCubic::spline(even_knots, even_values);
  double error = 0.0;
  for (std::size_t i = 1; i < knots.size(); i += 2) {
    error = std::max(error, std::abs(coarse.value(knots[i]) - values[i]));
  }
  return error;
}

}  // namespace

OctaveImage::OctaveImage(std::function<double(double)> exact) : exact_(std::move(exact)) {}

OctaveImage::~OctaveImage() {
  for (auto& slot : octaves_) delete slot.load(std::memory_order_relaxed);
}

std::unique_ptr<OctaveImage::Octave> OctaveImage::build(int exponent) const {
  auto out = std::make_unique<Octave>();
  out->lo = std::ldexp(0.5, exponent);
  out->width = out->lo;
  std::vector<double> exact;  // at the knots of the last try; each try's knots include them
  for (const int intervals : kIntervals) {
    std::vector<double> knots(static_cast<std::size_t>(intervals) + 1);
    std::vector<double> values(knots.size());
    const std::size_t reuse = exact.empty() ? 0 : (knots.size() - 1) / (exact.size() - 1);
    for (std::size_t i = 0; i < knots.size(); ++i) {
      knots[i] = out->lo + out->width * static_cast<double>(i) / intervals;
      values[i] = reuse > 0 && i % reuse == 0 ? exact[i / reuse] : exact_(knots[i]);
    }
    exact = values;
    // g is non-decreasing; eq. 4's own rounding may not be, by an ulp or so.
    for (std::size_t i = 1; i < values.size(); ++i) values[i] = std::max(values[i], values[i - 1]);
    const bool logarithmic = values.front() > 0.0;
    double tolerance = kTolerance;
    if (logarithmic) {
      for (std::size_t i = 0; i < knots.size(); ++i) {
        knots[i] = std::log(knots[i]);
        values[i] = std::log(values[i]);
      }
    } else {
      tolerance *= std::max(std::abs(values.front()), std::abs(values.back()));
    }
    if (skipped_error(knots, values) / 16.0 <= tolerance) {
      out->spline = ShapePreservingCubic::spline(std::move(knots), std::move(values));
      out->logarithmic = logarithmic;
      out->intervals = intervals;
      return out;
    }
  }
  return out;  // exact values at each call
}

const OctaveImage::Octave& OctaveImage::octave(int exponent) const {
  std::atomic<const Octave*>& slot = octaves_[static_cast<std::size_t>(exponent + kOffset)];
  if (const Octave* o = slot.load(std::memory_order_acquire)) return *o;
  std::unique_ptr<Octave> made = build(exponent);
  const Octave* expected = nullptr;
  if (slot.compare_exchange_strong(expected, made.get(), std::memory_order_acq_rel)) {
    built_.fetch_add(1, std::memory_order_relaxed);
    return *made.release();
  }
  return *expected;  // another thread built it meanwhile: ours is dropped
}

double OctaveImage::operator()(double x) const {
  if (!(x > 0.0) || !std::isfinite(x)) return exact_(x);
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);  // x = mantissa 2^exponent, in [0.5, 1)
  if (exponent + kOffset < 0 || exponent + kOffset >= kExponents) return exact_(x);
  const Octave& o = octave(exponent);
  if (!o.spline) return exact_(x);
  const double position = (mantissa - 0.5) * 2.0 * o.intervals;
  const auto k =
      std::min(static_cast<std::size_t>(position), static_cast<std::size_t>(o.intervals - 1));
  return o.logarithmic ? std::exp(o.spline->value_on(k, std::log(x))) : o.spline->value_on(k, x);
}

}  // namespace mdrsim::python

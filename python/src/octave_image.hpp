// The MDR image of a Python profile given by its shape alone, tabulated once per octave of x.
#pragma once

#include <array>
#include <atomic>
#include <climits>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

#include "profiles/shape_preserving_cubic.hpp"

namespace mdrsim::python {

/// g(x) from eq. 4 costs thousands of calls of the Python shape (about 1 ms): this table makes
/// each octave [2^(e-1), 2^e) of x a not-a-knot cubic spline (profiles/shape_preserving_cubic.hpp)
/// of log g over log x through exact values at 8 + 1 even knots (64 or 512 where needed, below),
/// built the first time an x in it is asked for and then read without a lock or the GIL. In
/// log-log a power law c x^n is a line, and a smooth tip is one near x = 0, so that few knots
/// do; an octave where g is not positive is splined in g itself.
///
/// Each octave checks its own error: the spline through every other knot, against the exact
/// values it skips, is 16 times as far off as the full spline (O(h^4)). Above kTolerance
/// (relative to g) the octave takes 8 times as many knots, up to kIntervals.back(), and
/// failing that (a kink in f, a profile too rough for cubics) asks for exact values at each
/// call, as without the table: a run is never less accurate than eq. 4 itself, only slower.
class OctaveImage {
 public:
  static constexpr std::array<int, 3> kIntervals{8, 64, 512};
  static constexpr double kTolerance = 1e-11;

  /// `exact` computes g(x) > 0 for x > 0; it is called from whatever thread asks first, and
  /// takes its own locks (the GIL).
  explicit OctaveImage(std::function<double(double)> exact);
  ~OctaveImage();
  OctaveImage(const OctaveImage&) = delete;
  OctaveImage& operator=(const OctaveImage&) = delete;

  double operator()(double x) const;

  /// Octaves built so far (for tests).
  std::size_t octaves_built() const { return built_.load(std::memory_order_relaxed); }

 private:
  struct Octave {
    std::optional<ShapePreservingCubic> spline;  ///< none: exact values at each call
    bool logarithmic = false;                    ///< log g over log x, else g over x
    double lo = 0.0, width = 0.0;                ///< [2^(e-1), 2^e)
    int intervals = 0;
  };
  static constexpr int kExponents = 2100;  ///< frexp's exponents of finite doubles, and more
  static constexpr int kOffset = 1080;

  const Octave& octave(int exponent) const;
  std::unique_ptr<Octave> build(int exponent) const;

  std::function<double(double)> exact_;
  mutable std::array<std::atomic<const Octave*>, kExponents> octaves_{};
  mutable std::atomic<std::size_t> built_{0};
};

}  // namespace mdrsim::python

// The tabulated profile: table checks, the CSV reader and eq. 4 on the interpolated shape.
#include "profiles/tabulated_profile.hpp"

#include "profiles/two_column_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace mdrsim {
namespace {

constexpr std::size_t kLeastPoints = 4;  // the not-a-knot spline's least
/// sum_i w_i fn(t_i) over [lo, hi] with Boost's N-point Gauss-Legendre nodes.
template <unsigned N, class Fn>
void gauss_legendre(double lo, double hi, Fn fn) {
  using Rule = boost::math::quadrature::gauss<double, N>;
  const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  const auto& x = Rule::abscissa();
  const auto& w = Rule::weights();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] == 0.0) {
      fn(mid, w[i] * half);
    } else {
      fn(mid - half * x[i], w[i] * half);
      fn(mid + half * x[i], w[i] * half);
    }
  }
}

/// cos - 1 and sin of a small angle |d| <= 0.16 by their Taylor series to d^11: the next
/// terms, d^12/12! and d^13/13!, are below 4e-19 of 1, so that both are exact to rounding
/// (cos - 1 with no cancellation where d is small).
struct CosSin {
  double cos_minus_one, sin;
};
CosSin small_cos_sin(double d) {
  const double q = d * d;
  const double c =
      -q * (1.0 / 2 - q * (1.0 / 24 - q * (1.0 / 720 - q * (1.0 / 40320 - q * (1.0 / 3628800)))));
  const double s =
      d * (1.0 - q * (1.0 / 6 - q * (1.0 / 120 - q * (1.0 / 5040 -
                                                      q * (1.0 / 362880 - q * (1.0 / 39916800))))));
  return {c, s};
}

/// Power series in phi^2, lowest power first.
constexpr std::size_t kSeriesLength = 16;
using PowerSeries = std::array<double, kSeriesLength>;

constexpr PowerSeries series_product(const PowerSeries& p, const PowerSeries& q) {
  PowerSeries r{};
  for (std::size_t i = 0; i < kSeriesLength; ++i) {
    for (std::size_t j = 0; i + j < kSeriesLength; ++j) r[i + j] += p[i] * q[j];
  }
  return r;
}

/// cos(phi) - 1 = sum_{n >= 1} (-1)^n phi^(2n) / (2n)!, and sin^2(phi) = (1 - cos(2 phi)) / 2.
constexpr PowerSeries cos_minus_one_series() {
  PowerSeries r{};
  double term = 1.0;  // (-1)^n / (2n)!
  for (std::size_t n = 1; n < kSeriesLength; ++n) {
    term *= -1.0 / static_cast<double>((2 * n - 1) * (2 * n));
    r[n] = term;
  }
  return r;
}
constexpr PowerSeries sin_squared_series() {
  PowerSeries r{};
  double term = 0.5;  // (-1)^(n+1) 2^(2n-1) / (2n)!
  for (std::size_t n = 1; n < kSeriesLength; ++n) {
    term *= -4.0 / static_cast<double>((2 * n - 1) * (2 * n));
    r[n] = -term;
  }
  return r;
}

/// int_{-d}^{d} (cos(phi) - 1)^i sin^l(phi) dphi for even l, as d^(2 lead + 1) times a series
/// in d^2. The integrands are sums of cos(m phi), m <= 3, so each term is below its predecessor
/// by about 9 d^2 / ((2n + 1)(2n + 2)): 6 terms are exact to rounding up to d = 0.15 (the arcs'
/// half-widths; checked against 40-digit quadrature), with none of the cancellation the closed
/// forms (sin d - d, ...) have at small d. All 6 are summed however narrow the arc: a loop over
/// arcs with no branch in it is taken two arcs at a time (16-byte vectors), which costs less
/// than choosing 4 terms for each narrow arc (d < 0.02, where 4 suffice) one arc at a time.
constexpr std::size_t kArcTerms = 6;
struct ArcSeries {
  std::size_t lead;
  std::array<double, kArcTerms> terms;
};
constexpr ArcSeries arc_series(int cos_power, int sin_power) {
  PowerSeries f{};
  f[0] = 1.0;
  for (int i = 0; i < cos_power; ++i) f = series_product(f, cos_minus_one_series());
  for (int i = 0; i < sin_power; i += 2) f = series_product(f, sin_squared_series());
  ArcSeries s{static_cast<std::size_t>(cos_power + sin_power / 2), {}};
  for (std::size_t n = 0; n < kArcTerms; ++n) {
    const std::size_t power = s.lead + n;
    s.terms[n] = 2.0 * f[power] / static_cast<double>(2 * power + 1);
  }
  return s;
}

double arc_moment(const ArcSeries& s, double d, double d2) {
  double sum = 0.0;
  for (std::size_t n = kArcTerms; n-- > 0;) sum = sum * d2 + s.terms[n];
  double power = d;
  for (std::size_t n = 0; n < s.lead; ++n) power *= d2;
  return power * sum;
}

/// The even moments over [-d, d] that a cubic in x = c cos(psi) needs about the arc's middle:
/// (cos - 1)^i sin^l with i + l <= 3 (the odd powers of sin vanish). Three series (kMoment*);
/// the two with sin^2 = -(cos - 1)^2 - 2 (cos - 1) follow from them, each a difference whose
/// smaller term is below d^2/5 of the larger (no cancellation).
struct ArcMoments {
  double c1, c2, c3;
  double s2() const { return -c2 - 2.0 * c1; }
  double c1s2() const { return -c3 - 2.0 * c2; }
};
constexpr ArcSeries kMomentC1 = arc_series(1, 0), kMomentC2 = arc_series(2, 0),
                    kMomentC3 = arc_series(3, 0);

/// Whether r f'(r) never falls on the cubic pieces of f: (r f')' = f' + r f'' is a quadratic
/// in r on each piece, whose least value on the piece is at an end or at its vertex.
bool r_slope_never_falls(const ShapePreservingCubic& f) {
  const std::vector<double>& r = f.knots();
  for (std::size_t k = 0; k + 1 < r.size(); ++k) {
    const auto rise = [&](double s) {
      const double x = r[k] + (r[k + 1] - r[k]) * s;
      return f.slope_on(k, x) + x * f.curvature_on(k, x);
    };
    // q(s) = q0 + b s + c s^2 through s = 0, 1/2, 1.
    const double q0 = rise(0.0), q_mid = rise(0.5), q1 = rise(1.0);
    const double c = 2.0 * (q0 - 2.0 * q_mid + q1);
    const double b = q1 - q0 - c;
    if (!(q0 >= 0.0 && q1 >= 0.0)) return false;
    if (c > 0.0 && b < 0.0 && -b < 2.0 * c && !(rise(-b / (2.0 * c)) >= 0.0)) return false;
  }
  return true;
}

}  // namespace

std::optional<TableProblem> find_table_problem(const ProfileTable& t) {
  const auto& r = t.radii;
  const auto& f = t.gaps;
  if (r.size() < kLeastPoints) {
    return TableProblem{"count", std::nullopt,
                        fmt::format("has {} points, expected at least {}", r.size(), kLeastPoints)};
  }
  if (f.size() != r.size()) {
    return TableProblem{
        "f", std::nullopt,
        fmt::format("has {} values for {} radii r, expected one per r", f.size(), r.size())};
  }
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (!std::isfinite(r[i])) return TableProblem{"r", i, fmt::format("is not a finite number")};
    if (!std::isfinite(f[i])) return TableProblem{"f", i, fmt::format("is not a finite number")};
    if (r[i] < 0.0) return TableProblem{"r", i, "is outside [0, inf)"};
    if (f[i] < 0.0) return TableProblem{"f", i, "is outside [0, inf)"};
  }
  if (r[0] != 0.0) return TableProblem{"r", 0, "is not 0: the table starts at the tip"};
  if (f[0] != 0.0) return TableProblem{"f", 0, "is not 0: the gap is 0 at the tip"};
  for (std::size_t i = 1; i < r.size(); ++i) {
    if (!(r[i] > r[i - 1])) {
      return TableProblem{
          "r", i, fmt::format("is not above the previous r = {}; r must increase", r[i - 1])};
    }
  }
  return std::nullopt;
}

ProfileTable read_profile_table(const std::string& path) {
  TwoColumnFile columns = read_two_column_file(path, "r", "f");
  return {std::move(columns.first), std::move(columns.second), std::move(columns.lines)};
}

TabulatedProfile::TabulatedProfile(const ProfileTable& table)
    : shape_(ShapePreservingCubic::spline(table.radii, table.gaps)),
      image_(ShapePreservingCubic::hermite({0.0, 1.0}, {0.0, 0.0}, {0.0, 0.0})) {
  const std::vector<double>& r = shape_.knots();
  const std::size_t intervals = r.size() - 1;
  // Every table interval split evenly into kImageNodes nodes or more; a longer table keeps
  // every stride-th point, so that building costs O(kImageNodes * table) at most.
  std::vector<double> nodes, values, slopes;
  if (intervals <= kImageNodes) {
    const std::size_t split = (kImageNodes + intervals - 1) / intervals;
    nodes.reserve(intervals * split + 1);
    for (std::size_t k = 0; k < intervals; ++k) {
      for (std::size_t j = 0; j < split; ++j) {
        nodes.push_back(r[k] +
                        (r[k + 1] - r[k]) * (static_cast<double>(j) / static_cast<double>(split)));
      }
    }
  } else {
    const std::size_t stride = (intervals + kImageNodes - 1) / kImageNodes;
    for (std::size_t k = 0; k < intervals; k += stride) nodes.push_back(r[k]);
  }
  nodes.push_back(r.back());
  values.reserve(nodes.size());
  slopes.reserve(nodes.size());
  for (const double x : nodes) {
    const ImageValue g = transform(x);
    values.push_back(g.image);
    slopes.push_back(g.slope);
  }
  image_never_falls_ = r_slope_never_falls(shape_) &&
                       std::is_sorted(values.begin(), values.end()) &&
                       std::all_of(slopes.begin(), slopes.end(), [](double s) { return s >= 0.0; });
  image_ = ShapePreservingCubic::hermite(std::move(nodes), std::move(values), std::move(slopes));
}

std::shared_ptr<const TabulatedProfile> TabulatedProfile::shared(const ProfileTable& table) {
  struct Entry {
    std::vector<double> radii, gaps;
    std::shared_ptr<const TabulatedProfile> profile;
  };
  static std::mutex mutex;
  static std::deque<Entry> recent;
  constexpr std::size_t kKept = 4;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (const Entry& e : recent) {
      if (e.radii == table.radii && e.gaps == table.gaps) return e.profile;
    }
  }
  auto built = std::make_shared<const TabulatedProfile>(table);
  const std::lock_guard<std::mutex> lock(mutex);
  recent.push_front({table.radii, table.gaps, built});
  if (recent.size() > kKept) recent.pop_back();
  return built;
}

TabulatedProfile::ImageValue TabulatedProfile::transform(double x) const {
  constexpr double kQuarterTurn = 0.5 * std::numbers::pi;
  if (!(x > 0.0)) return {0.0, kQuarterTurn * shape_.slope_on(0, 0.0)};
  const std::vector<double>& r = shape_.knots();
  const std::size_t last = r.size() - 2;
  double image = 0.0, slope = 0.0;
  double t_lo = 0.0;
  for (std::size_t k = 0; k <= last; ++k) {
    const bool final_piece = k == last || r[k + 1] >= x;
    const double t_hi = final_piece ? kQuarterTurn : std::asin(r[k + 1] / x);
    // On piece k, f' is a quadratic and f'' linear in r = x sin t: smooth in t, so Gauss-
    // Legendre converges geometrically. The error of n nodes over a width w is about
    // (w/2)^(2n) 2^(2n-1)/(2n)! of the piece: below 1e-16 for 3 nodes up to w = 0.01, 7 up to
    // 0.5 and 20 up to pi/2.
    const auto add = [&](double t, double w) {
      const double rr = x * std::sin(t);
      const double fp = shape_.slope_on(k, rr);
      image += w * fp;
      slope += w * (fp + rr * shape_.curvature_on(k, rr));
    };
    const double width = t_hi - t_lo;
    if (width < 0.01) {
      gauss_legendre<3>(t_lo, t_hi, add);
    } else if (width < 0.5) {
      gauss_legendre<7>(t_lo, t_hi, add);
    } else {
      gauss_legendre<20>(t_lo, t_hi, add);
    }
    if (final_piece) break;
    t_lo = t_hi;
  }
  return {x * image, slope};
}

double TabulatedProfile::shape(double r) const {
  if (r > outer_radius()) return std::numeric_limits<double>::infinity();
  return shape_.value(std::max(r, 0.0));
}

double TabulatedProfile::mdr_image(double x) const {
  if (x > outer_radius()) return std::numeric_limits<double>::infinity();
  return image_.value(std::max(x, 0.0));
}

double TabulatedProfile::mdr_image_slope(double x) const {
  if (x > outer_radius()) return std::numeric_limits<double>::infinity();
  return image_.slope(std::max(x, 0.0));
}

double TabulatedProfile::nonadhesive_force_per_modulus(double a) const {
  if (a > outer_radius()) return std::numeric_limits<double>::infinity();
  if (!(a > 0.0)) return 0.0;
  return 2.0 * (a * image_.value(a) - image_.integral(a));
}

namespace {

/// A Dugdale zone's J and dJ/dt on the image's Hermite pieces (TabulatedProfile::dugdale_gap),
/// `Carried` where the zone is thin. The arcs are taken in blocks: the block's knot angles first
/// (one arccos and one square root a knot, each shared by the two arcs that meet there), then
/// each arc's middle, then its moments, then the sums, each a loop of its own with no call
/// inside: the processor overlaps the arcs' long chains (a knot's arccos, the half-angle's
/// series, the division to the middle, the moments' series), which one loop doing all of an
/// arc before the next would wait on in turn.
template <bool Carried>
DugdaleGap gap_on_pieces(const ShapePreservingCubic& image, double a, double c, double t) {
  const std::vector<double>& knots = image.knots();
  const std::size_t first = image.piece(a);
  const double image_at_contact = Carried ? 0.0 : image.value_on(first, a);
  constexpr double kWidest = 0.3;  // wider arcs are split
  constexpr std::size_t kBlock = 32;
  // A zone spans at most pi/2, so that its splits add at most ceil((pi/2)/kWidest) - 1 arcs.
  constexpr std::size_t kMostArcs = kBlock + 6;
  std::array<double, kMostArcs + 1> angle, cosine, sine;  // the arcs' ends, from the cohesive edge
  std::array<std::size_t, kMostArcs> piece_of;
  std::array<double, kMostArcs> half, cos_half_minus_one, sin_half, mid_x, mid_y;
  std::array<double, kMostArcs> moment_c1, moment_c2, moment_c3;
  std::array<double, kBlock> knot_angle, knot_cos, knot_sin;
  const double to_unit = 1.0 / c;
  const double cos_t = std::cos(t), sin_t = std::sin(t);
  double rise = 0.0;  // r at the upper end of the next arc (x nearer c)
  double gap = 0.0, slope = 0.0;
  std::size_t k = image.piece(c);
  angle[0] = 0.0;
  cosine[0] = 1.0;
  sine[0] = 0.0;
  for (;;) {
    // The block's knots k, k - 1, ... above the contact's piece; where it reaches that piece,
    // its last arc ends at t.
    const std::size_t inner = k > first ? std::min(k - first, kBlock) : 0;
    const bool closes = inner < kBlock;
    // Each knot's angle with its cosine x_k/c and sine sqrt((c - x_k)(c + x_k))/c, exact where
    // the angle is small (1 - (x_k/c)^2 would cancel there).
    for (std::size_t j = 0; j < inner; ++j) {
      const double x = knots[k - j];
      knot_cos[j] = x * to_unit;
      knot_angle[j] = std::acos(knot_cos[j]);
      knot_sin[j] = std::sqrt((c - x) * (c + x)) * to_unit;
    }
    std::size_t arcs = 0;
    const auto add_end = [&](double psi, double cos_psi, double sin_psi, std::size_t piece) {
      const double width = psi - angle[arcs];
      const int parts = width > kWidest ? static_cast<int>(std::ceil(width / kWidest)) : 1;
      const double from = angle[arcs];
      for (int p = 1; p < parts; ++p) {
        const double split = from + width * p / parts;
        piece_of[arcs++] = piece;
        angle[arcs] = split;
        cosine[arcs] = std::cos(split);
        sine[arcs] = std::sin(split);
      }
      piece_of[arcs++] = piece;
      angle[arcs] = psi;
      cosine[arcs] = cos_psi;
      sine[arcs] = sin_psi;
    };
    for (std::size_t j = 0; j < inner; ++j) {  // a knot whose angle rounds past t ends at t
      if (knot_angle[j] > t) {
        add_end(t, cos_t, sin_t, k - j);
      } else {
        add_end(knot_angle[j], knot_cos[j], knot_sin[j], k - j);
      }
    }
    if (closes) add_end(t, cos_t, sin_t, k - inner);
    for (std::size_t i = 0; i < arcs; ++i) {
      half[i] = 0.5 * (angle[i + 1] - angle[i]);
      const CosSin h = small_cos_sin(half[i]);
      cos_half_minus_one[i] = h.cos_minus_one;
      if constexpr (Carried) sin_half[i] = h.sin;
      const double to_mid = 0.5 / (1.0 + h.cos_minus_one);
      mid_x[i] = c * (cosine[i] + cosine[i + 1]) * to_mid;
      mid_y[i] = c * (sine[i] + sine[i + 1]) * to_mid;
    }
    for (std::size_t i = 0; i < arcs; ++i) {
      const double d = half[i], d2 = d * d;
      moment_c1[i] = arc_moment(kMomentC1, d, d2);
      moment_c2[i] = arc_moment(kMomentC2, d, d2);
      moment_c3[i] = arc_moment(kMomentC3, d, d2);
    }
    for (std::size_t i = 0; i < arcs; ++i) {
      const double xm = mid_x[i], ym = mid_y[i];
      const ShapePreservingCubic::Taylor p = image.taylor_on(piece_of[i], xm);
      const ArcMoments e{moment_c1[i], moment_c2[i], moment_c3[i]};
      // The integrand's constant term about x_m: g(x_m) - g(a), or the carried rise r(x_m).
      double level = p.value - image_at_contact;
      if constexpr (Carried) {
        // The arc's ends about its middle: u = x_m (cos d - 1) +- y_m sin d (+ at psi_m - d).
        const double bend = xm * cos_half_minus_one[i], turn = ym * sin_half[i];
        const double top = bend + turn, bottom = bend - turn;
        // r(x_m) = r(top) - (g(top) - g(x_m)); the increment across the arc, g(bottom) - g(top),
        // as (bottom - top) (g'_m + h_m (bottom + top) + s_m (bottom^2 + bottom top + top^2)).
        level = rise - top * (p.slope + top * (p.half_curvature + top * p.sixth_third));
        rise += -2.0 * turn *
                (p.slope + p.half_curvature * 2.0 * bend +
                 p.sixth_third * (bottom * bottom + bottom * top + top * top));
      }
      // int u^j dphi over the arc.
      const double u0 = 2.0 * half[i], u1 = xm * e.c1, u2 = xm * xm * e.c2 + ym * ym * e.s2(),
                   u3 = xm * (xm * xm * e.c3 + 3.0 * ym * ym * e.c1s2());
      gap += level * u0 + p.slope * u1 + p.half_curvature * u2 + p.sixth_third * u3;
      // x g'(x) = (x_m + u) (g'_m + 2 h_m u + 3 s_m u^2) in powers of u.
      slope += xm * p.slope * u0 + (p.slope + 2.0 * p.half_curvature * xm) * u1 +
               (2.0 * p.half_curvature + 3.0 * p.sixth_third * xm) * u2 + 3.0 * p.sixth_third * u3;
    }
    if (closes) break;
    k -= inner;
    angle[0] = angle[arcs];
    cosine[0] = cosine[arcs];
    sine[0] = sine[arcs];
  }
  return {.integral = Carried ? gap - t * rise : gap, .angle_slope = sin_t / cos_t * slope};
}

}  // namespace

// In x = c cos(psi) the image's pieces meet at psi_k = arccos(x_k/c), and on each g is a cubic
// in cos(psi). J and dJ/dt's x g'(x) are integrated in closed form on each arc [psi_m - d,
// psi_m + d] of a piece: with the cubic expanded about x_m = c cos(psi_m), u = x - x_m =
// x_m (cos phi - 1) - y_m sin phi (y_m = c sin(psi_m)), and the powers of u integrated over phi
// in [-d, d] are sums of the five even moments ArcMoments holds (three series, two sums of
// them), of one sign in each power: no cancellation however much the piece bends, a few dozen
// operations an arc. Where the zone is thin (t < 0.3) the difference g(x) - g(a), which would
// cancel there, is never formed: the rise r(x) = g(x) - g(c) is carried down from c, arc by arc, by
// the cubic's increments across it (each the arc's chord times a mean slope), and J = int_0^t r
// dpsi - t r(a), whose two terms are about g'(c) c t^3 / 6 and g'(c) c t^3 / 2 (under 2 bits lost);
// above, g(x) - g(a) is taken as it is (a carried rise would pile up the rounding of a rough
// image's ups and downs). Arcs are at most 0.3 wide (wider pieces are split). The adaptive rule
// would halve its panels at every kink of g'' instead, some 30 panels of 21 nodes a zone.
DugdaleGap TabulatedProfile::dugdale_gap(double a, double c, double t) const {
  // Past the body's edge the image is infinite (mdr_image): the generic rule says so.
  if (!(c <= outer_radius()) || !(a > 0.0) || !(t > 0.0)) {
    return dugdale_gap_quadrature(*this, a, c, t);
  }
  return t < 0.3 ? gap_on_pieces<true>(image_, a, c, t) : gap_on_pieces<false>(image_, a, c, t);
}

std::optional<ExactIntegral> TabulatedProfile::squared_gap_integral(double a, double d) const {
  if (!(a <= outer_radius())) return std::nullopt;
  const ShapePreservingCubic::SquareIntegral i = image_.integral_of_square(d, std::max(a, 0.0));
  return ExactIntegral{i.value, i.magnitude};
}

}  // namespace mdrsim

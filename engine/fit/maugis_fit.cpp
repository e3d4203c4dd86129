// The Maugis-Dugdale fit: the MDR's contact branch sampled in a, interpolated in the depth, and
// driven by the one Levenberg-Marquardt driver; its start from the DMT and JKR fits.
#include "engine/fit/maugis_fit.hpp"

#include <fmt/format.h>
#include <Eigen/Dense>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>

#include "engine/fit/least_squares.hpp"

namespace mdrsim::fit {
namespace {

constexpr double kMaugisPi = std::numbers::pi;
constexpr int kNodes = 97;
constexpr double kLowestRadius = 1e-3;  // of the top radius: the branch's closing end
constexpr int kFreeNodes = 48;          // on the no-contact branch
// youngs_modulus, work_of_adhesion, maugis_parameter, contact_point, offset, slope
constexpr std::size_t kMaugisParameters = 6;
/// The relative step of the central differences in lambda (and in E and w but on the
/// paraboloid): truncation error about 1e-8 of the derivative. Forward steps of 1e-6 left
/// errors that stopped the minimiser short of the minimum along the valley where w, lambda and
/// the contact point trade against each other.
constexpr double kDifferenceStep = 1e-4;
/// The rise at a retract's jump off, in the force's noise, that makes it an observation: the
/// largest of 10^4 differences of pure noise lies near 5.5 of it.
constexpr double kReleaseNoises = 8.0;
/// The thresholds of `--model auto` (Johnson & Greenwood 1997).
constexpr double kDmtBelow = 0.1;
constexpr double kJkrAbove = 5.0;

/// The cubic Hermite interpolant on [0, 1] of values y0, y1 with slopes m0, m1 (per unit t):
/// its value and its slope in t.
std::array<double, 2> cubic_hermite(double t, double y0, double y1, double m0, double m1) {
  const double t2 = t * t, t3 = t2 * t;
  const double value = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 +
                       (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * m1;
  const double slope = (6 * t2 - 6 * t) * y0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * y1 +
                       (3 * t2 - 2 * t) * m1;
  return {value, slope};
}

DugdaleLaw maugis_law(const TipShape& tip, double reduced, double work, double lambda) {
  return {.adhesive_stress = maugis_adhesive_stress(lambda, reduced, work, tip.radius),
          .work_of_adhesion = work,
          .effective_modulus = reduced};
}

/// The samples a fit uses (the contact branch's and the baseline's) in their order.
struct MaugisSamples {
  std::vector<double> z;
  std::vector<double> force;
  std::vector<char> contact;
};

/// Where the lever lets a retract go (MaugisBranch::release_depth) and the branch there.
struct ReleaseSite {
  double stiffness = 0.0;  ///< [N/m] the lever's (input)
  double depth = 0.0;      ///< [m]
  double force = 0.0;      ///< [N] the branch's contact force
  double slope = 0.0;      ///< [N/m] dF/dd
  double curvature = 0.0;  ///< [N/m^2] d2F/dd2
  bool turns = false;      ///< false: the branch's shallow end
  /// [m] The lever's base there in tip positions: the tip's less the bending the contact's
  /// force makes (the baseline's drift is the instrument's, not a force on the lever).
  double base(std::span<const double> p) const { return p[3] - depth - force / stiffness; }
};

/// The model's forces at parameters p (E, w, lambda, contact point, offset, slope), the branch's
/// slopes dF/dd where `slopes` is given, the lever's release where `release` is given; throws
/// std::domain_error as MaugisBranch does.
void maugis_forces(const MaugisSamples& s, const TipShape& tip, double compliance, double deepest,
                   std::span<const double> p, std::span<double> forces, double* pull_off = nullptr,
                   std::span<double> slopes = {}, ReleaseSite* release = nullptr) {
  const double z_low = *std::min_element(s.z.begin(), s.z.end());
  const MaugisBranch branch(*tip.profile, maugis_law(tip, p[0] / compliance, p[1], p[2]),
                            std::max(deepest, p[3] - z_low));
  if (pull_off) *pull_off = -branch.lowest_force();
  if (release) {
    release->depth = branch.release_depth(release->stiffness, &release->turns);
    const MaugisBranch::State at = branch.at(release->depth);
    release->force = at.force;
    release->slope = at.d_force_d_depth;
    // A central difference of the slope over 1e-4 of the branch's span.
    const double h = 1e-4 * std::max(deepest, p[3] - z_low);
    release->curvature =
        (branch.at(release->depth + h).d_force_d_depth -
         branch.at(std::max(release->depth - h, branch.shallowest_depth())).d_force_d_depth) /
        (release->depth + h - std::max(release->depth - h, branch.shallowest_depth()));
  }
  for (std::size_t i = 0; i < s.z.size(); ++i) {
    double contact = 0.0, slope = 0.0;
    if (s.contact[i]) {
      const MaugisBranch::State state = branch.at(p[3] - s.z[i]);
      contact = state.force;
      slope = state.d_force_d_depth;
    }
    forces[i] = p[4] + p[5] * (s.z[i] - p[3]) + contact;
    if (!slopes.empty()) slopes[i] = slope;
  }
}

/// The sum of squares of the least-squares line through f[from, to) over the sample index.
double line_squares(const std::vector<double>& f, std::size_t from, std::size_t to) {
  const double m = static_cast<double>(to - from);
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = from; i < to; ++i) {
    const double x = static_cast<double>(i - from), y = f[i];
    sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
  }
  const double vxx = sxx - sx * sx / m, vxy = sxy - sx * sy / m, vyy = syy - sy * sy / m;
  return vxx > 0.0 ? vyy - vxy * vxy / vxx : vyy;
}

/// The force's noise from successive differences of f[from, to) (free of a baseline's tilt):
/// their median absolute value is 0.6745 sqrt(2) sigma for a normal law.
double difference_noise(const std::vector<double>& f, std::size_t from, std::size_t to) {
  std::vector<double> v;
  for (std::size_t i = from; i + 1 < to; ++i) v.push_back(std::abs(f[i + 1] - f[i]));
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2] / (0.6745 * std::sqrt(2.0));
}

/// The sum of squares of the least-squares parabola through f[from, to) over the sample index.
double parabola_squares(const std::vector<double>& f, std::size_t from, std::size_t to) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  double syy = 0.0;
  const double mid = 0.5 * static_cast<double>(to - from - 1);
  for (std::size_t i = from; i < to; ++i) {
    const double x = static_cast<double>(i - from) - mid;
    const Eigen::Vector3d row(1.0, x, x * x);
    normal += row * row.transpose();
    right += row * f[i];
    syy += f[i] * f[i];
  }
  const Eigen::Vector3d c = normal.ldlt().solve(right);
  return std::max(syy - c.dot(right), 0.0);
}

/// The approach's jump in: its first sample on the path (0: none found) and the standard
/// deviation of that index [samples].
struct JumpIn {
  std::size_t index = 0;
  double spread = 0.0;
};

/// The largest fall between the means of 20 samples either side before the lowest force,
/// then placed by the least squares of a line before and a parabola after a split of the 100
/// samples around it;
/// the index's spread from those sums of squares as a likelihood, exp(-S/(2 sigma^2)).
/// adhesive_fit's largest single fall is lost in 1 % noise where the jump is a few % of the peak
/// force (lambda 0.2 on a lever as stiff as the contact), and there the change point is uncertain
/// by several samples.
JumpIn approach_jump(const std::vector<double>& f) {
  constexpr std::size_t w = 20;
  const std::size_t n = f.size();
  const auto lowest = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
  if (n < 4 * w || lowest < 3 * w) return {};
  std::vector<double> sum(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) sum[i + 1] = sum[i] + f[i];
  std::size_t coarse = 0;
  double fall = -std::numeric_limits<double>::infinity();
  for (std::size_t k = w; k <= std::min(lowest, n - w); ++k) {
    const double drop = (sum[k] - sum[k - w]) - (sum[k + w] - sum[k]);
    if (drop > fall) fall = drop, coarse = k;
  }
  const double noise = difference_noise(f, 0, coarse > w ? coarse - w : coarse);
  std::vector<std::size_t> ks;
  std::vector<double> squares;
  // One span, split at k: a line before, a parabola after (the pull past the jump grows
  // fast, which also puts the coarse fall late by up to a window).
  const std::size_t lo = std::max(coarse, 4 * w) - 4 * w, hi = std::min(coarse + w, n);
  for (std::size_t k = lo + w / 2; k + w / 2 <= hi; ++k) {
    ks.push_back(k);
    squares.push_back(line_squares(f, lo, k) + parabola_squares(f, k, hi));
  }
  const auto best =
      static_cast<std::size_t>(std::min_element(squares.begin(), squares.end()) - squares.begin());
  JumpIn out{ks[best], 0.0};
  if (noise > 0.0) {
    double weight = 0.0, mean = 0.0, second = 0.0;
    for (std::size_t j = 0; j < ks.size(); ++j) {
      const double p = std::exp(-(squares[j] - squares[best]) / (2.0 * noise * noise));
      const double x = static_cast<double>(ks[j]) - static_cast<double>(ks[best]);
      weight += p, mean += p * x, second += p * x * x;
    }
    mean /= weight;
    out.spread = std::sqrt(std::max(second / weight - mean * mean, 0.0));
  }
  return out;
}

/// Where the lever's base stood half way between samples k - 1 and k of an approach: the
/// least-squares line through the free samples' tip positions z[0, k) over the index, taken at
/// k - 1/2. Off the path the tip is where the base is, which moves evenly; the line, unlike
/// z[k - 1], stays put where the split is placed a sample late (the sample then one on the
/// path, the tip pulled past the base by the contact's force over the lever's stiffness).
double free_line_at(const std::vector<double>& z, std::size_t k) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const double x = static_cast<double>(i), y = z[i];
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double m = static_cast<double>(k);
  const double vxx = sxx - sx * sx / m;
  if (!(vxx > 0.0)) return z[k - 1];
  const double rise = (sxy - sx * sy / m) / vxx;
  return (sy - rise * sx) / m + rise * (static_cast<double>(k) - 0.5);
}

bool finite_start(const AdhesiveFit& f) {
  return std::isfinite(f.youngs_modulus.value) && f.youngs_modulus.value > 0.0 &&
         std::isfinite(f.work_of_adhesion.value) && f.work_of_adhesion.value > 0.0 &&
         std::isfinite(f.contact_point.value) && std::isfinite(f.baseline_offset.value) &&
         std::isfinite(f.baseline_slope.value);
}

}  // namespace

double maugis_adhesive_stress(double lambda, double reduced_modulus, double work, double radius) {
  const double k = 4.0 * reduced_modulus / 3.0;
  return 0.5 * lambda * std::cbrt(kMaugisPi * work * k * k / radius);
}

MaugisBranch::MaugisBranch(const Profile& profile, const DugdaleLaw& law, double deepest) {
  const double outer = profile.outer_radius();
  // The top radius: Hertz's at the deepest indentation, widened until the branch, whose depth
  // lies below the image's by the zone's pull, reaches it.
  double top = profile.contact_radius_at_depth(std::max(deepest, 0.0));
  if (!(top > 0.0)) top = 1e-9;
  if (std::isfinite(outer)) top = std::min(top, 0.5 * outer);
  for (int k = 0; k < 60 && dugdale_contact_state(profile, law, top).indentation < deepest; ++k) {
    top = std::isfinite(outer) ? std::min(1.25 * top, 0.5 * (top + outer)) : 1.25 * top;
  }
  // Nodes in a = top u^2, u even from sqrt(1e-3) to 1: denser at small a, where the zone
  // closes and the depth turns.
  std::vector<double> radii(kNodes);
  const double u_low = std::sqrt(kLowestRadius);
  for (int k = 0; k < kNodes; ++k) {
    const double u = u_low + (1.0 - u_low) * k / (kNodes - 1);
    radii[static_cast<std::size_t>(k)] = top * u * u;
  }
  radii.back() = top;
  const std::vector<DugdaleState> states = dugdale_contact_states(profile, law, radii);
  // From the top down while the depth falls with a: the stable part of the branch.
  std::size_t first = states.size() - 1;
  bool folds = false;
  std::vector<DugdaleSlopes> slopes(states.size());
  for (std::size_t k = states.size(); k-- > 0;) {
    slopes[k] = dugdale_contact_slopes(profile, law, states[k]);
    if (!(slopes[k].indentation > 0.0) ||
        (k + 1 < states.size() && !(states[k].indentation < states[k + 1].indentation))) {
      folds = true;
      break;
    }
    first = k;
  }
  if (!folds) {
    // The contact closes before the depth turns (small lambda): the no-contact branch from
    // the closing radius c0 down to its own fold, d(c) = f(c) - (4 sigma_0/(pi E*)) c - h0
    // least, in c even; its slopes dd/dc by a central difference of f, dF/dc = -2 pi sigma_0 c.
    const double c0 = dugdale_closing_radius(profile, law);
    const auto depth_at = [&](double c) { return dugdale_free_state(profile, law, c).indentation; };
    const double c_fold = boost::math::tools::brent_find_minima(depth_at, 0.0, c0, 40).first;
    // Where the no-contact branch rises from c0 already, the path ends at the closing point:
    // that one node.
    const bool descends = c_fold < (1.0 - 1e-6) * c0;
    const int count = descends ? kFreeNodes : 1;
    for (int j = 0; j < count; ++j) {
      const double c = descends ? c_fold + (c0 - c_fold) * j / (kFreeNodes - 1) : c0;
      const DugdaleState state = dugdale_free_state(profile, law, c);
      const double h = 1e-6 * c;
      radius_.push_back(c);
      depth_.push_back(state.indentation);
      force_.push_back(state.normal_force);
      depth_slope_.push_back(j == 0 ? 0.0 : (depth_at(c + h) - depth_at(c - h)) / (2.0 * h));
      force_slope_.push_back(-2.0 * kMaugisPi * law.adhesive_stress * c);
      contact_.push_back(0);
    }
  }
  for (std::size_t k = first; k < states.size(); ++k) {
    if (!depth_.empty() && !(states[k].indentation > depth_.back())) continue;
    radius_.push_back(states[k].contact_radius);
    depth_.push_back(states[k].indentation);
    force_.push_back(states[k].normal_force);
    depth_slope_.push_back(slopes[k].indentation);
    force_slope_.push_back(slopes[k].normal_force);
    contact_.push_back(1);
  }
  // The lowest force: the lowest node's, refined where F'(a) = 0 on the cubics either side.
  const auto lowest =
      static_cast<std::size_t>(std::min_element(force_.begin(), force_.end()) - force_.begin());
  lowest_force_ = force_[lowest];
  for (std::size_t k = lowest > 0 ? lowest - 1 : 0; k <= lowest && k + 1 < force_.size(); ++k) {
    if (contact_[k] != contact_[k + 1]) continue;
    const double h = radius_[k + 1] - radius_[k];
    const double y0 = force_[k], y1 = force_[k + 1];
    const double m0 = force_slope_[k] * h, m1 = force_slope_[k + 1] * h;
    // F'(t) = qa t^2 + qb t + qc.
    const double qa = 6 * y0 + 3 * m0 - 6 * y1 + 3 * m1;
    const double qb = -6 * y0 - 4 * m0 + 6 * y1 - 2 * m1;
    const double qc = m0;
    const double disc = qb * qb - 4 * qa * qc;
    if (!(disc >= 0.0) || qa == 0.0) continue;
    for (const double sign : {-1.0, 1.0}) {
      const double t = (-qb + sign * std::sqrt(disc)) / (2 * qa);
      if (t > 0.0 && t < 1.0) {
        lowest_force_ = std::min(lowest_force_, cubic_hermite(t, y0, y1, m0, m1)[0]);
      }
    }
  }
}

MaugisBranch::State MaugisBranch::at(double depth) const {
  if (!(depth > depth_.front()) || depth_.size() < 2) return {force_.front(), 0.0};
  if (depth >= depth_.back()) {
    const double slope = force_slope_.back() / depth_slope_.back();
    return {force_.back() + slope * (depth - depth_.back()), slope};
  }
  const auto k = static_cast<std::size_t>(std::upper_bound(depth_.begin(), depth_.end(), depth) -
                                          depth_.begin() - 1);
  const double d0 = depth_[k], d1 = depth_[k + 1];
  if (contact_[k] != contact_[k + 1]) {
    // Where the no-contact branch meets the contact branch's last node (a = 1e-3 of the top
    // radius, its depth within (1e-3)^2 of the closing point's): a chord.
    const double slope = (force_[k + 1] - force_[k]) / (d1 - d0);
    return {force_[k] + slope * (depth - d0), slope};
  }
  const double h = radius_[k + 1] - radius_[k];
  const double m0 = depth_slope_[k] * h, m1 = depth_slope_[k + 1] * h;
  // d(t) = depth by Newton's steps from the chord, kept inside [0, 1] (d rises on it).
  double t = (depth - d0) / (d1 - d0), lo = 0.0, hi = 1.0;
  std::array<double, 2> d = cubic_hermite(t, d0, d1, m0, m1);
  for (int step = 0; step < 20; ++step) {
    const double excess = d[0] - depth;
    (excess < 0.0 ? lo : hi) = t;
    double next = d[1] > 0.0 ? t - excess / d[1] : 0.5 * (lo + hi);
    // A Newton step below 1e-7 leaves about its square: take it and stop (checked against the
    // bracket it could bounce off the end it has just set).
    const bool done = std::abs(next - t) <= 1e-7;
    if (!done && !(next > lo && next < hi)) next = 0.5 * (lo + hi);
    t = std::clamp(next, 0.0, 1.0);
    d = cubic_hermite(t, d0, d1, m0, m1);
    if (done) break;
  }
  const std::array<double, 2> f =
      cubic_hermite(t, force_[k], force_[k + 1], force_slope_[k] * h, force_slope_[k + 1] * h);
  return {f[0], d[1] > 0.0 ? f[1] / d[1] : 0.0};
}

double MaugisBranch::release_depth(double stiffness, bool* turns) const {
  if (turns) *turns = false;
  if (!(stiffness > 0.0) || depth_.size() < 2) return depth_.front();
  const auto node_slope = [&](std::size_t k) {
    return depth_slope_[k] > 0.0 ? force_slope_[k] / depth_slope_[k]
                                 : -std::numeric_limits<double>::infinity();
  };
  // Coming out from the deepest node: the first interval whose shallow node is past -k.
  std::size_t k = depth_.size() - 1;
  while (k > 0 && node_slope(k - 1) > -stiffness) --k;
  if (k == 0) return depth_.front();
  // The slope falls through -k inside [depth_[k - 1], depth_[k]]: bisection on at().
  double lo = depth_[k - 1], hi = depth_[k];
  for (int step = 0; step < 50; ++step) {
    const double mid = 0.5 * (lo + hi);
    (at(mid).d_force_d_depth > -stiffness ? hi : lo) = mid;
  }
  if (turns) *turns = true;
  return 0.5 * (lo + hi);
}

RegimeChoice choose_regime(double lambda) {
  const char* model = lambda < kDmtBelow ? "dmt" : lambda > kJkrAbove ? "jkr" : "maugis";
  return {model, fmt::format("auto: lambda = {:.3g} -> {}", lambda, model)};
}

namespace {

/// The JKR and DMT fits a Maugis fit starts from; the JKR fit also finds the path's samples.
struct AdhesiveStarts {
  AdhesiveFit jkr, dmt;
};

/// The starts on `segment`: its JKR and DMT fits, and where the JKR fit finds no contact, on the
/// samples past the 50 before the jump in `found` (an approach fitted alone), or a retract
/// without its last tenth.
AdhesiveStarts adhesive_starts(const PreparedSegment& segment, const MaugisFitOptions& options,
                               std::size_t found, bool alone) {
  AdhesiveFitOptions adhesive;
  adhesive.tip = options.tip;
  adhesive.poisson_ratio = options.poisson_ratio;
  adhesive.fixed = options.fixed;
  adhesive.retract = options.retract;
  adhesive.model = AdhesionModel::jkr;
  AdhesiveStarts starts;
  AdhesiveFit& jkr = starts.jkr;
  jkr = fit_adhesive(segment, adhesive);
  const std::size_t n = segment.force.size();
  // An approach whose jump in is lost in the noise for adhesive_fit's single largest fall:
  // the starts from the samples past the 50 before the jump approach_jump finds.
  PreparedSegment near;
  const PreparedSegment* start_segment = &segment;
  if (alone && jkr.status == FitStatus::no_contact && found > 50) {
    near = segment;
    const auto cut = static_cast<std::ptrdiff_t>(found - 50);
    near.tip_position.erase(near.tip_position.begin(), near.tip_position.begin() + cut);
    near.force.erase(near.force.begin(), near.force.begin() + cut);
    start_segment = &near;
    jkr = fit_adhesive(near, adhesive);
  }
  // A retract held by its lever nearly to the path's end (small lambda): the jump off is in the
  // noise, whose largest rise can fall among the last samples, leaving no baseline; the starts
  // from the segment without its last tenth.
  if (options.retract && jkr.status == FitStatus::no_contact && n > 100) {
    near = segment;
    near.tip_position.resize(n - n / 10);
    near.force.resize(n - n / 10);
    start_segment = &near;
    jkr = fit_adhesive(near, adhesive);
  }
  adhesive.model = AdhesionModel::dmt;
  try {
    starts.dmt = fit_adhesive(*start_segment, adhesive);
  } catch (const std::domain_error&) {
    // A start only: none where DMT's sphere is pressed past its reach.
    starts.dmt.status = FitStatus::not_converged;
  }
  return starts;
}

/// fit_maugis, and with `approach` (the segment then being the retract) both segments on one
/// path: the approach's samples from its jump in on it, the rest on the baseline, its jump in
/// the one more residual. `known`: the segment's adhesive_starts, where already fitted.
AdhesiveFit fit_maugis_segments(const PreparedSegment& segment, const MaugisFitOptions& options,
                                const PreparedSegment* approach,
                                const AdhesiveStarts* known = nullptr) {
  AdhesiveFit fit;
  const std::vector<double>& z = segment.tip_position;
  const std::vector<double>& f = segment.force;
  const std::size_t n = f.size();
  fit.points = n;
  if (options.tip.kind == TipKind::cone || !(options.tip.radius > 0.0)) {
    fit.status = FitStatus::not_converged;
    fit.message = "the Maugis parameter needs a tip radius (parabolic or sphere)";
    return fit;
  }
  const JumpIn jump_in_found = approach          ? approach_jump(approach->force)
                               : options.retract ? JumpIn{}
                                                 : approach_jump(f);
  const std::size_t found = jump_in_found.index;
  // The DMT and JKR fits find the contact branch's samples and give the starts.
  const AdhesiveStarts adhesive =
      known ? *known : adhesive_starts(segment, options, found, approach == nullptr);
  const AdhesiveFit& jkr = adhesive.jkr;
  const AdhesiveFit& dmt = adhesive.dmt;
  if (jkr.status == FitStatus::no_contact || jkr.contact_samples == 0) {
    fit.status = jkr.status;
    fit.message = jkr.message;
    return fit;
  }
  fit.adhesion_force_measured = jkr.adhesion_force_measured;
  const double compliance = 1.0 - options.poisson_ratio * options.poisson_ratio;
  // The path's samples as adhesive_fit found them: a retract's down to the jump off, past the
  // lowest force as far as the lever's stiffness held it there.
  const std::size_t jump = options.retract ? jkr.contact_samples - 1
                           : found > 0     ? found
                                           : n - jkr.contact_samples;
  if (approach && found == 0) {
    fit.status = FitStatus::no_contact;
    fit.message = "no jump in on the approach";
    return fit;
  }
  MaugisSamples samples;
  for (std::size_t i = 0; i < n; ++i) {
    const bool contact = options.retract ? i <= jump : i >= jump;
    const bool free = options.retract ? i > jump : i < jump;
    if (!contact && !free) continue;
    samples.z.push_back(z[i]);
    samples.force.push_back(f[i]);
    samples.contact.push_back(contact ? 1 : 0);
  }
  // The approach (with a retract): far first, on the baseline before its jump in.
  const std::vector<double>& jz = approach ? approach->tip_position : z;
  const std::vector<double>& jf = approach ? approach->force : f;
  std::size_t jump_index = approach ? found : jump;
  for (std::size_t i = 0; approach && i < jz.size(); ++i) {
    samples.z.push_back(jz[i]);
    samples.force.push_back(jf[i]);
    samples.contact.push_back(i >= jump_index ? 1 : 0);
  }
  const std::size_t used = samples.z.size();
  fit.points = used;
  // An approach adds one observation: the jump in, where the zone first reaches the surface,
  // the tip at d = -h0 (h0 = w / sigma_0, the zone's range). It lies between the last free
  // sample and the next step of the lever's base, which on the baseline moves the tip by the
  // sampling step: a uniform error of that step / sqrt(12). The data's shape alone hardly tells
  // lambda above 0.5 (the branch changes by 1e-4 of the peak force); this position does, as
  // h0 = 2 / (pi lambda) of Maugis' depth unit.
  const bool jump_in = (approach || !options.retract) && jump_index > 0;
  double jump_weight = 0.0, jump_observed = 0.0, jump_step = 0.0, jump_noise = 0.0;
  if (jump_in) {
    std::vector<double> steps;
    for (std::size_t i = 0; i + 1 < jump_index; ++i) steps.push_back(std::abs(jz[i + 1] - jz[i]));
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                     steps.end());
    jump_step = steps.empty() ? 0.0 : steps[steps.size() / 2];
    // The jump's position weighs as the force's noise over its standard deviation: the step's
    // uniform 1/sqrt(12) and the spread of the found index.
    jump_noise = difference_noise(jf, 0, jump_index);
    const double spread = found > 0 ? jump_in_found.spread : 0.0;
    if (jump_step > 0.0 && jump_noise > 0.0) {
      jump_weight = jump_noise / (jump_step * std::sqrt(1.0 / 12.0 + spread * spread));
      jump_observed = free_line_at(jz, jump_index);
    }
  }
  const bool jump_row = jump_in && jump_weight > 0.0;
  // A retract through a lever of known stiffness k adds the jump off: the base there stands
  // where q = d + F/k turns on the branch (dF/dd = -k), which moves with lambda apart from the
  // contact point unlike the jump in's -h0. Off the branch the tip is where the base is, which
  // moves evenly: the line through the free samples' positions, taken back half a step past
  // the last sample on the branch, places the jump within a uniform error of one step.
  ReleaseSite release;
  release.stiffness = segment.spring_constant;
  double release_weight = 0.0, release_observed = 0.0;
  if (options.retract && release.stiffness > 0.0 && jump + 10 < n) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = jump + 1; i < n; ++i) {
      const double x = static_cast<double>(i), y = z[i];
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double m = static_cast<double>(n - jump - 1);
    const double rise = (sxy - sx * sy / m) / (sxx - sx * sx / m);
    const double noise = difference_noise(f, jump + 1, n);
    // Only a jump that stands out: where the lever holds the path nearly to its end (small
    // lambda), the last step is lost in the noise and the one found is the noise's largest.
    const bool stands_out = f[jump + 1] - f[jump] > kReleaseNoises * noise;
    if (std::isfinite(rise) && rise != 0.0 && noise > 0.0 && stands_out) {
      release_observed = (sy - rise * sx) / m + rise * (static_cast<double>(jump) + 0.5);
      release_weight = noise / (std::abs(rise) * std::sqrt(1.0 / 12.0));
    }
  }
  const bool release_row = release_weight > 0.0;
  const std::size_t release_at = used + (jump_row ? 1 : 0);
  const std::size_t rows = release_at + (release_row ? 1 : 0);
  std::vector<double> data = samples.force;
  // Measured from the observed jumps (the residual is a small difference of small numbers).
  if (jump_row) data.push_back(0.0);
  if (release_row) data.push_back(0.0);
  // The zone's range h0 = w / sigma_0 at parameters p.
  const auto zone_range = [&](std::span<const double> p) {
    return p[1] / maugis_adhesive_stress(p[2], p[0] / compliance, p[1], options.tip.radius);
  };
  fit.contact_samples = static_cast<std::size_t>(
      std::count(samples.contact.begin(), samples.contact.end(), static_cast<char>(1)));

  const auto [z_low, z_high] = std::minmax_element(samples.z.begin(), samples.z.end());
  const double z_range = std::max(*z_high - *z_low, 1e-30);
  double force_scale = 0.0;
  for (const double v : samples.force) force_scale = std::max(force_scale, std::abs(v));
  force_scale = std::max(force_scale, 1e-300);
  const double deepest = std::max(jkr.contact_point.value - *z_low, 1e-3 * z_range);

  const std::array<std::optional<double>, kMaugisParameters> held = {
      options.fixed.youngs_modulus, options.fixed.work_of_adhesion, options.fixed.maugis_parameter,
      options.fixed.contact_point,  options.fixed.baseline_offset,  options.fixed.baseline_slope};
  // The starts: of the JKR and DMT fits, at each of five lambdas with w scaled to the pull-off
  // they measured, the one of least squares on the DMT side (lambda 0.1, 0.3) and the one on
  // the JKR side (1, 3, 10). The minimiser runs from both: towards JKR the curve hardly
  // changes with lambda (a plateau in log lambda that stops it where it starts).
  std::vector<double> forces(used);
  const auto jump_residual = [&](std::span<const double> p) {
    return (p[3] + zone_range(p) - jump_observed) * jump_weight;
  };
  const auto sum_squares = [&](std::span<const double> p, double* pull_off) {
    ReleaseSite site = release;
    maugis_forces(samples, options.tip, compliance, deepest, p, forces, pull_off, {},
                  release_row ? &site : nullptr);
    double sum = 0.0;
    for (std::size_t i = 0; i < used; ++i) {
      const double r = (forces[i] - samples.force[i]) / force_scale;
      sum += r * r;
    }
    if (jump_row) {
      const double r = jump_residual(p) / force_scale;
      sum += r * r;
    }
    if (release_row) {
      const double r = (site.base(p) - release_observed) * release_weight / force_scale;
      sum += r * r;
    }
    return sum;
  };
  using Parameters = std::array<double, kMaugisParameters>;
  std::array<Parameters, 2> starts{};
  std::array<double, 2> best = {std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::infinity()};
  const std::vector<double> lambdas =
      held[2] ? std::vector<double>{*held[2]} : std::vector<double>{0.1, 0.3, 1.0, 3.0, 10.0};
  for (const AdhesiveFit* from :
       {static_cast<const AdhesiveFit*>(&jkr), static_cast<const AdhesiveFit*>(&dmt)}) {
    if (!finite_start(*from)) continue;
    for (const double lambda : lambdas) {
      Parameters p = {
          from->youngs_modulus.value, from->work_of_adhesion.value, lambda,
          from->contact_point.value,  from->baseline_offset.value,  from->baseline_slope.value};
      try {
        double pull_off = 0.0;
        sum_squares(p, &pull_off);
        if (!held[1] && pull_off > 0.0) p[1] *= fit.adhesion_force_measured / pull_off;
        const double s = sum_squares(p, nullptr);
        const std::size_t side = held[2] || lambda < 1.0 ? 0 : 1;
        if (s < best[side]) best[side] = s, starts[side] = p;
      } catch (const std::domain_error&) {
      }
    }
  }
  if (!std::isfinite(best[0]) && !std::isfinite(best[1])) {
    fit.status = FitStatus::not_converged;
    fit.message = "no start of the Maugis model reaches the deepest indentation inside the tip";
    return fit;
  }

  ScaledProblem problem;
  // E, w and lambda as start x exp(x), positive; the rest as start + scale x.
  problem.scale = {1.0, 1.0, 1.0, deepest, force_scale, force_scale / z_range};
  problem.walk = {Walk::logarithmic, Walk::logarithmic, Walk::logarithmic,
                  Walk::linear,      Walk::linear,      Walk::linear};
  for (std::size_t j = 0; j < kMaugisParameters; ++j) problem.held.push_back(held[j].has_value());
  problem.data = &data;
  problem.force_scale = force_scale;
  // A zone past the tip's edge (a sphere pressed deep): a residual of 1e10 the force scale at
  // every sample, so that the minimiser refuses the step.
  const auto refuse = [&](std::span<double> model) {
    for (std::size_t i = 0; i < rows; ++i) model[i] = data[i] + 1e10 * force_scale;
  };
  problem.model = [&](std::span<const double> p, std::span<double> model) {
    try {
      ReleaseSite site = release;
      maugis_forces(samples, options.tip, compliance, deepest, p, model.first(used), nullptr, {},
                    release_row ? &site : nullptr);
      if (jump_row) model[used] = jump_residual(p);
      if (release_row) model[release_at] = (site.base(p) - release_observed) * release_weight;
    } catch (const std::domain_error&) {
      refuse(model);
    }
  };
  std::vector<double> slopes(used), shifted(used), lowered(used);
  problem.derivatives = [&](std::span<const double> p, std::span<double> d) {
    try {
      ReleaseSite site = release;
      maugis_forces(samples, options.tip, compliance, deepest, p, forces, nullptr, slopes,
                    release_row ? &site : nullptr);
      for (std::size_t i = 0; i < used; ++i) {
        d[3 * rows + i] = -p[5] + slopes[i];
        d[4 * rows + i] = 1.0;
        d[5 * rows + i] = samples.z[i] - p[3];
      }
      std::array<double, kMaugisParameters> q{};
      std::copy(p.begin(), p.end(), q.begin());
      // On the paraboloid Maugis' scaling is exact: F = pi w R P(d / delta; lambda) with
      // delta^3 = pi^2 w^2 R / K^2, so at fixed lambda dF/dln E = (2/3) d dF/dd and
      // dF/dln w = F - (2/3) d dF/dd; lambda (and E and w on other tips) by central
      // differences of the whole branch.
      const bool scales = options.tip.kind == TipKind::parabolic;
      if (scales) {
        for (std::size_t i = 0; i < used; ++i) {
          if (!samples.contact[i]) {
            d[i] = d[rows + i] = 0.0;
            continue;
          }
          const double contact = forces[i] - p[4] - p[5] * (samples.z[i] - p[3]);
          const double lever = 2.0 / 3.0 * (p[3] - samples.z[i]) * slopes[i];
          d[i] = lever / p[0];
          d[rows + i] = (contact - lever) / p[1];
        }
        if (release_row) {
          // The same scaling at the release: dF/dln E and dF/dln w at its depth, and the depth's
          // own shift, where the slope stays -k (implicit), or as delta at the fold.
          const double dd = site.depth, lever = 2.0 / 3.0 * dd * site.slope;
          const double d_force[2] = {lever, site.force - lever};
          const double d_slope[2] = {2.0 / 3.0 * (site.slope + dd * site.curvature),
                                     site.slope / 3.0 - 2.0 / 3.0 * dd * site.curvature};
          const double d_depth_fold[2] = {-2.0 / 3.0 * dd, 2.0 / 3.0 * dd};
          const double tilt = 1.0 + site.slope / site.stiffness;
          for (std::size_t k = 0; k < 2; ++k) {
            const double shift = site.turns && site.curvature != 0.0 ? -d_slope[k] / site.curvature
                                                                     : d_depth_fold[k];
            d[k * rows + release_at] =
                (-tilt * shift - d_force[k] / site.stiffness) / p[k] * release_weight;
          }
        }
      }
      for (std::size_t k = scales ? 2 : 0; k < 3; ++k) {
        if (held[k]) continue;
        const double step = kDifferenceStep * p[k];
        q[k] = p[k] + step;
        ReleaseSite up = release, down = release;
        maugis_forces(samples, options.tip, compliance, deepest, q, shifted, nullptr, {},
                      release_row ? &up : nullptr);
        const double base_up = release_row ? up.base(q) : 0.0;
        q[k] = p[k] - step;
        maugis_forces(samples, options.tip, compliance, deepest, q, lowered, nullptr, {},
                      release_row ? &down : nullptr);
        const double base_down = release_row ? down.base(q) : 0.0;
        q[k] = p[k];
        for (std::size_t i = 0; i < used; ++i) {
          d[k * rows + i] = (shifted[i] - lowered[i]) / (2.0 * step);
        }
        if (release_row) {
          d[k * rows + release_at] = (base_up - base_down) / (2.0 * step) * release_weight;
        }
      }
      if (jump_row) {
        // d(cp + h0)/dp: h0 = w / sigma_0 goes as w^(2/3) E^(-2/3) / lambda.
        const double h0 = zone_range(p);
        d[used] = -2.0 / 3.0 * h0 / p[0] * jump_weight;
        d[rows + used] = 2.0 / 3.0 * h0 / p[1] * jump_weight;
        d[2 * rows + used] = -h0 / p[2] * jump_weight;
        d[3 * rows + used] = jump_weight;
        d[4 * rows + used] = d[5 * rows + used] = 0.0;
      }
      if (release_row) {
        d[3 * rows + release_at] = release_weight;
        d[4 * rows + release_at] = d[5 * rows + release_at] = 0.0;
      }
    } catch (const std::domain_error&) {
      std::fill(d.begin(), d.end(), 0.0);
    }
  };
  FitParameter* const out[kMaugisParameters] = {&fit.youngs_modulus,   &fit.work_of_adhesion,
                                                &fit.maugis_parameter, &fit.contact_point,
                                                &fit.baseline_offset,  &fit.baseline_slope};
  ScaledSolution solution;
  solution.sum_squares = std::numeric_limits<double>::infinity();
  for (std::size_t side = 0; side < 2; ++side) {
    if (!std::isfinite(best[side])) continue;
    Parameters start = starts[side];
    for (std::size_t j = 0; j < kMaugisParameters; ++j) {
      if (held[j]) start[j] = *held[j];
    }
    problem.start.assign(start.begin(), start.end());
    std::array<FitParameter, kMaugisParameters> trial{};
    std::array<FitParameter*, kMaugisParameters> into{};
    for (std::size_t j = 0; j < kMaugisParameters; ++j) into[j] = &trial[j];
    ScaledSolution one = minimize_scaled(problem, into);
    // The lower sum of squares; a run that converged before one that did not.
    const bool better = (one.outcome == MinimizerOutcome::converged) !=
                                (solution.outcome == MinimizerOutcome::converged)
                            ? one.outcome == MinimizerOutcome::converged
                            : one.sum_squares < solution.sum_squares;
    if (!std::isfinite(solution.sum_squares) || better) {
      one.iterations += solution.iterations;
      one.evaluations += solution.evaluations;
      solution = std::move(one);
      for (std::size_t j = 0; j < kMaugisParameters; ++j) *out[j] = trial[j];
    } else {
      solution.iterations += one.iterations;
      solution.evaluations += one.evaluations;
    }
  }
  // A retract whose jump off is lost in the noise (the lever holds the path nearly to its end):
  // the jump found is the noise's largest rise, anywhere along the path's tail. Its samples
  // are then those the fitted model's lever holds (depth past the release). An approach's jump
  // in, found apart from the model, can lie late where the jump is a few noise deviations (or
  // anywhere near it where it is one): its first sample on the path is then the split of least
  // squares of the fitted model over the approach's samples (the baseline before, the path
  // from it), its spread from those sums as a likelihood, and the jump's row moves with it.
  // The fit runs again from its minimum while that moves samples (at most three times for a
  // retract alone, twenty with a jump in, which can creep a few samples a pass).
  const std::size_t retract_count = options.retract ? n : 0;
  const bool reclassify_retract = retract_count > 0 && release.stiffness > 0.0 && !release_row;
  const std::size_t approach_from = used - jz.size();
  std::vector<double> on_path(used);
  const auto reclassify = [&](ScaledSolution& settled) {
    for (int pass = 0; pass < (jump_row ? 20 : 3) && (reclassify_retract || jump_row) &&
                       std::isfinite(settled.sum_squares);
         ++pass) {
      const std::span<const double> q(settled.values);
      bool moved = false;
      if (reclassify_retract) {
        double release_depth = 0.0;
        try {
          const double low = *std::min_element(samples.z.begin(), samples.z.end());
          const MaugisBranch branch(*options.tip.profile,
                                    maugis_law(options.tip, q[0] / compliance, q[1], q[2]),
                                    std::max(deepest, q[3] - low));
          release_depth = branch.release_depth(release.stiffness);
        } catch (const std::domain_error&) {
          break;
        }
        for (std::size_t i = 0; i < retract_count; ++i) {
          const char held_on = q[3] - samples.z[i] >= release_depth ? 1 : 0;
          moved = moved || held_on != samples.contact[i];
          samples.contact[i] = held_on;
        }
      }
      if (jump_row) {
        MaugisSamples all_on = samples;
        std::fill(all_on.contact.begin() + static_cast<std::ptrdiff_t>(approach_from),
                  all_on.contact.end(), static_cast<char>(1));
        // The first sample the path reaches: the tip lands past -h0 (the lever pulls it on), so
        // a split before the zone's range would put free samples on a path they cannot be on.
        std::size_t reach = 1;
        try {
          maugis_forces(all_on, options.tip, compliance, deepest, q, on_path);
          const double range = zone_range(q);
          for (std::size_t i = 0; i < jz.size(); ++i) {
            if (q[3] - jz[i] <= -range) reach = std::max(reach, i + 1);
          }
        } catch (const std::domain_error&) {
          break;
        }
        if (reach + 1 >= jz.size()) break;
        // squares[k]: the approach's samples before k on the baseline, from k on the path.
        const std::size_t m = jz.size();
        std::vector<double> squares(m + 1, 0.0);
        for (std::size_t i = 0; i < m; ++i) {
          const double off = q[4] + q[5] * (jz[i] - q[3]) - jf[i];
          squares[i + 1] = squares[i] + off * off;
        }
        double after = 0.0;
        for (std::size_t i = m; i-- > 0;) {
          const double on = on_path[approach_from + i] - jf[i];
          after += on * on;
          squares[i] += after;
        }
        std::size_t best_k = std::max(jump_index, reach);
        for (std::size_t k = reach; k < m; ++k) {
          if (squares[k] < squares[best_k]) best_k = k;
        }
        double weight = 0.0, mean = 0.0, second = 0.0;
        for (std::size_t k = reach; k < m; ++k) {
          const double pk =
              std::exp(-(squares[k] - squares[best_k]) / (2.0 * jump_noise * jump_noise));
          const double x = static_cast<double>(k) - static_cast<double>(best_k);
          weight += pk, mean += pk * x, second += pk * x * x;
        }
        mean /= weight;
        const double spread = std::sqrt(std::max(second / weight - mean * mean, 0.0));
        for (std::size_t i = 0; i < m; ++i) {
          const char held_on = i >= best_k ? 1 : 0;
          moved = moved || held_on != samples.contact[approach_from + i];
          samples.contact[approach_from + i] = held_on;
        }
        jump_index = best_k;
        jump_weight = jump_noise / (jump_step * std::sqrt(1.0 / 12.0 + spread * spread));
        jump_observed = free_line_at(jz, jump_index);
      }
      if (!moved) break;
      problem.start.assign(q.begin(), q.end());
      std::array<FitParameter, kMaugisParameters> trial{};
      std::array<FitParameter*, kMaugisParameters> into{};
      for (std::size_t j = 0; j < kMaugisParameters; ++j) into[j] = &trial[j];
      ScaledSolution again = minimize_scaled(problem, into);
      again.iterations += settled.iterations;
      again.evaluations += settled.evaluations;
      settled = std::move(again);
      for (std::size_t j = 0; j < kMaugisParameters; ++j) *out[j] = trial[j];
    }
  };
  reclassify(solution);
  // Where the approach's jump in is a noise deviation or so (small lambda), its change point
  // can lie far late, and the fit from it settles where the path starts there (lambda several
  // times the truth). The retract alone places the jump in too, where the tip reaches -h0 of
  // its fit: the joint fit from there, kept where its samples' sum of squares is lower.
  if (approach && jump_row) {
    const AdhesiveFit alone = fit_maugis_segments(segment, options, nullptr, &adhesive);
    Parameters q = {alone.youngs_modulus.value,   alone.work_of_adhesion.value,
                    alone.maugis_parameter.value, alone.contact_point.value,
                    alone.baseline_offset.value,  alone.baseline_slope.value};
    std::size_t k = 0;
    if (alone.status == FitStatus::fitted) {
      try {
        const double range = zone_range(q);
        while (k < jz.size() && q[3] - jz[k] <= -range) ++k;
      } catch (const std::domain_error&) {
        k = 0;
      }
    }
    const auto sample_squares = [&](std::span<const double> p) {
      try {
        maugis_forces(samples, options.tip, compliance, deepest, p, forces);
      } catch (const std::domain_error&) {
        return std::numeric_limits<double>::infinity();
      }
      double sum = 0.0;
      for (std::size_t i = 0; i < used; ++i) sum += std::pow(forces[i] - samples.force[i], 2);
      return sum;
    };
    if (k > 0 && k < jz.size() && k != jump_index && std::isfinite(solution.sum_squares)) {
      const double kept_squares = sample_squares(solution.values);
      const MaugisSamples kept_samples = samples;
      const std::size_t kept_index = jump_index;
      const double kept_weight = jump_weight, kept_observed = jump_observed;
      ScaledSolution kept = solution;
      std::array<FitParameter, kMaugisParameters> kept_out{};
      for (std::size_t j = 0; j < kMaugisParameters; ++j) kept_out[j] = *out[j];
      for (std::size_t i = 0; i < jz.size(); ++i) {
        samples.contact[approach_from + i] = i >= k ? 1 : 0;
      }
      jump_index = k;
      jump_observed = free_line_at(jz, k);
      for (std::size_t j = 0; j < kMaugisParameters; ++j) {
        if (held[j]) q[j] = *held[j];
      }
      problem.start.assign(q.begin(), q.end());
      std::array<FitParameter, kMaugisParameters> trial{};
      std::array<FitParameter*, kMaugisParameters> into{};
      for (std::size_t j = 0; j < kMaugisParameters; ++j) into[j] = &trial[j];
      ScaledSolution other = minimize_scaled(problem, into);
      for (std::size_t j = 0; j < kMaugisParameters; ++j) *out[j] = trial[j];
      other.iterations += solution.iterations;
      other.evaluations += solution.evaluations;
      reclassify(other);
      const double other_squares = sample_squares(other.values);
      if (other.outcome == MinimizerOutcome::converged && other_squares < kept_squares) {
        solution = std::move(other);
      } else {
        samples = kept_samples;
        jump_index = kept_index;
        jump_weight = kept_weight;
        jump_observed = kept_observed;
        kept.iterations = other.iterations;
        kept.evaluations = other.evaluations;
        solution = std::move(kept);
        for (std::size_t j = 0; j < kMaugisParameters; ++j) *out[j] = kept_out[j];
      }
    }
  }
  fit.contact_samples = static_cast<std::size_t>(
      std::count(samples.contact.begin(), samples.contact.end(), static_cast<char>(1)));
  fit.iterations = solution.iterations;
  fit.evaluations = solution.evaluations;
  const std::vector<double>& p = solution.values;
  // Of the force samples alone (the jumps' rows are positions).
  double position_squares = jump_row ? std::pow(jump_residual(p) / force_scale, 2) : 0.0;
  if (release_row) {
    ReleaseSite site = release;
    try {
      maugis_forces(samples, options.tip, compliance, deepest, p, forces, nullptr, {}, &site);
      position_squares +=
          std::pow((site.base(p) - release_observed) * release_weight / force_scale, 2);
    } catch (const std::domain_error&) {
    }
  }
  fit.residual_rms = std::sqrt(std::max(solution.sum_squares - position_squares, 0.0) /
                               static_cast<double>(used)) *
                     force_scale;
  fit.max_indentation = std::max(0.0, p[3] - *z_low);
  bool reaches = true;
  try {
    maugis_forces(samples, options.tip, compliance, deepest, p, forces, &fit.adhesion_force_fitted);
  } catch (const std::domain_error&) {
    reaches = false;
  }
  settle_status(fit, out, solution.outcome,
                reaches ? nullptr : "the fitted cohesive zone reaches past the tip's edge",
                RefusalRank::before_non_finite);
  return fit;
}

}  // namespace

AdhesiveFit fit_maugis(const PreparedSegment& segment, const MaugisFitOptions& options) {
  return fit_maugis_segments(segment, options, nullptr);
}

AdhesiveFit fit_maugis_both(const PreparedSegment& approach, const PreparedSegment& retract,
                            const MaugisFitOptions& options) {
  MaugisFitOptions on_retract = options;
  on_retract.retract = true;
  return fit_maugis_segments(retract, on_retract, &approach);
}

}  // namespace mdrsim::fit

// The MDR transform (paper eq. 4) and its inverse (eq. 5) of any profile, by tanh-sinh quadrature.
#pragma once

#include <functional>
#include <vector>

namespace mdrsim {

/// Eq. 4: g(x) = x integral_0^x f'(r)/sqrt(x^2 - r^2) dr [m] at x >= 0 [m], from the slope
/// f'(r) [1]. Tanh-sinh clusters its nodes at both ends, where f' may be singular (a power
/// law below n = 1) and where 1/sqrt(x^2 - r^2) is; the distance to the end is handed over
/// exactly (Boost's complement), so x - r keeps its digits next to r = x. `breaks` are
/// radii where f' is not smooth (a table's points): the integral is split there, so that
/// each piece is smooth inside, as tanh-sinh needs.
double mdr_transform(const std::function<double(double)>& shape_slope, double x,
                     const std::vector<double>& breaks = {});

/// Eq. 5: f(r) = (2/pi) integral_0^r g(x)/sqrt(r^2 - x^2) dx [m] at r >= 0 [m], from g(x) [m],
/// split at `breaks` likewise.
double inverse_mdr_transform(const std::function<double(double)>& image, double r,
                             const std::vector<double>& breaks = {});

}  // namespace mdrsim

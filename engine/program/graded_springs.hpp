// A program row's springs on a graded half-space: their stiffness, the advancing front's gluing
// limit, and Hess's rule on them as the criterion the row's let-gos ask (docs/graded.md).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "detachment/criterion.hpp"
#include "engine/base/material.hpp"
#include "engine/model/graded_constants.hpp"
#include "engine/model/graded_image.hpp"

namespace mdrsim {

/// The graded springs of a row: spring i (both halves) carries the stiffness of its cell,
/// w_i = C_k (x_i^(1+k) - x_(i-1)^(1+k)), the springs 1..m together C_k x_m^(1+k); a free
/// spring glues when its gap reaches Hess's stretch with dgamma_a,
/// sqrt(4 pi x^(1-k) dgamma_a / ((1 + k) C_k)).
struct GradedSprings {
  const GradedImage* image;  ///< g_k, kept by the scene
  double punch_constant;     ///< C_k [Pa / m^k]
  double approach_work;      ///< dgamma_a [J/m^2]

  /// The springs of a graded material, none on a homogeneous one.
  static std::optional<GradedSprings> of(const std::optional<GradedImage>& image,
                                         const Material& material) {
    if (!image || !material.grading.graded()) return std::nullopt;
    return GradedSprings{&*image, material.grading.punch_constant,
                         material.approach_work_of_adhesion};
  }

  double exponent() const { return image->grading_exponent(); }
  /// w_i [N/m] of spring i at x_i [m]: x_i^(1+k) (1 - (1 - 1/i)^(1+k)) by expm1 and log1p, as
  /// the shorthand's row has it (a difference of two close powers loses digits on long rows).
  double weight(std::int64_t i, double x) const {
    const double p = 1.0 + exponent();
    const double fraction = -std::expm1(p * std::log1p(-1.0 / static_cast<double>(i)));
    return punch_constant * std::pow(x, p) * fraction;
  }
  /// C_k x^(1+k) [N/m]: the springs out to x [m] together.
  double stiffness_to(double x) const { return punch_constant * std::pow(x, 1.0 + exponent()); }
  /// The gap [m] at which the advancing front glues a free spring at x [m] (0: on touch).
  double front_limit(double x) const {
    return graded_let_go_stretch(exponent(), punch_constant, approach_work, x);
  }
};

/// Hess's rule on the graded springs as a criterion: the boundary spring at radius a lets go at
/// e(a) = sqrt(4 pi a^(1-k) dgamma / ((1 + k) C_k)) whatever u_x (a graded scene loads normally
/// only). The margin e(a) - elongation [m] is non-increasing in the elongation and holds on a
/// half-plane of (elongation, u_x): the contract, proved.
class GradedHessCriterion : public DetachmentCriterion {
 public:
  GradedHessCriterion(const GradedSprings& springs, double work_of_adhesion)
      : exponent_(springs.exponent()),
        punch_constant_(springs.punch_constant),
        work_of_adhesion_(work_of_adhesion) {}

  double margin(const BoundarySpring& spring) const override {
    return limit(spring.contact_radius) - spring.elongation;
  }
  std::optional<double> critical_elongation(double contact_radius, double) const override {
    return limit(contact_radius);
  }
  bool proves_contract() const override { return true; }

 private:
  double limit(double a) const {
    return graded_let_go_stretch(exponent_, punch_constant_, work_of_adhesion_, a);
  }
  double exponent_;
  double punch_constant_;
  double work_of_adhesion_;
};

}  // namespace mdrsim

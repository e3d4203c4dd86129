// The critical spring stress: sqrt((E* uz)^2 + (G* ux)^2) >= E* dl(a).
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

class StressCriterion final : public DetachmentCriterion {
 public:
  explicit StressCriterion(const InterfaceProperties& properties)
      : p_(properties), scales_(properties) {}
  double margin(const BoundarySpring& spring) const override;
  std::optional<double> critical_elongation(double contact_radius,
                                            double tangential_displacement) const override;
  /// The holding set |(E* e, G* u_x)| < E* dl(a) is an ellipse's inside (convex), and the margin
  /// falls with e >= 0.
  bool proves_contract() const override { return true; }

 private:
  InterfaceProperties p_;
  ElongationScales scales_;
};

}  // namespace mdrsim

// Johnson's energy release rate: E* uz^2 + G* ux^2 >= 2 pi a dgamma (paper eqs. 3, 20).
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

class ModeMixedCriterion final : public DetachmentCriterion {
 public:
  explicit ModeMixedCriterion(const InterfaceProperties& properties)
      : p_(properties), scales_(properties) {}
  double margin(const BoundarySpring& spring) const override;
  std::optional<double> critical_elongation(double contact_radius,
                                            double tangential_displacement) const override;
  /// The holding set E* e^2 + G* u_x^2 < 2 pi a dgamma is an ellipse's inside (convex), and
  /// the margin falls with e >= 0.
  bool proves_contract() const override { return true; }

 private:
  InterfaceProperties p_;
  ElongationScales scales_;
};

}  // namespace mdrsim

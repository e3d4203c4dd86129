// The deformation criterion: sqrt(uz^2 + ux^2) >= dl(a) (paper eq. 38).
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

class DeformationCriterion final : public DetachmentCriterion {
 public:
  explicit DeformationCriterion(const InterfaceProperties& properties)
      : p_(properties), scales_(properties) {}
  double margin(const BoundarySpring& spring) const override;
  std::optional<double> critical_elongation(double contact_radius,
                                            double tangential_displacement) const override;
  /// The holding set sqrt(e^2 + u_x^2) < dl(a) is a disk's inside (convex), and the margin falls
  /// with e >= 0.
  bool proves_contract() const override { return true; }

 private:
  InterfaceProperties p_;
  ElongationScales scales_;
};

}  // namespace mdrsim

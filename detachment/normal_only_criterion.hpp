// An interface without tangential strength: |uz| >= dl(a), ux ignored.
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

class NormalOnlyCriterion final : public DetachmentCriterion {
 public:
  explicit NormalOnlyCriterion(const InterfaceProperties& properties)
      : p_(properties), scales_(properties) {}
  double margin(const BoundarySpring& spring) const override;
  std::optional<double> critical_elongation(double contact_radius,
                                            double tangential_displacement) const override;
  /// The holding set e < dl(a) is a half-plane (convex), and the margin falls with e.
  bool proves_contract() const override { return true; }

 private:
  InterfaceProperties p_;
  ElongationScales scales_;
};

}  // namespace mdrsim

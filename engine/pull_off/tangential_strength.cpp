// The strength as a bracketed root of the boundary margin in the tangential displacement.
#include "engine/pull_off/tangential_strength.hpp"

#include <algorithm>
#include <cmath>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/boundary_let_go.hpp"

namespace mdrsim {

std::optional<double> tangential_strength(const Contact& contact,
                                          const DetachmentCriterion& criterion) {
  if (contact.springs_in_contact() == 0) return 0.0;
  const double a = contact.contact_radius();
  const double e = boundary_elongation(contact);
  const auto margin = [&](double u) { return criterion.margin({e, u, a}); };
  if (!(margin(0.0) > 0.0)) return 0.0;
  double lo = 0.0;
  double hi = std::max(e, contact.foundation().spacing());
  for (int doublings = 0; margin(hi) > 0.0; ++doublings) {
    if (doublings > 2100 || !std::isfinite(2.0 * hi)) return std::nullopt;
    lo = hi;
    hi *= 2.0;
  }
  if (!(margin(hi) <= 0.0)) return std::nullopt;  // NaN: the criterion has no answer there
  const double u = bracketed_root(margin, lo, hi);
  return contact.tangential_response().stiffness * u;
}

}  // namespace mdrsim

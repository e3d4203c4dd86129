// The continuum pull-off of a glued contact, computed apart from the engine's spring row.
#pragma once

#include <string_view>
#include <vector>

#include "profiles/profile.hpp"

namespace mdrsim::test {

/// The detachment law at the contact edge, written here from the criterion table of docs/scene.md
/// (not through detachment/): with W = 2 pi a dgamma and tan psi = sqrt(G*/E*) u_x / e, the
/// boundary spring lets go when
///   mode-mixed      E* e^2 + G* u_x^2 >= W
///   deformation     e^2 + u_x^2 >= W/E*
///   stress          (E* e)^2 + (G* u_x)^2 >= E* W
///   normal-only     E* e^2 >= W
///   mode-dependent  E* e^2 + G* u_x^2 >= W (1 + tan^2((1 - lambda) psi))
struct DetachmentLaw {
  enum class Kind { mode_mixed, deformation, stress, normal_only, mode_dependent };
  Kind kind = Kind::mode_mixed;
  double lambda = 1.0;  ///< mode-dependent only, in [0, 1] [1]
};

/// The half-space and the interface (docs: E* = E/(1 - nu^2), G* = 4G/(2 - nu)).
struct ContinuumMaterial {
  double effective_modulus;        ///< E* [Pa]
  double effective_shear_modulus;  ///< G* [Pa]
  double work_of_adhesion;         ///< dgamma [J/m^2]

  static ContinuumMaterial from_youngs_modulus(double youngs_modulus, double poisson_ratio,
                                               double work_of_adhesion);
};

/// What the tangential machine holds during the pull-off.
struct TangentialLoad {
  enum class Kind {
    none,          ///< u_x = 0
    displacement,  ///< fixed grips: u_x = value
    force,         ///< fixed load: u_x(a) = value / (2 G* a)
  };
  Kind kind = Kind::none;
  double value = 0.0;  ///< the held u_x [m] or F_x [N]
};

/// The normal machine as the affine constraint a_u d + a_F F = held value.
struct NormalControl {
  double displacement_coefficient = 1.0;  ///< a_u [1]
  double force_coefficient = 0.0;         ///< a_F [m/N]

  static NormalControl fixed_grips() { return {1.0, 0.0}; }
  static NormalControl fixed_load() { return {0.0, 1.0}; }
  /// A machine spring of stiffness [N/m] between the driving point and the indenter.
  static NormalControl compliant(double stiffness) { return {1.0, 1.0 / stiffness}; }
};

/// One equilibrium of the continuum contact.
struct ContinuumState {
  double contact_radius = 0.0;           ///< a [m]
  double stretch = 0.0;                  ///< boundary elongation e [m]
  double indentation = 0.0;              ///< d = g(a) - e [m]
  double normal_force = 0.0;             ///< F [N]
  double tangential_displacement = 0.0;  ///< u_x [m]
  double tangential_force = 0.0;         ///< F_x = 2 G* a u_x [N]
  double control_value = 0.0;            ///< a_u d + a_F F [m]
};

/// A jump that leaves a smaller contact in place: from a fold to where the branch's control
/// value comes back below the fold's.
struct ContinuumJump {
  ContinuumState from;
  ContinuumState to;
};

/// Where the pull-off of a contact glued at radius a_g ends.
struct ContinuumCritical {
  enum class Kind {
    fold,                      ///< the jump that empties the contact starts at a fold below a_g
    first_detachment,          ///< the first let-go at a_g already empties the contact
    shear_off,                 ///< the branch reaches the radius where e = 0 (the law breaks
                               ///< the boundary unstretched below it)
    shear_off_at_application,  ///< the tangential load alone breaks the glue at a_g
    none,                      ///< the control falls all the way to a -> 0: smooth peel
  };
  Kind kind = Kind::none;
  /// The last equilibrium before the jump that empties the contact. shear_off: the state
  /// at the shear-off radius; shear_off_at_application: the glued state at a_g with zero
  /// stretch; none: the smallest radius scanned.
  ContinuumState point;
  /// The most tensile (smallest) normal force over the equilibria of the path, from a_g to
  /// `point` (shear_off_at_application: the glued state's) [N].
  double peak_adhesive_force = 0.0;
  ContinuumState peak;  ///< the state where that force is reached
  std::vector<ContinuumJump> partial_jumps;
  double shear_off_radius = 0.0;  ///< a_s: below it e = 0 and the glue breaks at once [m]
  /// shear_off_at_application only: the largest tangential force the glued contact at a_g
  /// carries with zero boundary stretch, 2 G* a_g u_max (infinite for laws that ignore
  /// u_x at zero stretch) [N]; 0 otherwise.
  double tangential_strength = 0.0;
};

std::string_view kind_name(ContinuumCritical::Kind kind);

/// The law's margin for a boundary spring at radius a [m] with elongation e [m] and
/// tangential displacement u_x [m]: > 0 while it holds, <= 0 once it lets go [J/m].
double law_margin(const DetachmentLaw& law, const ContinuumMaterial& material, double elongation,
                  double tangential_displacement, double contact_radius);

/// The continuum branch d(a) = g(a) - e(a), F(a) = E* nf(a) - 2 E* a e(a) of a profile under
/// one law, tangential hold and normal control, and the pull-off along it. Every quantity
/// comes from the profile's g, g' and nonadhesive_force_per_modulus and from closed forms or
/// root searches written here.
class ContinuumReference {
 public:
  ContinuumReference(const Profile& profile, ContinuumMaterial material, DetachmentLaw law,
                     TangentialLoad tangential, NormalControl normal);

  /// a_s [m]: the radius below which the law lets go at zero stretch (0 if never).
  double shear_off_radius() const { return shear_off_radius_; }
  /// The largest |u_x| [m] the law holds at zero stretch at radius a [m] (infinite if any).
  double zero_stretch_limit(double contact_radius) const;

  double tangential_displacement(double contact_radius) const;  ///< u_x(a) [m]
  double stretch(double contact_radius) const;                  ///< e(a) [m], 0 for a <= a_s
  double stretch_slope(double contact_radius) const;            ///< de/da [1], for a > a_s
  ContinuumState at(double contact_radius) const;
  double control_slope(double contact_radius) const;       ///< d(a_u d + a_F F)/da [m/m]
  double normal_force_slope(double contact_radius) const;  ///< dF/da [N/m]

  /// The pull-off from glued radius a_g [m] with the tangential load held. Radii are
  /// scanned from a_g down to 1e-12 a_g (and geometrically towards a_s) at
  /// `samples_per_decade`; each fold, force extremum and landing point is refined to full
  /// precision by a bracketing root search.
  ContinuumCritical pull_off(double glued_radius, int samples_per_decade = 100) const;

 private:
  struct Edge {
    double stretch;  ///< e [m]
    double slope;    ///< de/da [1]
  };
  struct Sample {
    double a;              ///< [m]
    double control;        ///< [m]
    double control_slope;  ///< [1]
    double force;          ///< [N]
    double force_slope;    ///< [N/m]
    bool fold = false;     ///< a local minimum of the control value in a
  };

  Edge edge(double a) const;
  Edge mode_dependent_edge(double a, double tangential_displacement) const;
  Sample sample(double a) const;
  ContinuumState unstretched_state(double a) const;

  const Profile* profile_;
  ContinuumMaterial material_;
  DetachmentLaw law_;
  TangentialLoad tangential_;
  NormalControl normal_;
  double adhesion_length_;    ///< w = 2 pi dgamma / E*, so that the Hess limit is dl^2 = w a [m]
  double shear_coefficient_;  ///< c: the law lets go unstretched when c u_x^2 >= W [Pa]
  double shear_off_radius_;   ///< a_s [m]
};

}  // namespace mdrsim::test

// The springs in contact under friction: tangential force, slip events, frictional work.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "engine/base/large_pages.hpp"
#include "engine/base/material.hpp"
#include "engine/model/compensated_sum.hpp"
#include "engine/model/friction_settings.hpp"
#include "engine/program/index_set.hpp"
#include "engine/program/slip_keys.hpp"
#include "engine/program/stick_slip_spring.hpp"

namespace mdrsim {

/// A friction event of one spring of the row.
struct RowFrictionEvent {
  std::int64_t spring;  ///< i, 1-based
  FrictionEvent event;
};

/// Springs i = 1..m in contact at x_i = i dx (one half of the symmetric MDR foundation, as in
/// ProgramRow: every force is twice the half-row's sum); springs 1..k are glued. Each spring
/// carries its offset (f_x = G* dx (u_x - offset)) and whether it slides. A glued spring's
/// offset is the u_x at which it glued; it keeps it when it lets go and when it glues again.
///
/// The springs that are not glued (k < i <= m, pressed: d >= g_i, which the program's lift
/// events keep true) need no pass over the row. With r = mu E*/G*, a sticking spring slips
/// forward when p+ = u_x - r d rises to its key o_i - r g_i and backward when p- = u_x + r d
/// falls to o_i + r g_i: keys that do not change while it sticks, kept in order, so the next
/// slip is the smallest (largest) key, O(log m) per event in flat arrays. Every spring sliding
/// along +x has the same slip velocity p+' (along -x, p-'), so they stick together when it
/// reverses, and their force and dissipated work are sums of their count and images.
///
/// Glued springs under GluedShear::limited are on keys too. Their limit mu max(f_z, 0) + c_i
/// (c_i the adhesive part) is mu f_z + c_i while pressed (d >= g_i) and c_i in tension: a
/// pressed one is keyed against p+- as an unglued spring is, with its key moved by -+ c_i / kx;
/// one in tension against u_x alone, o_i +- c_i / kx. Each glued spring is in one of the two
/// classes; where d crosses its image it changes class, a `limit_kink` event found from the
/// largest image of the pressed ones and the smallest of those in tension (O(log k)). So every
/// event costs O(log m) with glue too; a change of the glued radius moves every c_i (tau_0 > 0
/// only), re-keying the glued springs, O(k) then. Under GluedShear::unlimited glued springs only
/// stick. Under a law other than Coulomb's (FrictionSettings::law) every spring goes spring by
/// spring, with the limit the law gave it as it touched (O(m) per query).
class FrictionRow {
 public:
  FrictionRow(const Material& material, const FrictionSettings& settings, double spacing);

  std::int64_t in_contact() const { return static_cast<std::int64_t>(springs_.size()); }  ///< m
  std::int64_t glued() const { return glued_; }                                           ///< k
  double position(std::int64_t i) const { return spacing_ * static_cast<double>(i); }  ///< x_i [m]
  /// Spring i's state; a sliding spring's offset is that of the present position (the last
  /// advance, touch or let_go_boundary).
  StickSlipSpring spring(std::int64_t i) const;
  SpringGeometry geometry(std::int64_t i) const;
  /// The slip limit of spring i: the friction law's while it is not glued (Coulomb's at
  /// `coefficient`, constant 0, unless FrictionSettings::law gives another); for a glued spring
  /// under glued = "coulomb" (GluedShear::limited) Coulomb's plus the MDR image of the shear
  /// strength over the glued disk, 2 tau_0 sqrt(a_g^2 - x^2) dx, so that it may carry tension;
  /// nullopt for a glued spring under GluedShear::unlimited (it never slips).
  std::optional<SlipLimit> law(std::int64_t i) const;
  /// Whether glued springs slip by their own law (glued = "coulomb"): each then carries its own
  /// stretch, not its glued run's u_x - s.
  bool glued_springs_slip() const { return settings_.glued == GluedShear::limited; }
  /// Glued spring i's tangential stretch f_x / kx at (d, u_x) in its present state (sticking or
  /// sliding, as between two events): u_x - offset while it sticks, +-limit / kx while it
  /// slides (0 at the glued edge in tension, where its limit is 0) [m].
  double glued_stretch(std::int64_t i, double indentation, double tangential) const;
  /// The tangential stretch spring i keeps at d once its glue is gone and it stays pressed:
  /// what its law lets it hold without glue, limit / kx (Coulomb's mu f_z / kx) [m].
  double released_limit_stretch(std::int64_t i, double indentation) const {
    const SlipLimit free = individual_ ? laws_[index(i)] : SlipLimit{settings_.coefficient, 0.0};
    return slip_limit(free, geometry(i), indentation) / tangential_stiffness_;
  }
  /// Whether that stretch moves with d (a coefficient or a law of its own).
  bool released_limit_moves() const { return individual_ || settings_.coefficient != 0.0; }
  /// The elastic energy of the springs' tangential stretches on both halves, kx (u_x -
  /// offset)^2 / 2 each, a slider's at its limit, limit^2 / (2 kx): O(1) from the row's sums
  /// (glued springs under glued = "coulomb" included, by class), plus O(m) while springs under
  /// a law of its own slide, O(k) where a glued slider's class is wrong at d [J].
  double stored_energy(double indentation, double tangential) const;

  /// Room for `springs` in contact without reallocation (the row's N: each regrowth copies the
  /// springs into fresh pages, and at 1e6 springs the pages cost more than the events).
  void reserve(std::int64_t springs);
  /// Spring m+1, of image g [m], is pressed with no tangential stretch at u_x [m].
  void touch(double image, double tangential);
  /// Spring m (not glued) leaves the indenter and forgets its slip.
  void lift_outer();
  /// Spring k+1 (in contact, sticking) glues at indentation d [m], keeping its present stretch.
  void glue_next(double indentation);
  /// The boundary spring k lets go and stays pressed at (d, u_x): it keeps its stretch and
  /// slips to its limit at once where the stretch exceeds it. Returns the dissipated work [J].
  double let_go_boundary(double indentation, double tangential);

  /// F_x = 2 sum over the springs in contact of f_x, glued ones included [N].
  double tangential_force(double indentation, double tangential) const;
  /// dF_x/du_x and dF_x/dd while no spring changes (F_x is affine in both): 2 G* dx per
  /// sticking spring, and 2 mu E* dx per pressed spring sliding along +x, minus along -x: the
  /// tangential equilibrium's coefficients under any control [N/m].
  double tangential_stiffness() const;
  double tangential_force_per_indentation(double indentation) const;
  /// Springs i <= m sliding now (one half of the row, like ProgramRow's counts).
  std::int64_t springs_sliding() const {
    return sliders_[0].size() + sliders_[1].size() + tension_sliders_[0].size() +
           tension_sliders_[1].size() + own_sliding_;
  }
  /// The radius inside which every spring in contact sticks: x_{j-1}, j the innermost
  /// sliding spring; the contact radius x_m when none slides [m]. Inline where none does:
  /// every snapshot asks.
  double stick_radius() const {
    return force_follows_indentation() ? sliding_stick_radius() : position(in_contact());
  }

  /// Whether F_x depends on d at a fixed u_x: only through a sliding spring's limit mu f_z.
  /// Without one, F_x(d, u_x) is the same number for every finite d.
  bool force_follows_indentation() const {
    return own_sliding_ > 0 || !sliders_[0].empty() || !sliders_[1].empty() ||
           !tension_sliders_[0].empty() || !tension_sliders_[1].empty();
  }
  /// Whether next_event can find anything along `motion`: not when nothing slides, no glued
  /// spring can slip (GluedShear::unlimited) and p+ falls or stays (p- rises or stays) with u_x
  /// still and d rising or still (a press: every touch of it would ask). Inline, so that the
  /// program loop pays no call for it.
  bool may_change(const LinearMotion& motion) const {
    return settings_.glued == GluedShear::limited || individual_ || force_follows_indentation() ||
           !(motion.tangential_rate == 0.0 && motion.indentation_rate >= 0.0);
  }
  /// Whether every spring in contact is on the keys and sliders (nothing glued, no law of its
  /// own): its events are then found in O(1) each, and a ramp may take them in bulk.
  bool slides_in_bulk() const { return glued_ == 0 && !individual_; }
  /// The first friction event of any spring along `motion` in [motion.start, end] (apply it
  /// and ask again at the same t for the next of a cascade).
  std::optional<RowFrictionEvent> next_event(const LinearMotion& motion, double end) const;
  /// Moves every spring from motion.start to t with no event in between; returns the work
  /// the slips dissipated on both halves (the step's dissipated_by_friction increment) [J].
  double advance(const LinearMotion& motion, double t) {
    if (force_follows_indentation()) return advance_sliding(motion, t);
    // Nothing slides: nothing dissipates, only the position moves (each touch of a press).
    indentation_ = motion.indentation_at(t);
    tangential_ = motion.tangential_at(t);
    return 0.0;
  }
  /// Applies an event found by next_event, after advance to its time.
  void apply(const RowFrictionEvent& event);

 private:
  struct Spring {
    StickSlipSpring
        state;     ///< a sliding spring's offset is not kept up to date when it is not glued
    double image;  ///< g(x_i) [m]
  };
  std::size_t index(std::int64_t i) const { return static_cast<std::size_t>(i - 1); }
  static std::size_t side(int direction) { return direction > 0 ? 0 : 1; }
  double limit_sum(std::size_t s, double indentation) const;  ///< sum of mu f_z of a side [N]
  /// The adhesive part of glued spring i's limit under GluedShear::limited: the MDR image of a
  /// uniform shear strength tau_0 over the glued disk, 2 tau_0 sqrt(a_g^2 - x_i^2) dx with a_g =
  /// x_k (docs/friction.md) [N].
  double glued_adhesive_limit(std::int64_t i) const;
  /// After a_g changed: every glued spring within its new limit sticks, one over it slips to it
  /// at once. Returns the work dissipated on both halves [J]; O(k), with tau_0 > 0 only. For
  /// springs that go one by one (own_springs()); keyed ones go through detach_glued and
  /// attach_glued around the change.
  double limit_glued_springs();
  /// Whether a change of a_g moves the keyed glued springs' limits (tau_0 > 0).
  bool glued_keys_move() const { return glued_keyed_ && settings_.shear_strength > 0.0; }
  /// Springs 1..n out of every set and sum, each sliding one's offset brought up to date first
  /// (before a_g changes: their c_i goes with it).
  void detach_glued(std::int64_t n);
  /// Springs 1..n back in under the present a_g: within its limit a spring sticks where it is,
  /// over it it slips to it at once (`relimit_sticking`: a sticking one too, else only a
  /// sliding one, where every limit grew). Returns the work dissipated on both halves [J].
  double attach_glued(std::int64_t n, bool relimit_sticking);
  /// Whether spring i is on the slip keys and sliders: under Coulomb's one coefficient, not
  /// glued or glued under GluedShear::limited. The others (own_springs()) go one by one,
  /// counted in own_sliding_; glued ones under GluedShear::unlimited only stick.
  bool keyed(std::int64_t i) const {
    return !individual_ && (i > glued_ || settings_.glued == GluedShear::limited);
  }
  /// A glued spring on the keys (GluedShear::limited).
  bool keyed_glued(std::int64_t i) const { return glued_keyed_ && i <= glued_; }
  /// Whether keyed glued spring i is in the class of those in tension.
  bool in_tension(std::int64_t i) const {
    return glued_images_.forward_key(i) != std::numeric_limits<double>::infinity();
  }
  /// Puts keyed glued spring i in its class (glued_images_).
  void classify(std::int64_t i, bool tension);
  /// Moves keyed glued spring i to the other class, where d crossed its image.
  void change_class(std::int64_t i);
  /// Whether every keyed glued slider's class is right at d (pressed: g <= d; in tension: g >=
  /// d; a sticking spring's force knows no class). Between events it is (each crossing is an
  /// event); at a d away from the present position (an equilibrium's search, a jump) the sums are
  /// corrected spring by spring.
  bool classes_hold(double indentation) const;
  /// sum over the keyed glued sliders of their exact f_x less what their class's sums give at
  /// d [N]: O(k), where classes_hold(d) is false.
  double misclassed_force(double indentation) const;
  double misclassed_slope(double indentation) const;  ///< the same for dF_x/dd / 2 [N/m]
  /// The same for the sliders' f_x^2 / kx (stored_energy's terms) [J].
  double misclassed_energy(double indentation) const;
  /// The glued spring's keys against p+- (pressed) or u_x (in tension): o -+ r g -+ c/kx, or the
  /// p at which it stuck on the side it slid to (`stuck_from`).
  void insert_keys(std::int64_t i, int stuck_from);
  /// Each keeps the sums, and the keys or sliders of a keyed spring, as spring i joins or leaves
  /// the sticking (sliding) springs; `stuck_from`: the direction of the slide that just ended
  /// (0: none).
  void add_sticking(std::int64_t i, int stuck_from = 0);
  void remove_sticking(std::int64_t i);
  void add_sliding(std::int64_t i);
  /// Spring i (out of its sets) back in under its present limit: it sticks where it is within
  /// it, or slips to it at once over it. Returns the work dissipated on one half [J].
  double settle_at_limit(std::int64_t i);
  void remove_sliding(std::int64_t i);
  std::int64_t first_own_sliding() const;  ///< of own_springs(); 0 when none
  double sliding_stick_radius() const;     ///< stick_radius with a spring sliding
  double advance_sliding(const LinearMotion& motion, double t);  ///< advance, some sliding
  /// next_event's part for the keyed glued springs: the slips and sticks of those in tension,
  /// and the next class change, which goes first at its t.
  void glued_events(const LinearMotion& motion, double end,
                    std::optional<RowFrictionEvent>& first) const;

  FrictionSettings settings_;
  double normal_stiffness_;      ///< E* dx [N/m]
  double tangential_stiffness_;  ///< G* dx [N/m]
  double ratio_;                 ///< r = mu E*/G* [1]
  double spacing_;               ///< dx [m]
  std::int64_t glued_ = 0;
  /// In large pages: 24 MB of fresh memory at 1e6 springs, one fault per 2 MiB, not per 4 KiB.
  std::vector<Spring, LargePageAllocator<Spring>> springs_;
  double indentation_ = 0.0;  ///< d at the present position [m]
  double tangential_ = 0.0;   ///< u_x at the present position [m]

  std::int64_t sticking_ = 0;        ///< springs that stick, glued ones included
  CompensatedSum sticking_offsets_;  ///< their offsets [m]
  /// o_i - r g_i and o_i + r g_i of the sticking springs not glued: flat, no allocation per
  /// spring, since every stick and slip inserts or removes one.
  SlipKeys keys_;
  std::array<IndexSet, 2> sliders_;              ///< not glued, sliding along +x, -x
  std::array<CompensatedSum, 2> slider_images_;  ///< their sums of g_i [m]
  std::int64_t own_sliding_ = 0;  ///< springs sliding that go one by one (own_springs)
  /// Glued springs are on the keys (GluedShear::limited under Coulomb's law).
  bool glued_keyed_;
  /// The sticking glued springs in tension: o + c/kx and o - c/kx, against u_x.
  SlipKeys tension_keys_;
  std::array<IndexSet, 2> tension_sliders_;  ///< glued, in tension, sliding along +x, -x
  /// Their sums of c_i (their whole limit) [N]; with tau_0 > 0 only.
  std::array<CompensatedSum, 2> tension_limits_;
  /// The sums of c_i of the glued sliders of sliders_ (pressed) [N]; with tau_0 > 0 only.
  std::array<CompensatedSum, 2> slider_adhesion_;
  /// What stored_energy needs beyond the forces' sums, kept beside them.
  struct EnergySums {
    CompensatedSum sticking_offset_squares;              ///< [m^2]
    std::array<CompensatedSum, 2> slider_image_squares;  ///< g_i^2 of sliders_ [m^2]
    /// c_i g_i and c_i^2 of the glued ones among sliders_; with tau_0 > 0 only [N m], [N^2].
    std::array<CompensatedSum, 2> slider_adhesion_images;
    std::array<CompensatedSum, 2> slider_adhesion_squares;
    std::array<CompensatedSum, 2> tension_limit_squares;  ///< c_i^2 of tension_sliders_ [N^2]
  };
  EnergySums energy_;
  /// The keyed glued springs by class: a pressed one with keys (+inf, g_i), one in tension with
  /// (g_i, -inf), so that backward_last is the pressed one of the largest image and
  /// forward_first the one in tension of the smallest: the next to cross as d falls (rises).
  SlipKeys glued_images_;
  std::int64_t glued_sliding_ = 0;  ///< keyed glued springs sliding
  /// Every spring in contact goes one by one, with its own law (a law other than Coulomb's).
  bool individual_;
  std::vector<SlipLimit> laws_;  ///< individual_: spring i's law while it is not glued
  /// The springs 1..own_springs() go one by one: every spring in contact under a law of its
  /// own, none else (they are on the keys).
  std::int64_t own_springs() const { return individual_ ? in_contact() : 0; }
};

}  // namespace mdrsim

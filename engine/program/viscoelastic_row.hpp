// A program's row of viscoelastic springs: the indentation moves linearly in time stage by
// stage, or follows a held force or machine end, a spring is pressed from the moment the
// indenter reaches it until its load falls to zero (Ting), and a free spring creeps back and may
// be met again; with an adhesive edge the spring outside the contact glues and the boundary
// spring lets go by the glassy criterion, under a held control with a glassy step of the depth
// (docs/viscoelastic.md).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/base/material.hpp"
#include "engine/model/viscoelastic_edge.hpp"

namespace mdrsim {

/// The springs: i = 1..N at x_i = i dx with images g(x_i), each of stiffness 2 E*(t) dx (both
/// halves of the foundation), E*(t) = E* + sum_j E_j* exp(-t / tau_j).
struct ViscoelasticRowSprings {
  double relaxed_modulus;        ///< E* [Pa] > 0
  std::vector<PronyTerm> terms;  ///< the Prony terms, plane strain
  double spacing;                ///< dx [m]
  std::vector<double> images;    ///< g(x_i) [m], i = 1..N
  /// The adhesive edge (null: no adhesion, every spring only pushes); must outlive the row.
  const ViscoelasticEdge* edge = nullptr;
  /// G* / E*: a glued spring's tangential arms are its normal arms scaled by it (G_inf dx in
  /// parallel with Maxwell arms G_j = E_j G* / E*, the same tau_j); 0: no tangential arms.
  double shear_ratio = 0.0;
  /// Coulomb's mu with [friction]: a pressed spring carries tangential arms too, sticking while
  /// |f_x| <= mu f_z and sliding at the limit otherwise (docs/friction.md); none: they push only.
  std::optional<double> friction = std::nullopt;
};

/// What a segment holds instead of the depth: the constraint a_u d + a_F F = h (fixed load,
/// a machine spring), h moving linearly in time.
struct HeldAxisMotion {
  AffineConstraint constraint;
  double start;  ///< h at the segment's start [N under a fixed load, m under a machine spring]
  double rate;   ///< h' [N/s or m/s]
};

/// A tangential force held instead of u_x (under any normal control): F_x, or a machine spring's
/// end, moves linearly in time and u_x creeps with the glued springs' tangential arms.
struct HeldShearForce {
  double start;  ///< h at the segment's start [N under a fixed load, m under a machine spring]
  double rate;   ///< h' [N/s or m/s]
  /// a_u u_x + a_F F_x = h: a fixed load (0, 1) or a machine spring (1, 1 / k).
  AffineConstraint constraint = {0.0, 1.0};
};

/// A stretch of the program during which the indentation moves at one rate, or, with `held`, a
/// force or a machine end does (the depth then follows the row's creep between events).
struct DriveSegment {
  double duration;  ///< [s] >= 0
  double rate;      ///< d' [m/s]; 0: a hold
  /// The depth at its end [m] where it is known exactly (a stage's held value), so that a
  /// spring whose image is that depth is met; else the start's plus rate times duration.
  std::optional<double> end_depth = std::nullopt;
  std::optional<HeldAxisMotion> held = std::nullopt;
  /// u_x' [m/s], the indenter's tangential displacement moving linearly (under any normal
  /// control: the tangential arms do not enter the depth's equation): a glued spring carries u_x
  /// less the indenter's u_x where it glued.
  double tangential_rate = 0.0;
  /// u_x at its end [m] where it is known exactly; else the start's plus rate times duration.
  std::optional<double> end_tangential = std::nullopt;
  /// F_x held instead (tangential_rate and end_tangential unused): u_x follows the glued
  /// springs' creep between events and steps at a let-go (docs/viscoelastic.md).
  std::optional<HeldShearForce> tangential_force = std::nullopt;
};

/// The row's state at one time.
struct ViscoelasticRowSample {
  double time;                ///< [s]
  double depth;               ///< d [m]
  double force;               ///< F [N], positive pressing
  double contact_radius;      ///< the outermost pressed spring's x [m]; 0 without contact
  std::int64_t pressed;       ///< springs in contact (glued or pressed)
  std::int64_t glued = 0;     ///< springs glued
  double glued_radius = 0.0;  ///< the outermost glued spring's x [m]; 0 without glue
  double tangential_displacement = 0.0;  ///< u_x [m]
  double tangential_force = 0.0;         ///< F_x [N], the glued springs' (pressed ones carry none)
  std::int64_t sliding = 0;              ///< with friction: pressed springs sliding at their limit
  double stick_radius = 0.0;  ///< with friction: inside it every spring in contact sticks [m]
};

struct ViscoelasticRowRun {
  /// The states at the requested times, in their order.
  std::vector<ViscoelasticRowSample> samples;
  /// When the last pressed spring let go, the contact being lost [s]; none if it never was
  /// after being made, or was made again.
  std::optional<double> separation_time;
  std::int64_t touches = 0;   ///< springs met by the indenter (fresh or free)
  std::int64_t releases = 0;  ///< springs whose load fell to zero
  std::int64_t glues = 0;     ///< springs glued by the advancing front
  std::int64_t let_gos = 0;   ///< boundary springs let go
  std::int64_t slips = 0;     ///< with friction: sticking springs that began to slide
  std::int64_t sticks = 0;    ///< with friction: sliding springs that stuck
  std::int64_t events() const { return touches + releases + glues + let_gos + slips + sticks; }
};

/// The row's energy since it started (d = 0, t = 0, every spring at rest), both halves [J]:
/// the machine's work int F dd (int F dh at the end of a machine spring), the energy the springs
/// and arms store now, and what the dashpots dissipated, sum_j int sigma_j^2 / (E_j tau_j) dt dx.
/// Each is summed spring by spring in closed form between the spring's events and the drive's
/// changes of rate, apart from the others, so that machine_work = stored + dissipated_by_bulk
/// closes to rounding. A free spring carries no load, so no work reaches it: what its dashpots
/// dissipate while it creeps is the energy it stores less.
///
/// With an adhesive edge a glue or a let-go is a step of the spring's stretch at one time (the
/// arms' springs take it, the dashpots do not move) with no work of the machine: a let-go of a
/// line load q releases the glassy energy q^2 / (2 E_0), a glue at gap delta costs E_0 delta^2
/// / 2. `surface` is the ring energy pi x dgamma created (let-gos) less destroyed (glues), and
/// `jump_losses` the rest of each step's stored energy change: machine_work = stored + surface +
/// dissipated_by_bulk + jump_losses.
///
/// A tangential drive adds its work int F_x du_x (`tangential_work`), the glued springs'
/// tangential arms their stored energy G_inf w_x^2 / 2 + sum_j s_j^2 / (2 G_j) and their
/// dissipation; a let-go steps the tangential stretch to zero load too, releasing q_x^2 /
/// (2 G_0) (in jump_losses): machine_work + tangential_work = stored + surface +
/// dissipated_by_bulk + jump_losses. Under a held F_x, tangential_work is int F_x du_x along u_x's
/// creep and F_x Du_x at each let-go's glassy step of u_x.
struct ViscoelasticRowEnergy {
  double machine_work = 0.0;
  double tangential_work = 0.0;
  double stored = 0.0;
  double dissipated_by_bulk = 0.0;
  double surface = 0.0;
  double jump_losses = 0.0;
  double dissipated_by_friction = 0.0;
};

/// A touch (a spring met by the indenter and pressed, pushing only), a release (a pressed
/// spring's load fell to zero), a glue (the spring outside the contact glued) or a let-go (the
/// boundary glued spring let go); with friction a slip (a pressed spring reaches its limit and
/// slides) or a stick (a sliding spring's slip velocity turns).
enum class ViscoelasticRowChange { touch, release, glue, let_go, slip, stick };

/// The row run segment by segment, for a caller that reports between them (a program's stages).
class ViscoelasticRowDrive {
 public:
  /// Every spring at rest, d = 0, t = 0. `springs` must outlive the drive.
  explicit ViscoelasticRowDrive(const ViscoelasticRowSprings& springs);
  ~ViscoelasticRowDrive();
  ViscoelasticRowDrive(const ViscoelasticRowDrive&) = delete;
  ViscoelasticRowDrive& operator=(const ViscoelasticRowDrive&) = delete;

  using OnChange = std::function<void(ViscoelasticRowChange, const ViscoelasticRowSample&)>;
  /// Runs `segment` from the present state: `on_change` at each event (a touch's or a glue's
  /// state after it, a release's or a let-go's as the spring leaves, before it is removed),
  /// a sample at each of `sample_times` (ascending, within the segment) into `samples`. With
  /// `stop_at_separation` the segment ends where the last spring in contact leaves; whether it
  /// did is returned.
  bool run(const DriveSegment& segment, bool stop_at_separation,
           std::span<const double> sample_times, std::vector<ViscoelasticRowSample>& samples,
           const OnChange& on_change = {});
  ViscoelasticRowSample sample() const;
  /// Stops run() once the row has taken `most` events in all (a guard against changes that
  /// never settle); whether it did.
  void limit_events(std::int64_t most) { event_limit_ = most; }
  bool limited() const { return limited_; }
  /// Whether the last let-go broke a compressed spring (its tangential load alone): it lost its
  /// glue and stays pressed.
  bool last_let_go_by_shear() const;
  /// Whether a fixed load F_x != 0 lost its last glued spring (run() then stops there).
  bool shear_unheld() const;
  /// The state just before the last change (an on_change may ask for it; kept only where
  /// run() was given one).
  const ViscoelasticRowSample& before_last_change() const { return before_last_change_; }
  /// The energy so far (a pass over the springs).
  ViscoelasticRowEnergy energy();
  /// Under a held control, what the let-gos at the present time did since the last other change
  /// (the glassy steps included; nothing dissipated in the bulk): energy() less it is the energy
  /// where they began, a fixed load's critical point when they lose the contact.
  ViscoelasticRowEnergy let_go_run() const;
  /// As ViscoelasticRowRun's.
  const ViscoelasticRowRun& counts() const { return counts_; }

 private:
  class Row;
  std::unique_ptr<Row> row_;
  ViscoelasticRowRun counts_;
  ViscoelasticRowSample before_last_change_{};
  std::int64_t event_limit_ = std::numeric_limits<std::int64_t>::max();
  bool limited_ = false;
};

/// Under a held force or machine end the springs are coupled through the depth: each event
/// rebuilds d(t) (prony_load_drive.hpp) and is the first of all springs' against it; the
/// machine's work and the pressed springs' dissipation are counted for all of them at once.
/// Runs the segments from d = 0, t = 0 (every spring at rest), reporting at `sample_times`
/// (ascending, within the segments' span). Events (a touch, a release) are located exactly in
/// time, one spring's next event at a time in a queue: between events nothing loops over the
/// springs (the pressed springs' arms are summed per term by SharedDriveArms).
ViscoelasticRowRun run_viscoelastic_row(const ViscoelasticRowSprings& springs,
                                        std::span<const DriveSegment> segments,
                                        std::span<const double> sample_times);

}  // namespace mdrsim

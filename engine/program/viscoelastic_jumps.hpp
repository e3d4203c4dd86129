// The jumps of a viscoelastic row's adhesive edge: glues or let-gos at one time grouped into
// cascades, the jump records, the cascade that lost the glue, and the most tensile state.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/model/contact_snapshot.hpp"
#include "engine/program/viscoelastic_row.hpp"
#include "engine/result/program_records.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

/// A run of glues (inward) or let-gos at one time.
struct ViscoelasticCascade {
  std::string stage;
  double time = 0.0;  ///< [s]
  bool inward = false;
  std::int64_t changes = 0;
  ViscoelasticRowSample before;  ///< the last equilibrium before its first change
  ViscoelasticRowSample after;   ///< the state after its last change
  bool first_by_shear = false;   ///< its first change broke a compressed spring
  bool second_by_shear = false;  ///< its second did
};

/// The state a program reports for a sample of the viscoelastic row.
ContactSnapshot viscoelastic_snapshot(const ViscoelasticRowSample& s);

/// Follows the edge's changes as they come (`by_shear`: a let-go of a compressed spring, by its
/// tangential load alone): a glue or a let-go at the time of the previous one
/// of the same kind joins its cascade (SPEC "Jumps": a cascade at one value of the stage
/// parameter, here the time, is a jump whose critical point is the last equilibrium before
/// it); any other change, or a stage's end, closes it.
class ViscoelasticJumps {
 public:
  /// A change of the row from `before` to `after` in stage `stage`; a closed cascade of more
  /// than one change is returned as a jump, to be reported before this change.
  std::optional<JumpRecord> change(ViscoelasticRowChange change, std::string_view stage,
                                   const ViscoelasticRowSample& before,
                                   const ViscoelasticRowSample& after, bool by_shear = false);
  /// Closes the open cascade (a stage ends); its jump if it was one.
  std::optional<JumpRecord> close();
  /// The open cascade, if any.
  const std::optional<ViscoelasticCascade>& open_cascade() const { return open_; }
  /// A state the program reports (a stage's end): a candidate for the most tensile.
  void observe(const ViscoelasticRowSample& s);

  /// Whether the open cascade has more than one change (a let-go in it is "in cascade").
  bool cascading() const { return open_ && open_->changes > 1; }
  /// The last cascade of let-gos that left no glue, if any.
  const std::optional<ViscoelasticCascade>& glue_loss() const { return glue_loss_; }
  /// The most tensile state seen with springs in contact (before each let-go, at stage ends).
  const std::optional<ViscoelasticRowSample>& most_tensile() const { return most_tensile_; }

  /// The status and critical point of a program whose contact was lost after its glue: the
  /// glue loss's cascade by loss_status's rule on the force scale `force_scale` [N].
  static void decide(const ViscoelasticCascade& loss, double force_scale, RunResult& r);

 private:
  std::optional<ViscoelasticCascade> open_;
  std::optional<ViscoelasticCascade> glue_loss_;
  std::optional<ViscoelasticRowSample> most_tensile_;
};

}  // namespace mdrsim

// The cascades that lost a program's glue or contact, and the status and critical point they
// decide: the program loop's status bookkeeping, apart from its stepping.
#pragma once

#include <cstdint>
#include <optional>

#include "engine/base/zero_scale.hpp"
#include "engine/program/program_cascade.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

class ProgramLosses {
 public:
  /// Notes a cascade that left no glue (`glued_after` 0) or no spring in contact
  /// (`in_contact_after` 0).
  void record(const Cascade& cascade, std::int64_t glued_after, std::int64_t in_contact_after);

  const std::optional<Cascade>& last_contact_loss() const { return last_contact_loss_; }
  const std::optional<Cascade>& last_glue_loss() const { return last_glue_loss_; }

  /// The loss that decides how a lost contact ended. Springs pressed without glue carry no
  /// tension and no tangential force (frictionless): once the glue is gone they lift one by
  /// one as the indenter withdraws, to zero force, whatever the jump that broke the glue.
  /// That jump is the instability (the glue letting go at one parameter value while springs
  /// stay in contact is a jump like any other; Fig. 3a's positive branch, a compressive
  /// critical force), so it decides the status and the critical point: the shorthand, whose
  /// row has no pressed springs, ends there too. Needs a contact loss.
  const Cascade& deciding() const;

  /// Writes the status a loss decides into `r`, with its critical point: nothing where nothing
  /// carried a force or glue when the contact went, else loss_status.hpp's rule on the run's
  /// force scale (`zero`, the same for every row and zoom of the run).
  static void decide(const Cascade& c, const ZeroScale& zero, RunResult& r);

 private:
  std::optional<Cascade> last_contact_loss_;
  std::optional<Cascade> last_glue_loss_;
  std::int64_t contact_losses_ = 0;     ///< cascades that left no spring in contact
  std::int64_t glue_loss_contact_ = 0;  ///< contact_losses_ before the last glue loss
};

}  // namespace mdrsim

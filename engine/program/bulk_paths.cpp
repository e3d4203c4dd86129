// A fixed-grips press glued in one pass, and a tangential ramp slid event by event.
#include "engine/program/bulk_paths.hpp"

#include <algorithm>
#include <cmath>

#include "engine/program/program_step.hpp"

namespace mdrsim {

bool stage_presses_in_bulk(const ProgramRow& row, const StageLine& line, double t_end,
                           bool springs_observed) {
  return line.normal.rate > 0.0 && line.tangential.rate == 0.0 && !springs_observed &&
         !row.friction() && std::isfinite(t_end) && is_fixed_grips(row.normal().constraint) &&
         is_fixed_grips(row.tangential().constraint) && row.adhesive() && row.glues_on_touch();
}

BulkEnd press_in_bulk(StagePosition& at, double t_end, std::int64_t last_spring,
                      RunCounts& counts) {
  constexpr std::int64_t kLeftToTheLoop = 3;
  constexpr std::int64_t kWorthIt = 16;
  const ProgramRow& row = at.row;
  const std::int64_t k = row.glued();
  if (row.in_contact() != k || !row.can_glue(k + 1)) return BulkEnd::not_taken;
  const double d = row.indentation();
  const double d_end = at.line.normal.at(t_end, false) * row.indentation_per_held();
  // Springs whose images rise strictly between d and d_end glue one at a time (a spring whose
  // image does not rise glues with the one before it: a jump, the loop's).
  std::int64_t last = k;
  double image = d;
  while (last < last_spring) {
    const double next = row.image(last + 1);
    if (!(next > image) || !(next < d_end)) break;
    image = next;
    ++last;
  }
  last -= kLeftToTheLoop;
  if (last - k < kWorthIt) return BulkEnd::not_taken;
  // Where the loop would glue spring `last`: the locator's parameter of its image.
  const double vd = row.indentation_per_held() * at.line.normal.rate;
  const double t = std::max(at.t + (row.image(last) - d) * (1.0 / vd), next_parameter(at.t));
  if (!at.advance_to(t)) return BulkEnd::overflow;  // the springs glued before: the trapezoid
  // Each spring glued at no stretch as d reached it: its glue released nothing, and the surface
  // it took is lost (StagePosition::EnergyTally).
  at.work.normal += at.row.glue_through(last);
  counts.events += last - k;
  at.guards.glued_from = last;
  return BulkEnd::taken;
}

bool stage_slides_in_bulk(const ProgramRow& row, const StageLine& line, bool stepping,
                          bool slips_observed) {
  return !stepping && !slips_observed && row.friction() != nullptr && line.normal.rate == 0.0 &&
         line.tangential.rate != 0.0 && is_fixed_grips(row.tangential().constraint);
}

BulkEnd slide_in_bulk(StagePosition& at, double t_end, std::int64_t events_until,
                      std::int64_t row_end, std::int64_t cap, RunCounts& counts) {
  ProgramRow& row = at.row;
  const FrictionRow* friction = row.friction();
  if (row.glued() > 0 || !friction->slides_in_bulk()) return BulkEnd::not_taken;
  const std::int64_t m = row.in_contact();
  const double d = row.indentation();
  // Nothing else due now (a spring to touch, lift or glue is the loop's), and nothing can be.
  if (m == 0 || (row.adhesive() && row.can_glue(1)) || row.image(m) - d > 0.0 ||
      (m < row_end && row.image(m + 1) - d <= 0.0)) {
    return BulkEnd::not_taken;
  }
  std::int64_t at_this_t = 0;
  bool applied = false;
  while (counts.events <= events_until) {
    const auto event = friction->next_event(
        ChangeLocator::motion(row, at.t, at.line.normal, at.line.tangential), t_end);
    if (!event) break;
    if (event->event.at > at.t) {
      const double t = std::max(event->event.at, next_parameter(at.t));
      if (!(t < t_end)) break;  // the stage's end is the loop's
      if (!at.advance_to(t)) return BulkEnd::overflow;
      at_this_t = 0;
    }
    // Rounding that keeps one parameter value's slips and sticks from settling (as a cascade).
    if (++at_this_t > cap) return BulkEnd::unending;
    row.apply_friction(*event);
    ++counts.events;
    applied = true;
  }
  return applied ? BulkEnd::taken : BulkEnd::not_taken;
}

}  // namespace mdrsim

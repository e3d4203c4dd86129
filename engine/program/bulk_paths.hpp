// The program loop's two shortcuts: a press that only glues springs as it reaches them, taken
// in one pass, and a tangential ramp whose only changes are slips and sticks, taken event by
// event without looking for changes that cannot come. Each leaves the same row, work and
// counts as the loop would.
#pragma once

#include <cstdint>

#include "engine/program/program_front.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/stage_position.hpp"
#include "engine/result/run_counts.hpp"

namespace mdrsim {

/// How a bulk path ended.
enum class BulkEnd {
  not_taken,  ///< it does not apply here: the loop takes the next change itself
  taken,      ///< springs glued, or slips and sticks applied: the loop observes the state
  overflow,   ///< the work left the range of a double on the way
  unending,   ///< one parameter value's slips and sticks did not settle
};

/// Fixed grips pressing at a held u_x, no friction, the front gluing each spring as it
/// touches (dgamma_a = 0), nobody observing single springs (their events are wanted): whether
/// a stage presses so, as far as its row lets it (press_in_bulk).
bool stage_presses_in_bulk(const ProgramRow& row, const StageLine& line, double t_end,
                           bool springs_observed);

/// Every spring in contact glued: each event is one spring glued, in the order of the images,
/// and nothing else happens (a glued spring pressed further holds: its margin does not fall
/// with its elongation, criterion.hpp, and the locator asks no let-go here either). Every such
/// spring up to `last_spring` but the last few before t_end glues in one pass, the stage's
/// work on them in closed form (ProgramRow::glue_through); the loop takes the rest, with
/// everything it records.
BulkEnd press_in_bulk(StagePosition& at, double t_end, std::int64_t last_spring, RunCounts& counts);

/// Fixed grips moving u_x at a still normal held value, by the event method, nobody observing
/// single slips: d stays (the axes are uncoupled). Whether a stage slides so, as far as its
/// row lets it (slide_in_bulk).
bool stage_slides_in_bulk(const ProgramRow& row, const StageLine& line, bool stepping,
                          bool slips_observed);

/// Nothing glued nor able to glue, every spring on the keys (FrictionRow::slides_in_bulk),
/// nothing to touch or lift below `row_end`: no spring touches, lifts, glues or lets go, and
/// the only changes are the friction row's own events, which it locates exactly as the loop
/// does (FrictionRow::next_event, in the same order). Each is applied where the loop would
/// apply it, with the same advance and work, until counts.events passes `events_until` or
/// the stage's end comes; more than `cap` at one parameter value do not settle.
BulkEnd slide_in_bulk(StagePosition& at, double t_end, std::int64_t events_until,
                      std::int64_t row_end, std::int64_t cap, RunCounts& counts);

}  // namespace mdrsim

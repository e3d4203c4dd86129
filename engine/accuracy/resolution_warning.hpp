// The warnings of a fixed row that does not resolve what it reports: one rule for the
// shorthand and programs.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/result/run_result.hpp"

namespace mdrsim {

/// Fewer springs than this in contact at the critical point do not resolve it.
inline constexpr std::int64_t kResolvedSprings = 100;

/// What a run's row spans, for the warnings: `springs` springs across `radius` [m], which
/// the text calls `radius_name` ("glued", or "largest" for a program's a_max).
struct ResolvedRow {
  std::int64_t springs;
  double radius;
  const char* radius_name;
  const char* remedy;  ///< what resolves it: "discretization.rtol zooms in on it"
};

/// "the critical point has only n springs in contact ...", where the reported critical point
/// has fewer than kResolvedSprings (and fewer than the row's) springs in contact: its error
/// is then of the order of the spacing and no estimate from rows that coarse bounds it (a
/// 30 degree cone's compliant fold on 2 to 15 springs missed by up to 33 %).
std::optional<std::string> unresolved_critical(const RunResult& result, const ResolvedRow& row);

/// "the contact peeled off down to its last spring ...": a row that ends an adhesive contact in a
/// smooth peel cannot tell it from a fold below its first spring (a 30 degree cone's compliant
/// pull on 512 springs peels smoothly; on 16384 it folds at -2.6e-8 N).
std::optional<std::string> unresolved_smooth_peel(const RunResult& result, const ResolvedRow& row,
                                                  bool adhesive);

/// A program `completed` whose row never brought a spring into contact (nothing was loaded): with
/// adhesion the first spring needs touch, which a row of one spring at an adhesive front
/// never reaches.
std::optional<std::string> never_in_contact(const RunResult& result, const ResolvedRow& row);

}  // namespace mdrsim

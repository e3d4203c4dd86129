// Reads [material]'s work_of_adhesion and approach_work_of_adhesion: a number, a table of
// dgamma(r) (inline or CSV) or a sinusoid.
#pragma once

#include <memory>

#include "engine/base/material.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// One work of adhesion as the scene gives it: its scale value (the number, the mean, or the
/// table's value at r = 0) and, where it varies, dgamma(r).
struct ReadAdhesion {
  double scale_value = 0.0;
  std::shared_ptr<const RadialAdhesion> by_radius;
};

/// Reads `key` of the [material] table `t`: a number >= 0, or a table with r and value
/// (arrays), file (a CSV with columns r,value), or mean, amplitude and wavelength. Absent:
/// `fallback` when given, else an error. Every bad point is reported at its key with its index
/// and radius (file, line and key).
ReadAdhesion read_adhesion(TomlReader& t, std::string_view key, const char* help,
                           std::optional<double> fallback);

/// Puts both into `m` and checks 0 <= dgamma_a(r) <= dgamma(r) at every radius (docs/scene.md),
/// failing at approach_work_of_adhesion with the first radius where it does not hold.
void apply_adhesion(TomlReader& t, const ReadAdhesion& receding, const ReadAdhesion& approach,
                    Material& m);

}  // namespace mdrsim

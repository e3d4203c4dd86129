// The tables a scene read from files (a profile's, a work of adhesion's), carried in the
// resolved scene so that the result reruns without the files.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "profiles/two_column_file.hpp"

namespace mdrsim {

/// Writes `table` = {r, f, fnv1a} into the resolved `profile` object: the points read from
/// `path` (the file the profile was built from) and the 64-bit FNV-1a of its bytes, in 16 hex
/// digits, which tells whether a CSV on disk is the one used. `file` stays, for the record.
void embed_profile_table(nlohmann::json& profile, const std::string& path);

/// The record `table` = {r, value, fnv1a} of a work of adhesion read from the CSV `path`
/// (its columns r,value as read_two_column_file returned them), as embed_profile_table writes a
/// profile's.
nlohmann::json adhesion_table_record(const std::string& path, const TwoColumnFile& table);

/// Reads a resolved scene's embedded tables (`scene` is the `scene` of a result, or a scene
/// object): the profile's (columns r, f) and each work of adhesion's given as a file (r,
/// value). While `file` holds the very bytes hashed, the file itself is read (and the
/// rerun's resolved scene is the same); when it is gone or changed, the columns come from
/// `table` instead, with a warning naming `source_name` and the key. `table` is removed either
/// way. A holder without a `table` object of both columns is left alone.
void use_embedded_table(nlohmann::json& scene, const std::string& source_name);

}  // namespace mdrsim

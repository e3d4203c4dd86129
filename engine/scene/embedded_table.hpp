// A profile table read from a file, carried in the resolved scene so that the result reruns
// without the file.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace mdrsim {

/// Writes `table` = {r, f, fnv1a} into the resolved `profile` object: the points read from
/// `path` (the file the profile was built from) and the 64-bit FNV-1a of its bytes, in 16 hex
/// digits, which tells whether a CSV on disk is the one used. `file` stays, for the record.
void embed_profile_table(nlohmann::json& profile, const std::string& path);

/// Reads a resolved scene's embedded table (`scene` is the `scene` of a result, or a scene
/// object): while `profile.file` holds the very bytes hashed, the file is read as before
/// (and the rerun's resolved scene is the same); when it is gone or changed, `profile.r`
/// and `profile.f` come from `profile.table` instead, with a warning naming `source_name`.
/// `table` is removed either way. A profile without a `table` object of arrays r and f is
/// left alone.
void use_embedded_table(nlohmann::json& scene, const std::string& source_name);

}  // namespace mdrsim

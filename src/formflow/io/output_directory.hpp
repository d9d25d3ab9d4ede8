// SPDX-License-Identifier: MIT
// Checking the output directory before a solve, so that a bad -o costs nothing.
#pragma once

#include <filesystem>
#include <span>
#include <string>

namespace formflow::io {

/// Checks that a result set with the files `names` can be published into
/// `directory` (io/result_set.hpp), before anything is solved:
///  - an existing `directory` is a directory (or a link to one) in which
///    formflow can create entries, and none of `names` there is a directory;
///  - a missing `directory` has a nearest existing ancestor that is such a
///    directory (the rest is created when the results are written).
/// "Can create entries" is tried, not guessed from mode bits (root, read-only
/// mounts, ACLs): a probe directory is made with mkdtemp and removed at once,
/// so nothing stays behind. Throws InputError (file "-o", key = the path)
/// saying what is wrong and what would be valid.
void check_output_directory(const std::filesystem::path& directory,
                            std::span<const std::string> names);

} // namespace formflow::io

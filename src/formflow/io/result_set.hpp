// SPDX-License-Identifier: MIT
// Publishing the files of one run into an output directory as a whole: all new, or all old.
#pragma once

#include "formflow/core/stop_request.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace formflow::io {

/// One file of a result set: its name in the output directory and its contents.
struct ResultFile {
  std::string name;
  std::string contents;
};

/// The prefix of the private staging directory publish_result_set makes in
/// the output directory (`.formflow-staging-XXXXXX`, mode 0700).
inline constexpr const char* staging_prefix = ".formflow-staging-";

/// Publishes `files` into `directory` (created if missing) so that a reader
/// finds either the previous set or the complete new one, never a mix:
///  1. every file is written into a private staging directory made by
///     mkdtemp(3) inside `directory` (unpredictable name, mode 0700, files
///     created O_EXCL|O_NOFOLLOW and synced), checking `stop_requested`
///     before each file;
///  2. the commit renames (rename(2), one file system): the old `commit_name`
///     first moves aside, so the set counts as absent while it changes; every
///     other file moves into place, old files named in `known_names` that the
///     new set lacks move aside, and `commit_name` (summary.json) moves in last;
///  3. the staging directory, with whatever was moved aside, is removed.
/// A failure before the commit (full disk, a stop request) leaves `directory`
/// exactly as it was; a failure inside the commit moves every file back. An
/// entry in the way that is a directory is an error, never moved or removed.
/// Throws Stopped when `stop_requested` answered true (nothing changed),
/// std::runtime_error naming the file and the reason otherwise.
/// `commit_name` must be one of `files`.
void publish_result_set(const std::filesystem::path& directory,
                        const std::vector<ResultFile>& files, const std::string& commit_name,
                        std::span<const std::string> known_names,
                        const StopRequested& stop_requested = {});

} // namespace formflow::io

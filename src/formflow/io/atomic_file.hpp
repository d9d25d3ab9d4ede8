// SPDX-License-Identifier: MIT
// Creating files that no planted link can redirect, and replacing one file atomically.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace formflow::io {

/// Creates the file `name` in the open directory `directory_fd` and writes
/// `contents` to it: O_CREAT|O_EXCL|O_NOFOLLOW, so an entry already there (a
/// planted symlink included) is an error and nothing outside is ever
/// written; the data are flushed to the disk (fdatasync) before it returns,
/// so a full disk shows up here and not after a later rename. On any error the
/// new file is removed and OutputError names `shown_path` and the
/// reason ("No space left on device"). Mode 0666 minus the umask, like any new file.
void write_new_file(int directory_fd, const std::string& name, std::string_view contents,
                    const std::filesystem::path& shown_path);

/// Writes `contents` to a temporary file beside `path` with an unpredictable
/// name (`<name>.tmp.XXXXXX`, created exclusively, links not followed), then
/// renames it to `path`, replacing any existing file. On failure the temporary
/// is removed, `path` is left as it was, and OutputError names the file.
/// The parent directory must exist.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

/// Same, for contents produced by `writer`; if `writer` throws, nothing is
/// created and the exception propagates.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer);

} // namespace formflow::io

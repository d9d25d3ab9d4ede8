// SPDX-License-Identifier: MIT
// Writing a file so that readers see either nothing or the complete contents.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace formflow::io {

/// The temporary name `path` is written under before the rename:
/// `<dir>/<name>.tmp.<pid>`, in the same directory so the rename stays on one
/// file system (and is therefore atomic on POSIX).
std::filesystem::path temporary_path(const std::filesystem::path& path);

/// Writes whatever `writer` puts into the (binary) stream to the temporary
/// name, then renames it to `path`, replacing any existing file. If `writer`
/// throws or the stream fails, the temporary file is removed, `path` is left
/// as it was, and the exception propagates (a stream failure throws
/// std::runtime_error naming the file). The parent directory must exist.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer);

/// Same, for contents that are already in memory (text or bytes).
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

} // namespace formflow::io

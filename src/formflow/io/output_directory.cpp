// SPDX-License-Identifier: MIT
// check_output_directory: is a directory, can take new entries, nothing in the way.
#include "formflow/io/output_directory.hpp"

#include "formflow/core/error.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <system_error>
#include <utility>

namespace formflow::io {

namespace {

constexpr const char* valid =
    "give -o a directory, existing or to be created, that formflow may write into";

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& message,
                         const std::string& hint = valid) {
  throw InputError("-o", 0, path.string(), message, hint);
}

/// What kind of entry `path` is, without following a final link; `path`
/// itself when the error is about it (a name too long, a loop of links).
std::filesystem::file_status status_of(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::symlink_status(path, error);
  if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
    refuse(path, "cannot be examined: " + error.message());
  return status;
}

std::string kind_of(std::filesystem::file_type type) {
  switch (type) {
  case std::filesystem::file_type::regular: return "a regular file";
  case std::filesystem::file_type::symlink: return "a broken symbolic link";
  case std::filesystem::file_type::fifo: return "a named pipe";
  case std::filesystem::file_type::socket: return "a socket";
  case std::filesystem::file_type::block:
  case std::filesystem::file_type::character: return "a device";
  default: return "not a directory";
  }
}

/// Whether new entries can be made in the existing directory `directory`:
/// makes and removes one (mode 0700, unpredictable name).
void probe_writable(const std::filesystem::path& directory, const std::filesystem::path& asked) {
  std::string pattern = (directory / ".formflow-probe-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    const std::string reason = std::generic_category().message(errno);
    refuse(asked, directory == asked ? "formflow cannot create files in it (" + reason + ")"
                                     : "cannot be created: formflow cannot create entries in " +
                                           directory.string() + " (" + reason + ")");
  }
  ::rmdir(pattern.c_str());
}

} // namespace

void check_output_directory(const std::filesystem::path& directory,
                            std::span<const std::string> names) {
  if (directory.empty()) refuse(directory, "is empty");
  // The nearest part of the path that exists: the directory itself or an ancestor.
  std::filesystem::path existing = directory;
  // A dangling link exists as a link (symlink_status): it stops the walk and is refused below.
  while (!existing.empty() && !std::filesystem::exists(status_of(existing))) {
    std::filesystem::path parent = existing.parent_path();
    if (parent == existing) refuse(directory, "has no existing ancestor directory");
    existing = std::move(parent);
  }
  if (existing.empty()) existing = ".";
  std::error_code error;
  const std::filesystem::file_status target = std::filesystem::status(existing, error);
  if (!std::filesystem::is_directory(target)) {
    const std::filesystem::file_type type =
        error ? std::filesystem::file_type::symlink : target.type();
    refuse(directory, existing == directory
                          ? "is " + kind_of(type) + ", not a directory"
                          : "cannot be created: " + existing.string() + " is " + kind_of(type));
  }
  probe_writable(existing, directory);
  if (existing != directory) return; // nothing inside yet that could be in the way
  for (const std::string& name : names)
    if (std::filesystem::is_directory(status_of(directory / name)))
      refuse(directory, name + " in it is a directory, and formflow writes a file of that name",
             "remove or rename " + (directory / name).string() + ", or choose another -o");
}

} // namespace formflow::io

// SPDX-License-Identifier: MIT
// An owned POSIX file descriptor, and the errno → exception helper the file code shares.
#pragma once

#include <filesystem>
#include <string>

namespace formflow::io {

/// Throws std::system_error for `error_number` with `what` in front of the reason.
[[noreturn]] void throw_errno(const std::string& what, int error_number);

/// Owns one file descriptor and closes it when it goes (errors ignored there:
/// call close_or_throw() where a failed close matters, i.e. after writing).
class FileDescriptor {
public:
  explicit FileDescriptor(int fd = -1) : fd_(fd) {}
  ~FileDescriptor();
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  FileDescriptor& operator=(FileDescriptor&& other) noexcept;
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;

  int get() const { return fd_; }
  /// Closes now; throws std::system_error if close(2) reports an error (a
  /// delayed write error on some file systems).
  void close_or_throw();

private:
  int fd_;
};

/// Opens `path` as a directory (O_DIRECTORY | O_CLOEXEC) for the *at() calls.
/// Throws std::system_error naming the path.
FileDescriptor open_directory(const std::filesystem::path& path);

/// fsync(2) of an open directory, so that renames in it survive a crash;
/// file systems that cannot sync a directory (EINVAL) are accepted.
void sync_directory(const FileDescriptor& directory, const std::filesystem::path& shown_path);

} // namespace formflow::io

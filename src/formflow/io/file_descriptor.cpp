// SPDX-License-Identifier: MIT
// FileDescriptor, open_directory, sync_directory.
#include "formflow/io/file_descriptor.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace formflow::io {

void throw_errno(const std::string& what, int error_number) {
  throw std::system_error(error_number, std::generic_category(), what);
}

FileDescriptor::~FileDescriptor() {
  if (fd_ >= 0) ::close(fd_);
}

FileDescriptor& FileDescriptor::operator=(FileDescriptor&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

void FileDescriptor::close_or_throw() {
  const int fd = fd_;
  fd_ = -1;
  // close(2) is not retried on EINTR: on Linux the descriptor is gone either way.
  if (fd >= 0 && ::close(fd) != 0 && errno != EINTR) throw_errno("cannot close", errno);
}

FileDescriptor open_directory(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw_errno("cannot open directory " + path.string(), errno);
  return FileDescriptor(fd);
}

void sync_directory(const FileDescriptor& directory, const std::filesystem::path& shown_path) {
  if (::fsync(directory.get()) != 0 && errno != EINVAL && errno != EROFS)
    throw_errno("cannot sync directory " + shown_path.string(), errno);
}

} // namespace formflow::io

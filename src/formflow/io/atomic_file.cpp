// SPDX-License-Identifier: MIT
// Exclusive file creation relative to a directory descriptor, and temporary file + rename.
#include "formflow/io/atomic_file.hpp"

#include "formflow/io/file_descriptor.hpp"
#include "formflow/io/output_error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <random>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace formflow::io {

namespace {

/// Writes all of `contents`, resuming after a signal or a short write.
void write_all(int fd, std::string_view contents) {
  while (!contents.empty()) {
    const ssize_t written = ::write(fd, contents.data(), contents.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      throw_errno("cannot write", errno);
    }
    contents.remove_prefix(static_cast<std::size_t>(written));
  }
}

/// Six random letters: the name of a temporary must not be guessable, or a
/// link planted there in advance would be a way to make us fail (O_EXCL stops
/// it from redirecting the write, not from blocking it).
std::string random_suffix() {
  static constexpr char letters[] =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device device;
  std::uniform_int_distribution<std::size_t> pick(0, sizeof(letters) - 2);
  std::string suffix(6, 'a');
  for (char& letter : suffix) letter = letters[pick(device)];
  return suffix;
}

} // namespace

void write_new_file(int directory_fd, const std::string& name, std::string_view contents,
                    const std::filesystem::path& shown_path) {
  const int fd = ::openat(directory_fd, name.c_str(),
                          O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0)
    throw OutputError("cannot create " + shown_path.string() + ": " +
                      std::generic_category().message(errno));
  FileDescriptor file(fd);
  try {
    write_all(file.get(), contents);
    // fdatasync: delayed allocation and network file systems report a full disk only here.
    if (::fdatasync(file.get()) != 0 && errno != EINVAL) throw_errno("cannot write", errno);
    file.close_or_throw();
  } catch (const std::system_error& error) {
    ::unlinkat(directory_fd, name.c_str(), 0);
    throw OutputError("cannot write " + shown_path.string() + ": " + error.code().message());
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : ".";
  const FileDescriptor directory = open_directory(parent);
  const std::string name = path.filename().string();
  // Retry on the (astronomically unlikely) collision with an existing name, as mkstemp does.
  for (int attempt = 0;; ++attempt) {
    const std::string temporary = name + ".tmp." + random_suffix();
    try {
      write_new_file(directory.get(), temporary, contents, parent / temporary);
    } catch (const OutputError&) {
      struct stat existing;
      if (attempt < 100 &&
          ::fstatat(directory.get(), temporary.c_str(), &existing, AT_SYMLINK_NOFOLLOW) == 0)
        continue;
      throw;
    }
    if (::renameat(directory.get(), temporary.c_str(), directory.get(), name.c_str()) != 0) {
      const int error = errno;
      ::unlinkat(directory.get(), temporary.c_str(), 0);
      throw OutputError("cannot rename " + (parent / temporary).string() + " to " + path.string() +
                        ": " + std::generic_category().message(error));
    }
    return;
  }
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer) {
  // Rendered in memory first: a writer that throws leaves nothing on the disk at all.
  std::ostringstream buffer(std::ios::binary);
  writer(buffer);
  write_file_atomically(path, buffer.view());
}

} // namespace formflow::io

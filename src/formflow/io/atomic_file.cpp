// SPDX-License-Identifier: MIT
// Temporary file + rename, with the temporary removed on every failure path.
#include "formflow/io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace formflow::io {

std::filesystem::path temporary_path(const std::filesystem::path& path) {
  // The pid keeps two runs writing into the same directory from sharing a temporary.
  std::filesystem::path result = path;
  result += ".tmp." + std::to_string(static_cast<long>(::getpid()));
  return result;
}

namespace {

/// Removes the temporary file unless released; errors are swallowed because
/// this runs while another exception is already on its way out.
class TemporaryGuard {
public:
  explicit TemporaryGuard(std::filesystem::path path) : path_(std::move(path)) {}
  ~TemporaryGuard() {
    if (armed_) {
      std::error_code ignored;
      std::filesystem::remove(path_, ignored);
    }
  }
  TemporaryGuard(const TemporaryGuard&) = delete;
  TemporaryGuard& operator=(const TemporaryGuard&) = delete;
  void release() { armed_ = false; }

private:
  std::filesystem::path path_;
  bool armed_ = true;
};

[[noreturn]] void fail_writing(const std::filesystem::path& path, int error_number) {
  std::string reason = error_number != 0 ? std::strerror(error_number) : "stream error";
  throw std::runtime_error("cannot write " + path.string() + ": " + reason);
}

} // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer) {
  const std::filesystem::path temporary = temporary_path(path);
  TemporaryGuard guard(temporary);
  {
    errno = 0;
    std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
    if (!stream) fail_writing(temporary, errno);
    writer(stream);
    stream.flush();
    // Checked before close() too: a full disk shows up here, and a failed close is caught below.
    if (!stream) fail_writing(temporary, errno);
    stream.close();
    if (!stream) fail_writing(temporary, errno);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
    throw std::runtime_error("cannot rename " + temporary.string() + " to " + path.string() + ": " +
                             error.message());
  guard.release();
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path, [contents](std::ostream& stream) {
    stream.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  });
}

} // namespace formflow::io

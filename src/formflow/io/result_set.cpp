// SPDX-License-Identifier: MIT
// publish_result_set: staging directory, then a commit of renames that can be undone.
#include "formflow/io/result_set.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/atomic_file.hpp"
#include "formflow/io/file_descriptor.hpp"
#include "formflow/io/output_error.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <system_error>

namespace formflow::io {

namespace {

std::string reason(int error_number) {
  return std::generic_category().message(error_number);
}

/// What is at `name` in the open directory, without following a link there.
enum class Entry { Missing, Directory, Other };
Entry entry_at(int directory_fd, const std::string& name) {
  struct stat info;
  if (::fstatat(directory_fd, name.c_str(), &info, AT_SYMLINK_NOFOLLOW) != 0) return Entry::Missing;
  return S_ISDIR(info.st_mode) ? Entry::Directory : Entry::Other;
}

/// The private directory the new files are written into; removed with
/// everything in it (new files not moved out, old ones moved aside) when it goes.
class StagingDirectory {
public:
  explicit StagingDirectory(const std::filesystem::path& directory) {
    // mkdtemp: an unpredictable name, created exclusively (a link planted there
    // makes it pick another name, never follow it), mode 0700.
    std::string pattern = (directory / (std::string(staging_prefix) + "XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw OutputError("cannot create a staging directory in " + directory.string() + ": " +
                        reason(errno));
    path_ = pattern;
    try {
      fd_ = open_directory(path_);
    } catch (...) {
      ::rmdir(path_.c_str());
      throw;
    }
  }
  ~StagingDirectory() {
    std::error_code ignored; // runs while another exception may be on its way out
    std::filesystem::remove_all(path_, ignored);
  }
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;
  int fd() const { return fd_.get(); }

private:
  std::filesystem::path path_;
  FileDescriptor fd_;
};

/// The renames of a commit, in order; unless finished, the destructor undoes
/// them in reverse, so a failed commit puts the previous files back.
class CommitJournal {
public:
  CommitJournal(int output_fd, int staging_fd, const std::filesystem::path& directory)
      : output_(output_fd), staging_(staging_fd), directory_(directory) {}
  ~CommitJournal() {
    for (auto move = moves_.rbegin(); move != moves_.rend(); ++move)
      if (move->aside)
        ::renameat(staging_, aside_name(move->name).c_str(), output_, move->name.c_str());
      else
        ::renameat(output_, move->name.c_str(), staging_, move->name.c_str());
  }
  CommitJournal(const CommitJournal&) = delete;
  CommitJournal& operator=(const CommitJournal&) = delete;

  /// output/name → staging/previous.name, if there is such an entry. A
  /// directory that appeared there since the check is refused: moved aside it
  /// would be removed with the staging directory.
  void move_aside(const std::string& name) {
    const Entry entry = entry_at(output_, name);
    if (entry == Entry::Missing) return;
    if (entry == Entry::Directory)
      throw OutputError((directory_ / name).string() +
                        " is a directory: formflow replaces only files there; the previous "
                        "results are back in place");
    rename(output_, name, staging_, aside_name(name),
           "cannot move the previous " + name + " aside");
    moves_.push_back({true, name});
  }
  /// staging/name → output/name.
  void move_in(const std::string& name) {
    rename(staging_, name, output_, name, "cannot move " + name + " into place");
    moves_.push_back({false, name});
  }
  void finish() { moves_.clear(); }

private:
  struct Move {
    bool aside;
    std::string name;
  };
  static std::string aside_name(const std::string& name) { return "previous." + name; }
  void rename(int from_fd, const std::string& from, int to_fd, const std::string& to,
              const std::string& what) const {
    if (::renameat(from_fd, from.c_str(), to_fd, to.c_str()) != 0)
      throw OutputError(what + " in " + directory_.string() + ": " + reason(errno) +
                        "; the previous results are back in place");
  }

  int output_, staging_;
  std::filesystem::path directory_;
  std::vector<Move> moves_;
};

void create_output_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw OutputError("cannot create the output directory " + directory.string() + ": " +
                      error.message());
}

} // namespace

void publish_result_set(const std::filesystem::path& directory,
                        const std::vector<ResultFile>& files, const std::string& commit_name,
                        std::span<const std::string> known_names,
                        const StopRequested& stop_requested) {
  [[maybe_unused]] const auto commit = std::find_if(
      files.begin(), files.end(), [&](const ResultFile& file) { return file.name == commit_name; });
  FF_ASSERT(commit != files.end(), "the commit file is part of the set");
  if (is_stop_requested(stop_requested)) throw Stopped("stopped before writing results");
  create_output_directory(directory);
  const FileDescriptor output = open_directory(directory);

  // Every name the commit touches: the commit file first (its absence marks the
  // set as changing), then the new files, then old ones the new set lacks.
  std::vector<std::string> touched{commit_name};
  auto touch = [&touched](const std::string& name) {
    if (std::find(touched.begin(), touched.end(), name) == touched.end()) touched.push_back(name);
  };
  for (const ResultFile& file : files) touch(file.name);
  for (const std::string& name : known_names) touch(name);
  // A directory in the way is refused, never moved aside (it would be removed with the staging).
  for (const std::string& name : touched)
    if (entry_at(output.get(), name) == Entry::Directory)
      throw OutputError((directory / name).string() +
                        " is a directory: formflow replaces only files there");

  const StagingDirectory staging(directory);
  for (const ResultFile& file : files) {
    if (is_stop_requested(stop_requested))
      throw Stopped("stopped before writing " + (directory / file.name).string());
    write_new_file(staging.fd(), file.name, file.contents, directory / file.name);
  }
  if (is_stop_requested(stop_requested)) throw Stopped("stopped before moving the results in");

  // From here on no stop request is honoured: the renames take microseconds,
  // and a set half moved in is what this function exists to prevent.
  CommitJournal journal(output.get(), staging.fd(), directory);
  for (const std::string& name : touched) journal.move_aside(name);
  for (const ResultFile& file : files)
    if (file.name != commit_name) journal.move_in(file.name);
  journal.move_in(commit_name);
  journal.finish();
  sync_directory(output, directory);
}

} // namespace formflow::io

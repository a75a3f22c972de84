#pragma once

// Output files as Unix tools write them. A new or regular file (through any
// symbolic links: the link stays a link) is written to a temporary file in
// its directory and renamed over it when complete, so readers see the old
// file or the whole new one and a failed or interrupted run leaves the old
// one untouched. Anything else that exists (a device, a FIFO, /dev/stdout)
// is written directly, and its write errors are reported. A new file gets
// 0666 less the umask; a replaced file keeps its mode and, where allowed,
// its owner.

#include <functional>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sweetspot::io {

// A file that could not be written: what() is "cannot write PATH: REASON".
class WriteError : public std::runtime_error {
 public:
  WriteError(const std::string& path, const std::string& reason);
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

// A temporary file ".<start of name>.XXXXXX" (mkstemp, mode 0600) in
// `directory`: short whatever the length of `name`, so it fits in NAME_MAX
// wherever `name` does. While it exists it is on the list that
// remove_temporaries_on_signals() empties. The destructor removes it unless
// rename_over() moved it into place. Throws WriteError naming `for_path`.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& directory, std::string_view name, const std::string& for_path);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  // Flushes to disk, closes and renames over `target`; throws WriteError naming `for_path`.
  void rename_over(const std::string& target);

 private:
  std::string path_;
  std::string for_path_;
  int fd_ = -1;
  int slot_ = -1;  // in the list of temporaries removed on a signal
};

// One output being written to `path` (see the top of this file).
class OutputFile {
 public:
  // Resolves `path` and opens its temporary file or, for a target that is not
  // a regular file, the target itself (a FIFO waits for its reader). Throws
  // WriteError for a directory, a missing folder, no permission, ...
  explicit OutputFile(const std::string& path);
  ~OutputFile();  // without commit(): the temporary file is removed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // True when the target is written in place (not a regular file).
  bool direct() const { return !temporary_.has_value(); }
  // The descriptor written: the temporary file's, or the target's.
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  // Writes all of `bytes`; throws WriteError with strerror (ENOSPC, EPIPE, ...).
  void write(std::string_view bytes);
  // Completes the output: the temporary file gets its mode and replaces the
  // target; a direct target is closed. Throws WriteError.
  void commit();

 private:
  std::string path_;    // as given, for messages
  std::string target_;  // symbolic links followed
  std::optional<TemporaryFile> temporary_;
  int fd_ = -1;
  bool owns_fd_ = false;
  bool existed_ = false;
  unsigned mode_ = 0;
  unsigned uid_ = 0;
  unsigned gid_ = 0;
};

// Writes `content` to `path` through OutputFile. Throws WriteError.
void write_file_atomically(const std::string& path, std::string_view content);

// The same for output produced as a stream (a sweep, a batch): `write` fills
// the output, which replaces `path` only when complete. A write error (a
// full disk) ends `write` at once with WriteError; if `write` throws, the
// temporary file is removed and the exception goes on.
void write_stream_atomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write);

// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE (those not
// ignored) that remove every temporary file in progress and then re-raise
// the signal with its default action, so that the exit status is the
// signal's. Call once from main().
void remove_temporaries_on_signals();

// The directory for scratch files (TMPDIR, else /tmp).
std::string scratch_directory();

}  // namespace sweetspot::io

#pragma once

// Output files as Unix tools write them. A new or regular file (through any
// symbolic links: the link stays a link) is written to a temporary file in
// its directory and renamed over it when complete, so readers see the old
// file or the whole new one and a failed or interrupted run leaves the old
// one untouched. Anything else that exists (a device, a FIFO, /dev/stdout;
// "-" names standard output) is written directly, and its write errors are reported. A new file
// gets 0666 less the umask; a replaced file keeps its mode and, where allowed, its owner.

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

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

// The folder of a path as written ("." for a bare name, "/" at the root) and
// its last component.
std::string directory_of(const std::string& path);
std::string name_of(const std::string& path);

// Writes `content` to `path` through OutputFile. Throws WriteError.
void write_file_atomically(const std::string& path, std::string_view content);

// The same for output produced as a stream (a sweep, a batch): `write` fills
// the output, which replaces `path` only when complete. A write error (a
// full disk) ends `write` at once with WriteError; if `write` throws, the
// temporary file is removed and the exception goes on.
void write_stream_atomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write);

// A command's outputs, written all or none: each file is written to its
// temporary file as it is added (a device, a FIFO or standard output is
// written directly, at once) and commit() renames them all into place, so
// that a failure before commit() (a plot gnuplot cannot draw, a full disk)
// leaves every file as it was. Throws WriteError.
class OutputSet {
 public:
  void write(const std::string& path, std::string_view content);
  // `write` fills the output (as write_stream_atomically()).
  void write_stream(const std::string& path, const std::function<void(std::ostream&)>& write);
  // Replaces every target, in the order added.
  void commit();

 private:
  std::vector<std::unique_ptr<OutputFile>> files_;
};

// Several files written all or none (a folder of reports) through an
// OutputSet, their folders made as needed; if any cannot be written, none is
// replaced and the folders made for them are removed again. Throws WriteError.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

// Installs handlers for every catchable signal whose default action ends the
// process (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2,
// SIGXCPU, SIGPIPE, SIGVTALRM, SIGPROF, SIGPOLL, SIGPWR, SIGSTKFLT; those
// ignored by whoever started us stay ignored; and SIGABRT, SIGSEGV, SIGBUS,
// SIGFPE, SIGILL, SIGSYS, SIGTRAP when no one else handles them) that remove
// every temporary file in progress and then re-raise the signal with its
// default action, so that the exit status is the signal's. SIGXFSZ is
// ignored, so that a file grown past `ulimit -f` fails its write with EFBIG
// (an error with one line, exit 1) instead of killing the process. SIGKILL
// and SIGSTOP cannot be caught. Call once from main().
void remove_temporaries_on_signals();

// The directory for scratch files (TMPDIR, else /tmp).
std::string scratch_directory();

}  // namespace sweetspot::io

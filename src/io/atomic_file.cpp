#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <streambuf>
#include <vector>

namespace sweetspot::io {
namespace {

// The temporary files in progress, for a signal handler to remove. A signal
// handler can only reach global state, and only through lock-free atomics and
// async-signal-safe calls: a fixed table of paths, each slot claimed (1) while
// its path is copied in and live (2) while the file may exist.
constexpr int kTemporarySlots = 256;
struct TemporarySlot {
  std::atomic<int> state{0};
  std::array<char, PATH_MAX> path{};
};
static_assert(std::atomic<int>::is_always_lock_free);
TemporarySlot g_temporaries[kTemporarySlots];

// Every signal whose default action ends the process and that can be caught.
constexpr int kEnding[] = {SIGINT,  SIGTERM, SIGHUP,    SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2,
                           SIGXCPU, SIGPIPE, SIGVTALRM, SIGPROF, SIGPOLL, SIGPWR,  SIGSTKFLT};

// kEnding blocked in this thread for its lifetime: a temporary made and
// listed under it is listed before any handler can look (the signal waits, or
// another thread takes it and waits for the listing, below).
class EndingSignalsBlocked {
 public:
  EndingSignalsBlocked() {
    sigset_t blocked;
    sigemptyset(&blocked);
    for (const int signal_number : kEnding) sigaddset(&blocked, signal_number);
    ::pthread_sigmask(SIG_BLOCK, &blocked, &previous_);
  }
  ~EndingSignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  EndingSignalsBlocked(const EndingSignalsBlocked&) = delete;
  EndingSignalsBlocked& operator=(const EndingSignalsBlocked&) = delete;

 private:
  sigset_t previous_;
};

int register_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kTemporarySlots; ++i) {
    int free = 0;
    if (!g_temporaries[i].state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(g_temporaries[i].path.data(), path.c_str(), path.size() + 1);
    g_temporaries[i].state.store(2);
    return i;
  }
  return -1;  // more than kTemporarySlots at once: still written, just not removed on a signal
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_temporaries[slot].state.store(0);
}

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (TemporarySlot& slot : g_temporaries) {
    // A slot being listed by another thread (signals blocked there) is live
    // within a few instructions; the wait is bounded all the same.
    for (long spins = 0; slot.state.load() == 1 && spins < 100'000'000; ++spins) {
    }
    if (slot.state.load() == 2) ::unlink(slot.path.data());
  }
  // The handler was reset to the default action on entry (SA_RESETHAND) and
  // the signal is not blocked (SA_NODEFER): this ends the process.
  ::raise(signal_number);
}

std::string errno_text(int error) { return std::strerror(error); }

// The umask. umask(2) can only be read by setting it, which would change it
// for every thread for a moment; Linux shows it in /proc/self/status.
unsigned current_umask() {
  if (FILE* status = std::fopen("/proc/self/status", "re")) {
    char line[256];
    unsigned mask = 0;
    bool found = false;
    while (!found && std::fgets(line, sizeof line, status)) {
      found = std::sscanf(line, "Umask: %o", &mask) == 1;
    }
    std::fclose(status);
    if (found) return mask;
  }
  // Set to the strictest mask meanwhile: a file another thread creates then
  // is never more open than it should be.
  const mode_t old = ::umask(077);
  ::umask(old);
  return old;
}

// The descriptor that /dev/stdout, /dev/stderr, /dev/fd/N or /proc/self/fd/N
// names: written through a duplicate, as a shell does, so that an output
// redirected with >> is appended to and never truncated or replaced.
std::optional<int> descriptor_named(const std::string& path) {
  if (path == "-" || path == "/dev/stdout") return 1;
  if (path == "/dev/stderr") return 2;
  for (const std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (path.size() <= prefix.size() || path.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = path.substr(prefix.size());
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    return std::atoi(digits.c_str());
  }
  return std::nullopt;
}

// Buffers a stream into an OutputFile; a write error is thrown out of the
// stream (whose badbit exceptions are on) and so ends the writer at once.
class OutputBuffer : public std::streambuf {
 public:
  explicit OutputBuffer(OutputFile& file) : file_(file), buffer_(1 << 16) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  void flush_all() {
    file_.write(std::string_view(pbase(), static_cast<std::size_t>(pptr() - pbase())));
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }

 protected:
  int_type overflow(int_type c) override {
    flush_all();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    flush_all();
    return 0;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n > epptr() - pptr()) {
      flush_all();
      if (n >= static_cast<std::streamsize>(buffer_.size())) {
        file_.write(std::string_view(s, static_cast<std::size_t>(n)));
        return n;
      }
    }
    std::memcpy(pptr(), s, static_cast<std::size_t>(n));
    pbump(static_cast<int>(n));
    return n;
  }

 private:
  OutputFile& file_;
  std::vector<char> buffer_;
};

}  // namespace

std::string directory_of(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string name_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

WriteError::WriteError(const std::string& path, const std::string& reason)
    : std::runtime_error("cannot write " + path + ": " + reason), reason_(reason) {}

TemporaryFile::TemporaryFile(const std::string& directory, std::string_view name,
                             const std::string& for_path)
    : for_path_(for_path) {
  // A prefix of the name, cut on a UTF-8 character boundary.
  constexpr std::size_t kPrefixBytes = 32;
  std::size_t cut = std::min(name.size(), kPrefixBytes);
  while (cut > 0 && cut < name.size() && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80)
    --cut;
  std::string pattern = directory + "/." + std::string(name.substr(0, cut)) + ".XXXXXX";
  int error = 0;
  {
    // Made and listed with the ending signals held off: a signal between the
    // two would end the run with the temporary left behind.
    const EndingSignalsBlocked held;
    fd_ = ::mkostemp(pattern.data(), O_CLOEXEC);
    error = errno;
    if (fd_ >= 0) {
      path_ = pattern;
      slot_ = register_temporary(path_);
    }
  }
  if (fd_ < 0) throw WriteError(for_path, errno_text(error));
}

TemporaryFile::~TemporaryFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!path_.empty()) ::unlink(path_.c_str());
  unregister_temporary(slot_);
}

void TemporaryFile::rename_over(const std::string& target) {
  const bool synced = ::fsync(fd_) == 0;
  const int sync_error = errno;
  const bool closed = ::close(fd_) == 0;
  const int close_error = errno;
  fd_ = -1;
  if (!synced) throw WriteError(for_path_, errno_text(sync_error));
  if (!closed) throw WriteError(for_path_, errno_text(close_error));
  if (::rename(path_.c_str(), target.c_str()) != 0) throw WriteError(for_path_, errno_text(errno));
  path_.clear();
  unregister_temporary(slot_);
  slot_ = -1;
}

OutputFile::OutputFile(const std::string& path) : path_(path), target_(path) {
  if (path.empty()) throw WriteError("\"\"", "an empty file name");
  // Follow symbolic links to the file they name (a relative link is relative
  // to its own folder), stopping at a descriptor's name.
  struct stat info {};
  for (int hops = 0;; ++hops) {
    if (const std::optional<int> fd = descriptor_named(target_)) {
      const int flags = ::fcntl(*fd, F_GETFL);
      if (flags < 0 || (flags & O_ACCMODE) == O_RDONLY) throw WriteError(path, errno_text(EBADF));
      fd_ = ::fcntl(*fd, F_DUPFD_CLOEXEC, 0);
      if (fd_ < 0) throw WriteError(path, errno_text(errno));
      owns_fd_ = true;
      return;
    }
    if (::lstat(target_.c_str(), &info) != 0) {
      if (errno != ENOENT) throw WriteError(path, errno_text(errno));
      break;  // a new file
    }
    if (!S_ISLNK(info.st_mode)) {
      existed_ = true;
      break;
    }
    if (hops == 40) throw WriteError(path, errno_text(ELOOP));
    std::vector<char> link(static_cast<std::size_t>(info.st_size > 0 ? info.st_size : PATH_MAX) +
                           1);
    const ssize_t length = ::readlink(target_.c_str(), link.data(), link.size());
    if (length < 0) throw WriteError(path, errno_text(errno));
    const std::string to(link.data(), static_cast<std::size_t>(length));
    target_ = !to.empty() && to[0] == '/' ? to : directory_of(target_) + "/" + to;
  }

  if (existed_ && S_ISDIR(info.st_mode)) throw WriteError(path, errno_text(EISDIR));
  if (existed_ && !S_ISREG(info.st_mode)) {
    // A device, a FIFO or a socket: written in place, as a shell's > would.
    fd_ = ::open(target_.c_str(), O_WRONLY | O_TRUNC | O_NOCTTY | O_CLOEXEC);
    if (fd_ < 0) throw WriteError(path, errno_text(errno));
    owns_fd_ = true;
    return;
  }
  if (existed_) {
    mode_ = info.st_mode & 07777;
    uid_ = info.st_uid;
    gid_ = info.st_gid;
  } else {
    mode_ = 0666 & ~current_umask();
  }
  temporary_.emplace(directory_of(target_), name_of(target_), path);
  fd_ = temporary_->fd();
}

OutputFile::~OutputFile() {
  if (owns_fd_ && fd_ >= 0) ::close(fd_);
}

void OutputFile::write(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw WriteError(path_, errno_text(errno));
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void OutputFile::commit() {
  if (direct()) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR) throw WriteError(path_, errno_text(errno));
    return;
  }
  // The owner first: fchown clears set-user-ID bits, which fchmod then restores.
  if (existed_) {
    struct stat mine {};
    if (::fstat(fd_, &mine) == 0 && (mine.st_uid != uid_ || mine.st_gid != gid_)) {
      if (::fchown(fd_, uid_, gid_) != 0) (void)!::fchown(fd_, static_cast<uid_t>(-1), gid_);
    }
  }
  if (::fchmod(fd_, mode_) != 0) throw WriteError(path_, errno_text(errno));
  temporary_->rename_over(target_);
  fd_ = -1;
}

void write_file_atomically(const std::string& path, std::string_view content) {
  OutputFile file(path);
  file.write(content);
  file.commit();
}

void write_stream_atomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write) {
  OutputFile file(path);
  OutputBuffer buffer(file);
  std::ostream stream(&buffer);
  stream.exceptions(std::ios::badbit);
  write(stream);
  buffer.flush_all();
  if (stream.fail()) throw WriteError(path, "the output stream failed");
  file.commit();
}

void OutputSet::write(const std::string& path, std::string_view content) {
  files_.push_back(std::make_unique<OutputFile>(path));
  files_.back()->write(content);
}

void OutputSet::write_stream(const std::string& path,
                             const std::function<void(std::ostream&)>& write) {
  files_.push_back(std::make_unique<OutputFile>(path));
  OutputBuffer buffer(*files_.back());
  std::ostream stream(&buffer);
  stream.exceptions(std::ios::badbit);
  write(stream);
  buffer.flush_all();
  if (stream.fail()) throw WriteError(path, "the output stream failed");
}

void OutputSet::commit() {
  for (const auto& file : files_) file->commit();
  files_.clear();
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::string> made;  // folders made here, outermost first
  try {
    OutputSet outputs;
    for (const auto& [path, content] : files) {
      std::vector<std::string> missing;
      for (std::string folder = directory_of(path); folder != "." && folder != "/";
           folder = directory_of(folder)) {
        struct stat info {};
        if (::stat(folder.c_str(), &info) == 0) break;
        missing.push_back(folder);
      }
      for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST)
          throw WriteError(path, errno_text(errno));
        made.push_back(*it);
      }
      outputs.write(path, content);
    }
    outputs.commit();
  } catch (...) {
    for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
    throw;
  }
}

void remove_temporaries_on_signals() {
  // Every signal whose default action ends the process and that can be
  // caught. The faults come last and are taken only when nobody (a
  // sanitizer, a debugger's preload) handles them already.
  constexpr int kFaults[] = {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS, SIGTRAP};
  const auto install = [](int signal_number, bool only_default) {
    struct sigaction current {};
    if (::sigaction(signal_number, nullptr, &current) != 0) return;
    const bool plain = !(current.sa_flags & SA_SIGINFO);
    // A signal ignored by whoever started us (nohup) stays ignored.
    if (plain && current.sa_handler == SIG_IGN) return;
    if (only_default && !(plain && current.sa_handler == SIG_DFL)) return;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_NODEFER;
    ::sigaction(signal_number, &action, nullptr);
  };
  for (const int signal_number : kEnding) install(signal_number, false);
  for (const int signal_number : kFaults) install(signal_number, true);
  // A file grown past `ulimit -f` is a write error (EFBIG), reported and
  // cleaned like a full disk, not a death that leaves the temporary behind.
  ::signal(SIGXFSZ, SIG_IGN);
}

std::string scratch_directory() {
  const char* tmpdir = std::getenv("TMPDIR");
  return tmpdir && *tmpdir ? tmpdir : "/tmp";
}

}  // namespace sweetspot::io

#pragma once

// Helpers the file-writing tests share: a file's whole text, and a reader
// that drains a FIFO in the background.

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace sweetspot::io::testing {

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Reads a FIFO in the background until its writer closes it, or nothing
// comes for 10 s (so that a writer that never opens it cannot hang the test).
class FifoReader {
 public:
  explicit FifoReader(const std::string& path)
      : fd_(::open(path.c_str(), O_RDONLY | O_NONBLOCK)), thread_([this] { run(); }) {}
  std::string finish() {
    thread_.join();
    if (fd_ >= 0) ::close(fd_);
    return text_;
  }

 private:
  void run() {
    char buffer[1 << 16];
    while (fd_ >= 0) {
      pollfd wanted{fd_, POLLIN, 0};
      if (::poll(&wanted, 1, 10'000) <= 0) return;
      const ssize_t n = ::read(fd_, buffer, sizeof buffer);
      if (n > 0) text_.append(buffer, static_cast<std::size_t>(n));
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) return;
    }
  }
  int fd_;
  std::string text_;
  std::thread thread_;
};

}  // namespace sweetspot::io::testing

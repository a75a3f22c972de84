#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace sweetspot::io {
namespace {
[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path + ": " + what);
}
}  // namespace

std::string temporary_path_for(const std::string& path) {
  std::string pattern = path + ".tmp.XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = mkstemp(buffer.data());
  if (fd < 0) fail(path, std::strerror(errno));
  close(fd);
  return std::string(buffer.data());
}

void commit_file(const std::string& temporary, const std::string& path) {
  // mkstemp creates 0600; outputs are for everyone to read.
  std::error_code ignored;
  std::filesystem::permissions(temporary,
                               std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                                   std::filesystem::perms::group_read | std::filesystem::perms::others_read,
                               ignored);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    fail(path, reason);
  }
}

void discard_file(const std::string& temporary) { std::remove(temporary.c_str()); }

void write_stream_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = temporary_path_for(path);
  try {
    std::ofstream file(temporary, std::ios::binary);
    write(file);
    file.close();
    if (!file) fail(path, "write failed");
    commit_file(temporary, path);
  } catch (...) {
    discard_file(temporary);
    throw;
  }
}

void write_file_atomically(const std::string& path, std::string_view content) {
  const std::string temporary = temporary_path_for(path);
  FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) {
    discard_file(temporary);
    fail(path, std::strerror(errno));
  }
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const bool flushed = std::fflush(file) == 0 && fsync(fileno(file)) == 0;
  const bool closed = std::fclose(file) == 0;
  if (!written || !flushed || !closed) {
    discard_file(temporary);
    fail(path, "write failed");
  }
  commit_file(temporary, path);
}

}  // namespace sweetspot::io

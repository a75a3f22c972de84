#include "cli/output_plan.hpp"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"

namespace sweetspot::cli {
namespace {

namespace fs = std::filesystem;

using io::directory_of;
using io::name_of;

// `path` with its symbolic links followed to the name they end at (which
// may not exist: a dangling link is written through, as OutputFile does).
std::string final_target(const std::string& path) {
  std::string target = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat info {};
    if (::lstat(target.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return target;
    std::vector<char> link(PATH_MAX + 1);
    const ssize_t length = ::readlink(target.c_str(), link.data(), link.size());
    if (length < 0) return target;
    const std::string to(link.data(), static_cast<std::size_t>(length));
    target = !to.empty() && to[0] == '/' ? to : directory_of(target) + "/" + to;
  }
  return target;
}

std::string quoted(const std::string& path) { return io::one_line(path); }

std::string mode_text(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
  return text;
}

bool writable(const std::string& path, int how) {
  return ::faccessat(AT_FDCWD, path.c_str(), how, AT_EACCESS) == 0;
}

}  // namespace

OutputPlan::Identity OutputPlan::identify(const std::string& path, int standard_fd) {
  Identity identity;
  struct stat info {};
  if (path == "-") {
    if (::fstat(standard_fd, &info) == 0) {
      identity = {true, info.st_dev, info.st_ino, info.st_mode, ""};
    } else {
      identity.new_name = "-";  // closed: still "the" standard stream
    }
    return identity;
  }
  if (::stat(path.c_str(), &info) == 0) return {true, info.st_dev, info.st_ino, info.st_mode, ""};
  std::error_code error;
  const std::string target = final_target(path);
  const fs::path absolute = fs::absolute(target, error);
  identity.new_name = fs::weakly_canonical(absolute, error).string();
  if (identity.new_name.empty()) identity.new_name = absolute.lexically_normal().string();
  return identity;
}

bool OutputPlan::same(const Identity& a, const Identity& b) {
  if (a.exists != b.exists) return false;
  if (!a.exists) return a.new_name == b.new_name;
  // Nothing is lost in /dev/null or a terminal, however many outputs go there.
  if (S_ISCHR(a.mode)) return false;
  return a.device == b.device && a.inode == b.inode;
}

void OutputPlan::refuse_collisions(const std::string& option, const std::string& path,
                                   const Identity& identity) const {
  for (const Entry& input : inputs_) {
    if (input.identity.exists && same(identity, input.identity)) {
      const bool stdin_input = input.path == "-";
      throw CLI::ValidationError(
          option + " " + quoted(path) + ": is the input " +
          (stdin_input ? std::string("on standard input") : quoted(input.path)) +
          "; an output never replaces an input (give another file)");
    }
  }
  for (const Entry& output : outputs_) {
    if (same(identity, output.identity) || (path == "-" && output.path == "-")) {
      if (output.option == option) {
        throw CLI::ValidationError(option + ": names " + quoted(path) +
                                   " twice; give each output its own file");
      }
      throw CLI::ValidationError(option + " and " + output.option + ": both name " + quoted(path) +
                                 "; give each output its own file");
    }
  }
}

void OutputPlan::read(const std::string& path) {
  if (path.empty()) return;
  const Identity identity = identify(path, 0);
  if (identity.exists) inputs_.push_back({"", path, identity});
}

void OutputPlan::read_folder(const std::string& folder) {
  read(folder);
  std::error_code error;
  constexpr int kMostFiles = 100000;  // a folder of inputs, not a disk
  int seen = 0;
  for (fs::recursive_directory_iterator
           it(folder, fs::directory_options::skip_permission_denied, error),
       end;
       !error && it != end && seen < kMostFiles; it.increment(error), ++seen) {
    if (it->is_regular_file(error)) read(it->path().string());
  }
}

void OutputPlan::write(const std::string& option, const std::string& path, bool folder_made_later) {
  if (path.empty()) throw CLI::ValidationError(option + " \"\": an empty file name");
  const Identity identity = identify(path, 1);
  refuse_collisions(option, path, identity);
  outputs_.push_back({option, path, identity});
  if (path == "-") return;
  const std::string target = final_target(path);
  if (identity.exists) {
    if (S_ISDIR(identity.mode)) throw io::WriteError(quoted(path), std::strerror(EISDIR));
    if (!writable(target, W_OK)) {
      // A read-only file system is no one's permission: a write error (exit 1).
      if (errno != EACCES && errno != EPERM)
        throw io::WriteError(quoted(path), std::strerror(errno));
      throw CLI::ValidationError(option + " " + quoted(path) +
                                 ": this user may not write it (mode " + mode_text(identity.mode) +
                                 "); it is left as it was");
    }
    if (!S_ISREG(identity.mode)) return;  // a device or a FIFO: written in place
  } else if (name_of(target).size() > NAME_MAX) {
    throw io::WriteError(quoted(path), std::strerror(ENAMETOOLONG));
  }
  // A regular file is replaced by renaming a temporary file in its folder.
  const std::string folder = directory_of(target);
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0) {
    if (errno == ENOENT && folder_made_later) return;
    throw io::WriteError(quoted(path), std::strerror(errno));
  }
  if (!S_ISDIR(info.st_mode)) throw io::WriteError(quoted(path), std::strerror(ENOTDIR));
  if (!writable(folder, W_OK | X_OK)) {
    if (errno != EACCES && errno != EPERM) throw io::WriteError(quoted(path), std::strerror(errno));
    throw CLI::ValidationError(option + " " + quoted(path) + ": this user may not write in " +
                               quoted(folder) + " (mode " + mode_text(info.st_mode) + ")");
  }
}

void OutputPlan::write_folder(const std::string& option, const std::string& path) {
  if (path.empty()) throw CLI::ValidationError(option + " \"\": an empty folder name");
  if (path == "-") {
    throw CLI::ValidationError(option +
                               " -: names a folder to fill with files, not standard output");
  }
  const Identity identity = identify(path, 1);
  if (identity.exists && !S_ISDIR(identity.mode)) {
    throw CLI::ValidationError(option + " " + quoted(path) + ": not a folder");
  }
  refuse_collisions(option, path, identity);
  outputs_.push_back({option, path, identity});
  // The folder, or the nearest folder above it that exists (where it is made).
  std::error_code error;
  fs::path folder = fs::absolute(path, error);
  while (!fs::exists(folder, error) && folder.has_relative_path()) folder = folder.parent_path();
  if (!fs::is_directory(folder, error)) {
    throw CLI::ValidationError(option + " " + quoted(path) + ": " + quoted(folder.string()) +
                               " is not a folder");
  }
  if (!writable(folder.string(), W_OK | X_OK)) {
    struct stat info {};
    ::stat(folder.c_str(), &info);
    throw CLI::ValidationError(option + " " + quoted(path) + ": this user may not write in " +
                               quoted(folder.string()) + " (mode " + mode_text(info.st_mode) + ")");
  }
}

bool is_standard_output(const std::string& path) {
  if (path == "-") return true;
  struct stat mine {};
  struct stat out {};
  return ::fstat(1, &out) == 0 && ::stat(path.c_str(), &mine) == 0 && mine.st_dev == out.st_dev &&
         mine.st_ino == out.st_ino;
}

void say_written(const std::string& path) {
  (is_standard_output(path) ? std::cerr : std::cout)
      << "wrote " << (path == "-" ? std::string("standard output") : quoted(path)) << "\n";
}

void require_plot_stem(const std::string& option, const std::string& path) {
  if (path == "-") {
    throw CLI::ValidationError(option +
                               " -: names several files (FILE-<what>.png), not standard output");
  }
  const std::string name = name_of(path);
  if (name.empty() || name == "." || name == "..") {
    throw CLI::ValidationError(option + " " + quoted(path) +
                               ": names a folder; give a file name for the plots to start with "
                               "(FILE.png gives FILE-<what>.png)");
  }
}

}  // namespace sweetspot::cli

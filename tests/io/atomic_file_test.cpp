#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "file_helpers.hpp"

namespace sweetspot::io {
namespace {

namespace fs = std::filesystem;

class Folder {
 public:
  Folder() : dir_(fs::temp_directory_path() / ("sweetspot-atomic-" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Folder() { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string file(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return path(name);
  }
  // The names in `sub` (the folder itself by default), hidden ones included.
  std::set<std::string> names(const std::string& sub = "") const {
    std::set<std::string> out;
    for (const auto& entry : fs::directory_iterator(dir_ / sub))
      out.insert(entry.path().filename().string());
    return out;
  }

 private:
  fs::path dir_;
};

using testing::FifoReader;
using testing::slurp;

unsigned mode_of(const std::string& path) {
  struct stat info {};
  REQUIRE(::lstat(path.c_str(), &info) == 0);
  return info.st_mode;
}

// Sets the umask for the scope of a test.
class Umask {
 public:
  explicit Umask(mode_t mask) : old_(::umask(mask)) {}
  ~Umask() { ::umask(old_); }

 private:
  mode_t old_;
};

TEST_CASE("A new file gets 0666 less the umask, an existing one keeps its mode") {
  const Folder folder;
  {
    const Umask strict(027);
    write_file_atomically(folder.path("new.txt"), "new\n");
    write_stream_atomically(folder.path("new.csv"), [](std::ostream& out) { out << "new\n"; });
  }
  CHECK((mode_of(folder.path("new.txt")) & 07777) == 0640);
  CHECK((mode_of(folder.path("new.csv")) & 07777) == 0640);
  {
    const Umask open(0);
    write_file_atomically(folder.path("open.txt"), "new\n");
  }
  CHECK((mode_of(folder.path("open.txt")) & 07777) == 0666);

  const std::string kept = folder.file("kept.txt", "old\n");
  REQUIRE(::chmod(kept.c_str(), 0604) == 0);
  write_file_atomically(kept, "new\n");
  CHECK(slurp(kept) == "new\n");
  CHECK((mode_of(kept) & 07777) == 0604);
  write_stream_atomically(kept, [](std::ostream& out) { out << "streamed\n"; });
  CHECK(slurp(kept) == "streamed\n");
  CHECK((mode_of(kept) & 07777) == 0604);
  CHECK(folder.names() == std::set<std::string>{"new.txt", "new.csv", "open.txt", "kept.txt"});
}

TEST_CASE("Writing through a symbolic link updates its target and leaves the link a link") {
  const Folder folder;
  fs::create_directories(folder.path("real"));
  const std::string target = folder.file("real/target.csv", "old\n");
  fs::create_symlink("real/target.csv", folder.path("link.csv"));
  write_file_atomically(folder.path("link.csv"), "new\n");
  CHECK(S_ISLNK(mode_of(folder.path("link.csv"))));
  CHECK(slurp(target) == "new\n");
  // The temporary file was made beside the target, and is gone.
  CHECK(folder.names("real") == std::set<std::string>{"target.csv"});
  CHECK(folder.names() == std::set<std::string>{"real", "link.csv"});

  // A dangling link creates its target, as a shell's > does.
  fs::create_symlink("real/later.csv", folder.path("dangling.csv"));
  write_file_atomically(folder.path("dangling.csv"), "created\n");
  CHECK(S_ISLNK(mode_of(folder.path("dangling.csv"))));
  CHECK(slurp(folder.path("real/later.csv")) == "created\n");
}

TEST_CASE("A 250-character file name can be written: the temporary name stays short") {
  const Folder folder;
  const std::string name = std::string(246, 'n') + ".csv";
  REQUIRE(name.size() == 250);
  write_file_atomically(folder.path(name), "a\n");
  write_stream_atomically(folder.path(name), [](std::ostream& out) { out << "b\n"; });
  CHECK(slurp(folder.path(name)) == "b\n");
  CHECK(folder.names() == std::set<std::string>{name});
}

TEST_CASE("A FIFO is written in place, not replaced") {
  const Folder folder;
  const std::string fifo = folder.path("pipe");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  FifoReader reader(fifo);
  write_file_atomically(fifo, "through the pipe\n");
  CHECK(reader.finish() == "through the pipe\n");
  CHECK(S_ISFIFO(mode_of(fifo)));
}

TEST_CASE("A device is written in place, and a full one is a write error naming it") {
  const Folder folder;
  // Private nodes of the null (1,3) and full (1,7) devices: a failing check
  // must not replace the machine's own /dev/null.
  const std::string null_device = folder.path("null");
  const std::string full_device = folder.path("full");
  if (::mknod(null_device.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      ::mknod(full_device.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    WARN("skipped: cannot make device nodes here (needs root and a filesystem without nodev)");
    return;
  }
  write_file_atomically(null_device, "discarded\n");
  write_stream_atomically(null_device, [](std::ostream& out) { out << "discarded\n"; });
  CHECK(S_ISCHR(mode_of(null_device)));

  CHECK_THROWS_WITH(write_file_atomically(full_device, "x"),
                    "cannot write " + full_device + ": No space left on device");
  // A streamed output stops at the first failed write instead of running on.
  std::size_t written = 0;
  CHECK_THROWS_AS(write_stream_atomically(full_device,
                                          [&](std::ostream& out) {
                                            for (; written < 100'000'000; ++written) out << 'x';
                                          }),
                  WriteError);
  CHECK(written < 1'000'000);
  CHECK(S_ISCHR(mode_of(full_device)));
  CHECK(folder.names() == std::set<std::string>{"null", "full"});
}

TEST_CASE("An output set writes all of its files or none") {
  const Folder folder;
  const std::string a = folder.file("a.csv", "old a\n");
  const std::string b = folder.file("b.png", "old b\n");
  {
    // The second file cannot be made: the first, complete, is not put in place either.
    OutputSet outputs;
    outputs.write(a, "new a\n");
    CHECK_THROWS_AS(outputs.write(folder.path("missing/c.png"), "c"), WriteError);
  }
  CHECK(slurp(a) == "old a\n");
  {
    OutputSet outputs;
    outputs.write(a, "new a\n");
    outputs.write_stream(b, [](std::ostream& out) { out << "new b\n"; });
    CHECK(slurp(a) == "old a\n");  // nothing replaced before commit()
    outputs.commit();
  }
  CHECK(slurp(a) == "new a\n");
  CHECK(slurp(b) == "new b\n");
  CHECK(folder.names() == std::set<std::string>{"a.csv", "b.png"});  // no temporary left
}

TEST_CASE("Files written all or none make their folders, and remove them when one fails") {
  const Folder folder;
  const std::string kept = folder.file("README.md", "old\n");
  CHECK_THROWS_AS(write_files_atomically({{kept, "new\n"},
                                          {folder.path("studies/one.md"), "one"},
                                          {folder.path("README.md/x"), "not a folder"}}),
                  WriteError);
  CHECK(slurp(kept) == "old\n");
  CHECK(folder.names() == std::set<std::string>{"README.md"});
  write_files_atomically({{kept, "new\n"}, {folder.path("studies/deep/one.md"), "one"}});
  CHECK(slurp(kept) == "new\n");
  CHECK(slurp(folder.path("studies/deep/one.md")) == "one");
}

TEST_CASE("A directory, a missing folder and a failing writer leave everything as it was") {
  const Folder folder;
  fs::create_directories(folder.path("dir"));
  CHECK_THROWS_WITH(write_file_atomically(folder.path("dir"), "x"),
                    "cannot write " + folder.path("dir") + ": Is a directory");
  CHECK_THROWS_AS(write_file_atomically(folder.path("missing/x.md"), "x"), WriteError);
  const std::string kept = folder.file("kept.csv", "old\n");
  CHECK_THROWS_WITH(write_stream_atomically(kept,
                                            [](std::ostream& out) {
                                              out << "half";
                                              throw std::invalid_argument("bad row");
                                            }),
                    "bad row");
  CHECK(slurp(kept) == "old\n");
  CHECK(folder.names() == std::set<std::string>{"dir", "kept.csv"});
}

TEST_CASE(
    "A signal during a write removes the temporary file and ends the process by that signal") {
  const Folder folder;
  const std::string kept = folder.file("kept.csv", "old\n");
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      remove_temporaries_on_signals();
      write_stream_atomically(kept, [&](std::ostream& out) {
        out << "half a row" << std::flush;
        ::raise(signal_number);
      });
      ::_exit(0);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal_number);
    CHECK(slurp(kept) == "old\n");
    CHECK(folder.names() == std::set<std::string>{"kept.csv"});
  }
}

}  // namespace
}  // namespace sweetspot::io

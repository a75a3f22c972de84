#pragma once

// One command's output plan: every file it reads and every file it will
// write, checked before any work, so that an output never costs an input or
// another output.
//
// An output is refused (CLI::ValidationError: exit 2, one line naming the
// option and the path) when it is
//  - empty ("" is no file name);
//  - an input of the command: the same file by device and inode, through
//    any symbolic links ("-" as an input is whatever standard input is);
//  - another output of the same command: the same existing file, or the same
//    new file (the same absolute name once links are followed), or standard
//    output twice;
//  - a file this user may not write: a file without write permission for
//    them (as cp and the shell's > judge it: with access(2) on the effective
//    user, so root, who may write any file, replaces a mode 0444 file as
//    cp does), or a new file in a folder they may not write.
// A character device (/dev/null, a terminal) may take any number of outputs
// and may be an input too: nothing is lost there. An output that cannot be
// written at all (into a missing folder, onto a folder, a name over NAME_MAX,
// on a read-only file system)
// is io::WriteError (exit 1), also before any work. "-" is standard output.

#include <sys/types.h>

#include <string>
#include <vector>

namespace sweetspot::cli {

class OutputPlan {
 public:
  // A file the command reads ("-": standard input). A file that does not
  // exist (yet) cannot collide with anything and is skipped.
  void read(const std::string& path);
  // Every file under `folder` (and the folder itself): a folder of inputs.
  void read_folder(const std::string& folder);

  // `path`, to be written for `option` (named in messages, e.g. "--plot").
  // `folder_made_later`: its folder may not exist yet (it is created with
  // the file, as the reports folder's subfolders are).
  void write(const std::string& option, const std::string& path, bool folder_made_later = false);
  // A folder that `option` fills (report --out, bench --out): refused when
  // "" or "-", a file, an input folder, or not writable; may not exist yet.
  void write_folder(const std::string& option, const std::string& path);

 private:
  struct Identity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    mode_t mode = 0;
    std::string new_name;  // for a file that does not exist: its absolute name
  };
  struct Entry {
    std::string option;
    std::string path;
    Identity identity;
  };
  static Identity identify(const std::string& path, int standard_fd);
  static bool same(const Identity& a, const Identity& b);
  void refuse_collisions(const std::string& option, const std::string& path,
                         const Identity& identity) const;

  std::vector<Entry> inputs_;
  std::vector<Entry> outputs_;
};

// True when `path` as an output is standard output ("-", /dev/stdout, or the
// very file standard output is): what says "wrote PATH" then says it on
// standard error, never into the output.
bool is_standard_output(const std::string& path);

// Says on standard output (standard error when `path` is standard output)
// that `path` was written.
void say_written(const std::string& path);

// Refuses (exit 2) a plot name whose file name is empty or a folder's
// ("maps/", ".", ".."), for an option that adds a suffix to the name
// (map's FILE-power.png): it would write files named "-power.png"; and "-",
// which cannot be several files.
void require_plot_stem(const std::string& option, const std::string& path);

}  // namespace sweetspot::cli

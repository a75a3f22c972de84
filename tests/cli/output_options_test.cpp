// Every output option of every subcommand, found in its --help ("Output
// files", where cli/output.hpp registers them), through the cases of the
// output plan (cli/output_plan.hpp): its own input, another output, a
// read-only file, a symbolic link, "-" and "". A new output option fails the
// first test until it has a place in kModes below, so it is tested the day it
// is added. SWEETSPOT_CLI is the built executable.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kSource = SWEETSPOT_SOURCE_DIR;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string quote(const std::string& word) {
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct Run {
  int status = -1;
  std::string out;
  std::string err;
};

// One output option as --help shows it.
struct OutputOption {
  std::string name;  // the long name, "--plot"
  bool folder = false;
};

// `sweetspot ARGS --help`'s lines.
std::vector<std::string> help_lines(const std::string& arguments) {
  const fs::path file =
      fs::temp_directory_path() / ("sweetspot-help-" + std::to_string(::getpid()));
  const std::string command =
      std::string("\"") + SWEETSPOT_CLI + "\" " + arguments + " --help >" + file.string();
  REQUIRE(std::system(command.c_str()) == 0);
  std::istringstream text(slurp(file));
  fs::remove(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(text, line);) lines.push_back(line);
  return lines;
}

// The entries of the help section headed `heading` ("Subcommands:"): the
// first word of each line indented by two spaces.
std::vector<std::pair<std::string, std::string>> section(const std::vector<std::string>& lines,
                                                         const std::string& heading) {
  std::vector<std::pair<std::string, std::string>> entries;
  bool inside = false;
  for (const std::string& line : lines) {
    if (line == heading) {
      inside = true;
    } else if (inside && line.empty()) {
      if (!entries.empty()) break;
    } else if (inside && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') {
      std::istringstream words(line);
      std::string first, second;
      words >> first >> second;
      entries.emplace_back(first, second);
    } else if (inside && line[0] != ' ') {
      break;
    }
  }
  return entries;
}

std::vector<std::string> subcommands() {
  std::vector<std::string> names;
  for (const auto& [name, rest] : section(help_lines(""), "Subcommands:")) names.push_back(name);
  return names;
}

std::vector<OutputOption> output_options(const std::string& subcommand) {
  std::vector<OutputOption> options;
  for (const auto& [names, type] : section(help_lines(subcommand), "Output files:")) {
    std::string name =
        names.substr(names.rfind(',') == std::string::npos ? 0 : names.rfind(',') + 1);
    options.push_back({name, type == "DIR"});
  }
  return options;
}

// One way to run a subcommand: its arguments (in a folder holding `setup`'s
// files), the inputs an output may collide with, the output options it
// takes, and for an option that derives its file names, the suffix it adds
// (response's --plot F.png writes F-at-2cm.png).
struct Mode {
  std::string subcommand;
  std::string arguments;
  std::vector<std::pair<std::string, std::string>> setup;  // name in the case, path in the source
  std::vector<std::string> inputs;
  std::vector<std::string> options;
  std::map<std::string, std::string> suffix;
  std::string text_option;  // the output that is standard output when not given
};

const std::string kOptimize =
    R"({"design": "d.json", "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.4}],)"
    R"( "objective": {"output": "peak_wrist_force_N", "goal": "minimize"}})";
const std::string kSweep =
    R"({"design": "d.json", "variables": [{"path": "/hand/mass_kg", "min": 0.3, "max": 0.6, )"
    R"("points": 3}], "outputs": ["peak_wrist_force_N"]})";

// A racquet with a head (no shipped design gives headsize_sq_in).
const std::string kMapDesign =
    R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5, )"
    R"("swingweight_kg_cm2": 320, "headsize_sq_in": 100}})";

const std::vector<Mode> kModes = {
    {"evaluate",
     "evaluate d.json",
     {{"d.json", "designs/table1/row1.json"}},
     {"d.json"},
     {"--output"},
     {},
     "--output"},
    {"evaluate",
     "evaluate --batch c.csv --base d.json",
     {{"d.json", "designs/table1/row1.json"}, {"c.csv", ""}},
     {"c.csv", "d.json"},
     {"--output"},
     {},
     "--output"},
    {"compare",
     "compare d.json e.json",
     {{"d.json", "designs/table1/row1.json"}, {"e.json", "designs/table1/row2.json"}},
     {"d.json", "e.json"},
     {"--output", "--html"},
     {},
     "--output"},
    {"table1",
     "table1 --dir t1",
     {{"t1", "designs/table1"}},
     {"t1/row1.json"},
     {"--output"},
     {},
     "--output"},
    {"figure",
     "figure 5 --design b.json",
     {{"b.json", "designs/paper-beam.json"}},
     {"b.json"},
     {"--output", "--plot"},
     {},
     "--output"},
    {"report", "report --designs ds", {{"ds", "designs"}}, {"ds"}, {"--out"}, {}, ""},
    {"report",
     "report d.json",
     {{"d.json", "designs/table1/row1.json"}},
     {"d.json"},
     {"--html"},
     {},
     ""},
    {"optimize",
     "optimize o.json",
     {{"d.json", "designs/table1/row1.json"}, {"o.json", ""}},
     {"o.json", "d.json"},
     {"--output", "--html", "--plot"},
     {},
     "--output"},
    {"sweep",
     "sweep s.json",
     {{"d.json", "designs/table1/row1.json"}, {"s.json", ""}},
     {"s.json", "d.json"},
     {"--output", "--plot"},
     {},
     "--output"},
    {"modes",
     "modes f.json",
     {{"f.json", "designs/studies/table1-racquet-flexible.json"}},
     {"f.json"},
     {"--output", "--plot"},
     {},
     "--output"},
    {"response",
     "response f.json --at 0.02",
     {{"f.json", "designs/studies/table1-racquet-flexible.json"}},
     {"f.json"},
     {"--output", "--plot"},
     {{"--plot", "-at-2cm"}},
     "--output"},
    {"map",
     "map t.json --columns 2 --rows 2",
     {{"t.json", ""}},
     {"t.json"},
     {"--output", "--plot"},
     {{"--plot", "-power"}},
     "--output"},
    {"tune",
     "tune t.json --target mass_g=330 --places 12,handle",
     {{"t.json", ""}},
     {"t.json"},
     {"--output"},
     {},
     ""},
    {"tune",
     "tune --match t.json u.json --places 12,3/9,handle",
     {{"t.json", ""}, {"u.json", ""}},
     // (its inputs are files, which a folder option refuses as not a folder:
     // tests/hostile/tune.tsv; a file it would write onto an input is refused
     // by the output plan, tests/cli/cli_test.cpp)
     {},
     {"--output-dir"},
     {},
     ""},
    {"bench",
     "bench speed --repeats 1 --designs ds",
     {{"ds", "designs"}},
     {"ds"},
     {"--out"},
     {},
     ""},
};

// The file an option writes when given `value` (its suffix before ".png").
std::string written(const Mode& mode, const std::string& option, const std::string& value) {
  const auto it = mode.suffix.find(option);
  if (it == mode.suffix.end()) return value;
  const std::string stem = value.size() > 4 && value.compare(value.size() - 4, 4, ".png") == 0
                               ? value.substr(0, value.size() - 4)
                               : value;
  return stem + it->second + ".png";
}

// A case's own folder with the mode's files, and running the command there.
class Case {
 public:
  explicit Case(const Mode& mode, const std::string& name)
      : dir_(fs::temp_directory_path() /
             ("sweetspot-outputs-" + std::to_string(::getpid()) + "-" + name)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "run");
    for (const auto& [file, source] : mode.setup) {
      const fs::path to = dir_ / "run" / file;
      if (file == "c.csv") {
        std::ofstream(to) << "name,implement.mass_kg\na,0.3\nb,0.35\n";
      } else if (file == "o.json") {
        std::ofstream(to) << kOptimize;
      } else if (file == "s.json") {
        std::ofstream(to) << kSweep;
      } else if (file == "t.json") {
        std::ofstream(to) << kMapDesign;
      } else if (file == "u.json") {  // a second racquet, 10 g heavier
        std::string heavier = kMapDesign;
        heavier.replace(heavier.find("305"), 3, "315");
        std::ofstream(to) << heavier;
      } else {
        fs::copy(kSource + "/" + source, to, fs::copy_options::recursive);
      }
    }
  }
  ~Case() { fs::remove_all(dir_); }
  fs::path path(const std::string& name) const { return dir_ / "run" / name; }
  // Runs `arguments` in the case's folder, as `as_user` ("" or setpriv's words) when given.
  Run run(const std::string& arguments, const std::string& as_user = "") const {
    const std::string command = "cd " + quote((dir_ / "run").string()) + " && " + as_user + " \"" +
                                SWEETSPOT_CLI + "\" " + arguments + " >" +
                                quote((dir_ / "stdout").string()) + " 2>" +
                                quote((dir_ / "stderr").string()) + " </dev/null";
    const int raw = std::system(command.c_str());
    return Run{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir_ / "stdout"),
               slurp(dir_ / "stderr")};
  }
  // The contents of every file in the folder, to see that a refusal left them.
  std::map<std::string, std::string> snapshot() const {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir_ / "run")) {
      const std::string name = fs::relative(entry.path(), dir_ / "run").string();
      files[name] = entry.is_symlink()        ? "link " + fs::read_symlink(entry.path()).string()
                    : entry.is_regular_file() ? slurp(entry.path())
                                              : "folder";
    }
    return files;
  }

 private:
  fs::path dir_;
};

// A refusal: exit 2, one line on stderr holding `words`, every file as it was.
void require_refused(const Case& c, const std::string& arguments, const std::string& words,
                     const std::string& as_user = "") {
  const auto before = c.snapshot();
  const Run run = c.run(arguments, as_user);
  INFO("sweetspot " << arguments << "\nstderr: " << run.err);
  CHECK(run.status == 2);
  CHECK(run.err.rfind("sweetspot: ", 0) == 0);
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  CHECK(run.err.find(words) != std::string::npos);
  CHECK(c.snapshot() == before);
}

// An output option that names a folder to fill.
bool folder_option(const std::string& option) {
  return option == "--out" || option == "--output-dir";
}

bool setpriv_works() {
  return std::system("setpriv --reuid=65534 --regid=65534 --clear-groups true >/dev/null 2>&1") ==
         0;
}

}  // namespace

TEST_CASE("Every output option of every subcommand has a place in the output options test") {
  std::set<std::string> known;
  for (const Mode& mode : kModes) {
    for (const std::string& option : mode.options) known.insert(mode.subcommand + " " + option);
  }
  const std::vector<std::string> names = subcommands();
  REQUIRE(names.size() >= 11);
  int found = 0;
  for (const std::string& subcommand : names) {
    for (const OutputOption& option : output_options(subcommand)) {
      INFO("add `" << subcommand << " " << option.name
                   << "` to kModes in tests/cli/output_options_test.cpp");
      CHECK(known.count(subcommand + " " + option.name) == 1);
      ++found;
    }
  }
  // evaluate, compare (2), table1, figure (2), report (2), optimize (3), sweep (2), modes (2),
  // response (2), map (2), bench: no fewer than today.
  CHECK(found >= 19);
}

TEST_CASE("No output option writes over an input, directly or through a symbolic link") {
  for (const Mode& mode : kModes) {
    for (const std::string& option : mode.options) {
      for (const std::string& input : mode.inputs) {
        const Case c(mode, "input");
        // An option that derives its names (F-at-2cm.png) meets an input only through a link.
        if (!mode.suffix.count(option)) {
          require_refused(c, mode.arguments + " " + option + " " + quote(input), "is the input");
        }
        fs::create_symlink(input, c.path(written(mode, option, "link")));
        require_refused(c, mode.arguments + " " + option + " link",
                        option + " " + written(mode, option, "link") + ": is the input");
      }
    }
  }
}

TEST_CASE("No two output options of one command may name one file") {
  for (const Mode& mode : kModes) {
    for (std::size_t i = 0; i < mode.options.size(); ++i) {
      for (std::size_t j = i + 1; j < mode.options.size(); ++j) {
        // The option that derives its names is given x.png; the other, the name it derives.
        std::string a = mode.options[i], b = mode.options[j];
        if (mode.suffix.count(a)) std::swap(a, b);
        const Case c(mode, "pair");
        const std::string file = written(mode, b, "x.png");
        require_refused(c, mode.arguments + " " + a + " " + file + " " + b + " x.png",
                        "both name " + file);
        // ... nor through a link, nor when the file exists already.
        std::ofstream(c.path(file)) << "keep";
        fs::create_symlink(file, c.path("link"));
        require_refused(c, mode.arguments + " " + a + " link " + b + " x.png", "both name");
      }
    }
  }
}

TEST_CASE("An output this user may not write is refused and kept, and root writes it as cp does") {
  const bool root = ::geteuid() == 0;
  if (root && !setpriv_works()) {
    WARN("skipped: running as root without setpriv to become an ordinary user");
    return;
  }
  const std::string as_user = root ? "setpriv --reuid=65534 --regid=65534 --clear-groups" : "";
  for (const Mode& mode : kModes) {
    for (const std::string& option : mode.options) {
      const Case c(mode, "read-only");
      fs::permissions(c.path(""), fs::perms::all);  // the folder is anyone's: only the file is not
      const bool folder = folder_option(option);
      const std::string name = folder ? "ro" : "ro.out";
      if (folder) {
        fs::create_directory(c.path("ro"));
        fs::permissions(c.path("ro"), fs::perms::owner_read | fs::perms::owner_exec |
                                          fs::perms::group_read | fs::perms::group_exec |
                                          fs::perms::others_read | fs::perms::others_exec);
      } else {
        std::ofstream(c.path(written(mode, option, name))) << "keep";
        fs::permissions(c.path(written(mode, option, name)),
                        fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
      }
      // A file in the read-only folder, or the read-only file itself.
      const std::string target = folder ? "ro/r" : name;
      require_refused(c, mode.arguments + " " + option + " " + target, "may not write", as_user);
    }
  }
  if (root) {  // root may write any file: the read-only file is replaced and keeps its mode
    const Case c(kModes.front(), "root");
    std::ofstream(c.path("ro.out")) << "keep";
    fs::permissions(c.path("ro.out"), fs::perms::owner_read | fs::perms::group_read);
    const Run run = c.run(kModes.front().arguments + " -o ro.out");
    CHECK(run.status == 0);
    CHECK(slurp(c.path("ro.out")).rfind("# ", 0) == 0);
    CHECK((fs::status(c.path("ro.out")).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::group_read));
  }
}

TEST_CASE(
    "'-' is standard output for every file option but refused for a folder, and '' is refused") {
  for (const Mode& mode : kModes) {
    for (const std::string& option : mode.options) {
      const Case c(mode, "dash");
      require_refused(c, mode.arguments + " " + option + " ''", option + ": an empty value");
      if (folder_option(option)) {
        require_refused(c, mode.arguments + " " + option + " -", "names a folder");
        continue;
      }
      if (mode.suffix.count(option)) {  // several files, FILE-<what>.png
        require_refused(c, mode.arguments + " " + option + " -", "not standard output");
        continue;
      }
      // The text that would be on standard output goes to a file instead.
      const std::string text =
          option != mode.text_option && !mode.text_option.empty() && option != "--html"
              ? " " + mode.text_option + " text.out"
              : "";
      const Run run = c.run(mode.arguments + " " + option + " -" + text);
      INFO("sweetspot " << mode.arguments << " " << option << " -" << text
                        << "\nstderr: " << run.err);
      CHECK(run.status == 0);
      CHECK(!fs::exists(c.path("-")));
      CHECK(!run.out.empty());
      CHECK(run.out.find("wrote") == std::string::npos);
      // The standard output is taken: a second output there is refused.
      if (!text.empty()) {
        require_refused(c, mode.arguments + " " + option + " -", "both name -");
      }
    }
  }
}

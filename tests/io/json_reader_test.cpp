#include "io/json_reader.hpp"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "io/input_error.hpp"

namespace sweetspot::io {
namespace {

namespace fs = std::filesystem;

class Folder {
 public:
  Folder() : dir_(fs::temp_directory_path() / ("sweetspot-json-" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~Folder() { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

constexpr std::size_t kSmallLimit = 1000;

TEST_CASE("A file up to the limit is read whole, one byte more is refused naming the file and the limit") {
  const Folder folder;
  const std::string at_limit = folder.path("at-limit.json");
  std::ofstream(at_limit) << "{}" << std::string(kSmallLimit - 2, ' ');
  CHECK(read_input_file(at_limit, kSmallLimit).size() == kSmallLimit);
  const std::string over = folder.path("over.json");
  std::ofstream(over) << "{}" << std::string(kSmallLimit - 1, ' ');
  CHECK_THROWS_WITH(read_input_file(over, kSmallLimit),
                    over + ": the file is larger than the limit of 1000 bytes for a design or study file");
  CHECK(read_input_file(over, std::size_t{1} << 20).size() == kSmallLimit + 1);
}

TEST_CASE("A device that never ends is read only up to the limit") {
  // /dev/zero reports size 0 and never ends: st_size cannot be trusted. Its
  // first chunk holds a NUL byte, so reading stops there and the parser says binary.
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(read_json_file("/dev/zero"), Catch::Contains("/dev/zero") && Catch::Contains("binary"));
  CHECK_THROWS_WITH(read_json_file("/dev/urandom"), Catch::Contains("/dev/urandom"));
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
}

TEST_CASE("A directory is said to be one, not an empty file") {
  const Folder folder;
  CHECK_THROWS_AS(read_json_file(folder.path("")), InputError);
  CHECK_THROWS_WITH(read_json_file(folder.path("")), Catch::Contains("is a directory"));
}

TEST_CASE("A read error is a run-time error naming the file, never the end of the input") {
  // Reading /proc/self/mem at offset 0 (unmapped) fails with EIO.
  try {
    read_input_file("/proc/self/mem", kMaxInputFileBytes);
    FAIL("no error");
  } catch (const InputError& e) {
    FAIL("an input error: " << e.what());
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "cannot read /proc/self/mem: Input/output error");
  }
}

TEST_CASE("A missing file is bad input with the system's reason") {
  const Folder folder;
  CHECK_THROWS_WITH(read_json_file(folder.path("nowhere.json")),
                    Catch::Contains("cannot open the file for reading: No such file or directory"));
}

TEST_CASE("The documented limit of a design or study file is 16 MiB") {
  CHECK(kMaxInputFileBytes == 16u * 1024 * 1024);
  CHECK(input_name("-") == "standard input");
  CHECK(input_name("d.json") == "d.json");
}

}  // namespace
}  // namespace sweetspot::io

#pragma once

// Strict JSON input: a parser that refuses duplicate keys, deep nesting,
// empty and binary files; and a reader for one JSON object that converts
// units by key suffix and refuses unknown keys. Every error is an InputError
// naming the source and the JSON pointer.

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot::io {

using Json = nlohmann::json;

// Deepest nesting accepted; real designs and studies use 4 or 5 levels.
// People's units the readers accept and the reports print, in SI, defined
// once: the inch, the square inch (head sizes) and the pound-force.
inline constexpr double kInch_m = 0.0254;
inline constexpr double kSquareInch_m2 = kInch_m * kInch_m;
inline constexpr double kPoundForce_N = 4.4482216152605;
inline constexpr double kKilogramForce_N = 9.80665;  // standard gravity times 1 kg

inline constexpr int kMaxJsonDepth = 64;

// Parses `text` as one JSON document. Throws InputError for empty or binary
// (NUL byte) input, syntax errors (with line and column), duplicate keys and
// nesting deeper than kMaxJsonDepth.
Json parse_json(std::string_view text, const std::string& source);

// Largest design or study file read (docs/command-line.md, "Limits on what is read"): 16 MiB.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{16} << 20;

// How messages name an input file: "-" is "standard input".
std::string input_name(const std::string& path);

// The whole of a file ("-": standard input), read in chunks. Throws
// InputError for a file that cannot be opened, a directory, or more than
// `limit_bytes` (stopping there: a device or FIFO need not end); a read error
// (EIO) is std::runtime_error, never taken for the end of the file. Stops
// early after a chunk holding a NUL byte, which no JSON text has.
std::string read_input_file(const std::string& path, std::size_t limit_bytes);

// Reads (read_input_file, kMaxInputFileBytes) and parses a file.
Json read_json_file(const std::string& path);

// Text for a JSON value in an error message, shortened to ~60 characters.
// A number is the shortest text that reads back to it (52, not JSON's 52.0).
std::string brief(const Json& value);

// The offset of the first byte of `text` that does not start a valid UTF-8
// sequence; std::string_view::npos when all of it is UTF-8.
std::size_t invalid_utf8_at(std::string_view text);

// `text` with each byte that is not part of a valid UTF-8 sequence replaced
// by U+FFFD: fit for a JSON string (a file name used as a design's name).
std::string valid_utf8(std::string_view text);

// A physical dimension and the unit suffixes accepted for it, each with its
// factor to SI ("_cm" length -> 0.01 m).
enum class Dimension {
  kLength,
  kMass,
  kTime,
  kSpeed,
  kInertia,
  kForce,
  kStiffness,
  kDamping,
  kFrequency,
  kLinearDensity,  // a string's mass per length
  kSpringRate      // a force per displacement (a string bed's stiffness)
};

// Every Dimension, for the loops that try each.
inline constexpr Dimension kAllDimensions[] = {
    Dimension::kLength,    Dimension::kMass,          Dimension::kTime,      Dimension::kSpeed,
    Dimension::kInertia,   Dimension::kForce,         Dimension::kStiffness, Dimension::kDamping,
    Dimension::kFrequency, Dimension::kLinearDensity, Dimension::kSpringRate};

// Every key that spells `base` in a unit of `dimension` ("mass" -> mass_kg, mass_g).
std::vector<std::string> spellings(std::string_view base, Dimension dimension);

// The factor to SI of `key` when it spells `base` in a unit of `dimension`
// ("from_tip_cm", "from_tip", kLength -> 0.01), as ObjectReader::quantity()
// applies it; std::nullopt when it does not.
std::optional<double> unit_factor(std::string_view key, std::string_view base, Dimension dimension);

// A unit's conversion to SI. A factor that is a power of ten in decimal (g,
// cm, mm, ms, kg cm^2) moves the decimal point of the number as the user
// wrote it (its shortest decimal form), so 282 g is the double nearest 0.282
// kg and 28.2 cm the double nearest 0.282 m; any other factor multiplies.
struct UnitScale {
  double factor = 1.0;   // SI per unit
  int power_of_ten = 0;  // factor == 10^power_of_ten exactly, or 0
  double to_si(double given) const;
};

// The double nearest value x 10^power_of_ten, value read as its shortest
// decimal form (the digits that read back as it).
double shift_decimal(double value, int power_of_ten);

// unit_factor() as a UnitScale, as ObjectReader::quantity() applies it.
std::optional<UnitScale> unit_scale(std::string_view key, std::string_view base,
                                    Dimension dimension);

// The other keys that give the same quantity as `key` in another unit or form
// ("mass_g" -> mass_kg; "balance_cm" -> balance_from_butt_m, balance_pts_hl;
// "from_tip_m" -> from_butt_m, ...). Empty for a key of no known quantity.
std::vector<std::string> alternative_spellings(std::string_view key);

// A JSON pointer's reference token: '~' and '/' escaped (RFC 6901).
std::string escape_pointer_token(std::string_view token);

// A path an override cannot take: an entry past the end of a list (the next
// one adds an entry; a later one would leave a gap of nulls). `pointer` is the
// entry's, `detail` says what the list holds.
class PathError : public std::invalid_argument {
 public:
  PathError(std::string pointer, std::string detail)
      : std::invalid_argument(pointer + ": " + detail),
        pointer_(std::move(pointer)),
        detail_(std::move(detail)) {}
  const std::string& pointer() const { return pointer_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string pointer_;
  std::string detail_;
};

// Sets document[pointer] = value, first removing the alternative spellings of
// the same quantity beside it, so that an override never contradicts a default.
// Throws PathError for an entry past the end of a list, Json::exception for a
// path through a value that is not an object.
void override_field(Json& document, const std::string& pointer, Json value);

// override_field() prepared once for a pointer set in many documents (a CSV
// column of a batch): the pointer parsed and its alternative spellings listed.
class FieldOverride {
 public:
  // Throws Json::exception when `pointer` is not a JSON pointer.
  explicit FieldOverride(const std::string& pointer);
  void apply(Json& document, Json value) const;
  // The pointers of the same quantity spelled in another object, which
  // apply() erases ("/strings/head_size_in2", ... for the implement's head).
  std::vector<std::string> elsewhere_pointers() const;

 private:
  Json::json_pointer at_;
  Json::json_pointer parent_;
  std::vector<std::string> alternatives_;
  // The same quantity spelled in another object (the head's size as
  // strings.head_size_in2 for implement.headsize_sq_in): that object and its keys.
  Json::json_pointer elsewhere_;
  std::vector<std::string> elsewhere_keys_;
};

// override_field() for every leaf of `patch` (objects are descended, anything
// else replaces): a design row laid over a base design.
void override_fields(Json& document, const Json& patch);

// Where each value was found: canonical SI name ("hand/mass_kg") -> the JSON
// pointer the user wrote ("/hand/mass_g") and the value as written there
// ("300"), so errors found later by the physics core point at the user's own
// key and quote the user's own value.
struct KeyOrigin {
  std::string pointer;
  Json given;  // the value in the file (null when absent), formatted only for a message
  // How the model's value came from the given one when not by a unit alone
  // ("less its tension_loss of 40 %"), for the message; "" for a unit.
  std::string derived_by = {};
};
using KeyMap = std::map<std::string, KeyOrigin>;

// The value as the file gave it, as brief() writes it; "" when absent.
std::string given_text(const KeyOrigin& origin);

// What is said of `key`, unknown where `expected` are the keys accepted:
// "unknown key; the mass is given as mass_kg or mass_g (expected one of: ...)"
// when the key, its words put in the reader's (weight is the mass, inch is
// in), names the stem of known keys in another unit; else the nearest keys in
// edit distance ("did you mean ...?"); else the list alone.
std::string unknown_key_detail(std::string_view key, const std::vector<std::string>& expected);

class ObjectReader {
 public:
  // `canonical` is the SI-named path of this object relative to the document
  // ("hand", "implement/sections/0"); `pointer` is its JSON pointer.
  ObjectReader(const Json& value, std::string pointer, std::string canonical,
               const std::string& source, KeyMap* keys);

  bool has(std::string_view key) const;
  const std::string& pointer() const { return pointer_; }
  std::string pointer_of(std::string_view key) const;
  const std::string& source() const { return source_; }

  // A finite number under `key`; std::nullopt when absent.
  std::optional<double> number(std::string_view key);
  // A quantity given under `base` + one unit suffix of `dimension`
  // ("mass" -> "mass_kg" | "mass_g"), converted to SI. Two spellings at once is
  // a contradiction. The canonical SI key is recorded in the KeyMap.
  std::optional<double> quantity(std::string_view base, Dimension dimension);
  // Which of several alternative keys is present (at most one); "" when none.
  std::string one_of(const std::vector<std::string>& keys) const;
  std::optional<std::string> string(std::string_view key);
  // A child object or array; marks the key as read.
  const Json* child(std::string_view key);
  // Records that canonical SI name `canonical_key` came from `key`.
  void record(std::string_view canonical_key, std::string_view key);

  // Throws for any key not read (an unknown key), naming the expected keys
  // (unknown_key_detail()); or, when `why_not` is given, saying that (a key
  // the object knows but this form of it does not take).
  void finish(const std::vector<std::string>& expected, std::string_view why_not = {}) const;
  // Throws for any key not in `known` (every key the object may hold, in any
  // form), before a missing key is complained of: a misspelt key is named.
  void check_known(const std::vector<std::string>& known) const;

  [[noreturn]] void fail(std::string_view key, const std::string& detail) const;

 private:
  const Json& object_;
  std::string pointer_;
  std::string canonical_;
  std::string source_;
  KeyMap* keys_;
  // The keys read, as views of the object's own keys (which outlive the reader).
  std::vector<std::string_view> read_;
  void mark_read(const std::string& own_key);
  // The value under one of the object's own keys as a finite number, marked read.
  double finite_number(const std::string& own_key, const Json& value);
};

}  // namespace sweetspot::io

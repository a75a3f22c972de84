#include "io/json_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "io/design_fields.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"

namespace sweetspot::io {
namespace {

// Builds the document while parsing, so that duplicate keys and depth are
// seen with the exact JSON pointer where they occur.
class StrictBuilder : public nlohmann::json_sax<Json> {
 public:
  explicit StrictBuilder(const std::string& source) : source_(source) {}

  Json take() { return std::move(root_); }

  bool null() override { return add(Json(nullptr)); }
  bool boolean(bool v) override { return add(Json(v)); }
  bool number_integer(number_integer_t v) override { return add(Json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return add(Json(v)); }
  bool number_float(number_float_t v, const string_t& text) override {
    if (!std::isfinite(v)) fail("number " + text + " is out of range, expected a finite number");
    return add(Json(v));
  }
  bool string(string_t& v) override { return add(Json(std::move(v))); }
  bool binary(binary_t&) override { fail("binary values are not JSON text"); }
  bool start_object(std::size_t) override { return open(Json::object()); }
  bool key(string_t& k) override {
    Json& object = *stack_.back().value;
    if (object.contains(k)) fail("duplicate key \"" + k + "\" (each key may appear once)", k);
    stack_.back().key = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string& token,
                   const nlohmann::detail::exception& e) override {
    constexpr int kNumberOverflow = 406;  // nlohmann's id for a number beyond double
    if (e.id == kNumberOverflow)
      fail("number " + token + " is out of range, expected a finite number");
    // The line and column say where; a pointer would name the last complete value.
    throw InputError(source_, "", invalid_json_message(e.what()));
  }

 private:
  struct Open {
    Json* value;
    std::string key;  // pending key (objects)
  };

  // Pointer of the innermost open container: each open container is the last
  // child inserted into the one before it.
  std::string container_pointer() const {
    std::string pointer;
    for (std::size_t i = 0; i + 1 < stack_.size(); ++i) {
      const Open& parent = stack_[i];
      pointer += "/" + (parent.value->is_object() ? escape_pointer_token(parent.key)
                                                  : std::to_string(parent.value->size() - 1));
    }
    return pointer;
  }

  // Pointer of the slot about to be filled, or of `key` in the innermost object.
  std::string current_pointer(std::string_view key = {}) const {
    if (stack_.empty()) return "";
    const Open& inner = stack_.back();
    std::string token = !key.empty()               ? escape_pointer_token(key)
                        : inner.value->is_object() ? escape_pointer_token(inner.key)
                                                   : std::to_string(inner.value->size());
    return container_pointer() + "/" + token;
  }

  [[noreturn]] void fail(const std::string& detail, std::string_view key = {}) const {
    throw InputError(source_, current_pointer(key), detail);
  }

  static std::string invalid_json_message(const std::string& what) {
    // nlohmann: "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error
    // ..."
    const auto at = what.find("] ");
    std::string text = at == std::string::npos ? what : what.substr(at + 2);
    return "not valid JSON: " + text;
  }

  Json* insert(Json value) {
    if (stack_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Json& parent = *stack_.back().value;
    if (parent.is_object()) return &(parent[stack_.back().key] = std::move(value));
    parent.push_back(std::move(value));
    return &parent.back();
  }

  bool add(Json value) {
    insert(std::move(value));
    return true;
  }

  bool open(Json container) {
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
      fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    Json* value = insert(std::move(container));
    stack_.push_back(Open{value, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  const std::string& source_;
  Json root_;
  std::vector<Open> stack_;
};

}  // namespace

namespace {

// `token` escaped for a JSON pointer (RFC 6901: ~ as ~0, / as ~1), appended to `out`.
void append_pointer_token(std::string& out, std::string_view token) {
  if (std::none_of(token.begin(), token.end(), [](char c) { return c == '~' || c == '/'; })) {
    out.append(token);
    return;
  }
  for (const char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
}

}  // namespace

std::string escape_pointer_token(std::string_view token) {
  std::string out;
  append_pointer_token(out, token);
  return out;
}

Json parse_json(std::string_view text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw InputError(source, "", "the file is empty, expected a JSON object");
  }
  if (text.find('\0') != std::string_view::npos) {
    throw InputError(source, "", "the file is binary (it contains NUL bytes), expected JSON text");
  }
  StrictBuilder builder(source);
  Json::sax_parse(text, &builder, nlohmann::json::input_format_t::json, true);
  return builder.take();
}

std::string input_name(const std::string& path) { return path == "-" ? "standard input" : path; }

std::string read_input_file(const std::string& path, std::size_t limit_bytes) {
  const std::string name = input_name(path);
  const bool standard_input = path == "-";
  const int fd =
      standard_input ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    throw InputError(name, "",
                     std::string("cannot open the file for reading: ") + std::strerror(errno));
  }
  struct Closer {
    int fd;
    bool owned;
    ~Closer() {
      if (owned) ::close(fd);
    }
  } closer{fd, !standard_input};
  const std::string limit_text =
      "the file is larger than the limit of " +
      (limit_bytes % (1 << 20) == 0 ? std::to_string(limit_bytes >> 20) + " MiB"
                                    : std::to_string(limit_bytes) + " bytes") +
      " for a design or study file";
  struct stat info {};
  if (::fstat(fd, &info) != 0)
    throw std::runtime_error("cannot read " + name + ": " + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw InputError(name, "", "is a directory, expected a JSON file");
  // st_size is trusted only to refuse a regular file early: devices, FIFOs
  // and /proc files are read, and stopped at the limit.
  if (S_ISREG(info.st_mode) && static_cast<std::uintmax_t>(info.st_size) > limit_bytes) {
    throw InputError(name, "", limit_text);
  }
  std::string text;
  std::array<char, 1 << 16> chunk{};
  for (;;) {
    const ssize_t n = ::read(fd, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error("cannot read " + name + ": " + std::strerror(errno));
    if (n == 0) break;
    text.append(chunk.data(), static_cast<std::size_t>(n));
    if (text.size() > limit_bytes) throw InputError(name, "", limit_text);
    // Binary input (/dev/zero, /dev/urandom) is refused by parse_json at its first NUL byte.
    if (std::memchr(chunk.data(), '\0', static_cast<std::size_t>(n))) break;
  }
  return text;
}

Json read_json_file(const std::string& path) {
  return parse_json(read_input_file(path, kMaxInputFileBytes), input_name(path));
}

std::string brief(const Json& value) {
  // A number as the shortest text that reads back to it (52, 1000000000),
  // not the 52.0 and 1000000000.0 JSON writes for a double.
  if (value.is_number_float() && std::isfinite(value.get<double>()))
    return exact(value.get<double>());
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::string given_text(const KeyOrigin& origin) {
  return origin.given.is_null() ? std::string() : brief(origin.given);
}

namespace {

// The length of the valid UTF-8 sequence starting at text[i], 0 if none.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xbf;  // the range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf)
    length = 2;
  else if (lead == 0xe0)
    length = 3, low = 0xa0;
  else if (lead == 0xed)
    length = 3, high = 0x9f;  // no UTF-16 surrogates
  else if (lead >= 0xe1 && lead <= 0xef)
    length = 3;
  else if (lead == 0xf0)
    length = 4, low = 0x90;
  else if (lead == 0xf4)
    length = 4, high = 0x8f;  // nothing beyond U+10FFFF
  else if (lead >= 0xf1 && lead <= 0xf3)
    length = 4;
  else
    return 0;
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  }
  return length;
}

}  // namespace

std::size_t invalid_utf8_at(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) return i;
    i += length;
  }
  return std::string_view::npos;
}

std::string valid_utf8(std::string_view text) {
  if (invalid_utf8_at(text) == std::string_view::npos) return std::string(text);
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) {
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
      ++i;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

namespace {

struct Unit {
  std::string_view suffix;
  double to_si;
  int power_of_ten = 0;  // to_si is 10^power_of_ten exactly in decimal (0: not, or 1)
  UnitScale scale() const { return UnitScale{to_si, power_of_ten}; }
};

const std::vector<Unit>& units(Dimension dimension) {
  static const std::vector<Unit> length{
      {"_m", 1.0}, {"_cm", 0.01, -2}, {"_mm", 0.001, -3}, {"_in", kInch_m}};
  static const std::vector<Unit> mass{{"_kg", 1.0}, {"_g", 0.001, -3}};
  static const std::vector<Unit> time{{"_s", 1.0}, {"_ms", 0.001, -3}};
  static const std::vector<Unit> speed{{"_m_s", 1.0}, {"_km_h", 1.0 / 3.6}, {"_mph", 0.44704}};
  static const std::vector<Unit> inertia{{"_kg_m2", 1.0}, {"_kg_cm2", 1e-4, -4}};
  static const std::vector<Unit> force{
      {"_N", 1.0}, {"_lb", kPoundForce_N}, {"_kg", kKilogramForce_N}};
  static const std::vector<Unit> stiffness{{"_N_m2", 1.0}};
  static const std::vector<Unit> damping{{"_N_s_m2", 1.0}};
  static const std::vector<Unit> frequency{{"_Hz", 1.0}};
  static const std::vector<Unit> linear_density{{"_kg_m", 1.0}, {"_g_m", 0.001, -3}};
  static const std::vector<Unit> spring_rate{{"_N_m", 1.0}, {"_lb_in", kPoundForce_N / kInch_m}};
  switch (dimension) {
    case Dimension::kLength:
      return length;
    case Dimension::kMass:
      return mass;
    case Dimension::kTime:
      return time;
    case Dimension::kSpeed:
      return speed;
    case Dimension::kInertia:
      return inertia;
    case Dimension::kForce:
      return force;
    case Dimension::kStiffness:
      return stiffness;
    case Dimension::kDamping:
      return damping;
    case Dimension::kFrequency:
      return frequency;
    case Dimension::kLinearDensity:
      return linear_density;
    case Dimension::kSpringRate:
      return spring_rate;
  }
  return length;
}

}  // namespace

std::vector<std::string> spellings(std::string_view base, Dimension dimension) {
  std::vector<std::string> keys;
  for (const Unit& unit : units(dimension))
    keys.push_back(std::string(base) + std::string(unit.suffix));
  return keys;
}

namespace {

// Which of units(dimension) `key` spells `base` in, if any.
std::optional<std::size_t> unit_index(std::string_view key, std::string_view base,
                                      Dimension dimension) {
  if (!key.starts_with(base)) return std::nullopt;
  const std::vector<Unit>& list = units(dimension);
  for (std::size_t u = 0; u < list.size(); ++u) {
    if (key.substr(base.size()) == list[u].suffix) return u;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> unit_factor(std::string_view key, std::string_view base,
                                  Dimension dimension) {
  const auto u = unit_index(key, base, dimension);
  if (!u) return std::nullopt;
  return units(dimension)[*u].to_si;
}

std::optional<UnitScale> unit_scale(std::string_view key, std::string_view base,
                                    Dimension dimension) {
  const auto u = unit_index(key, base, dimension);
  if (!u) return std::nullopt;
  return units(dimension)[*u].scale();
}

double shift_decimal(double value, int power_of_ten) {
  if (power_of_ten == 0 || !std::isfinite(value) || value == 0.0) return value;
  // The shortest decimal that reads back as `value` (the digits the user
  // typed, when they typed at most 15), its exponent moved, read again.
  char text[48];
  const auto written = std::to_chars(text, text + 32, value, std::chars_format::scientific);
  if (written.ec != std::errc()) return value * std::pow(10.0, power_of_ten);
  char* e = std::find(text, written.ptr, 'e');
  int exponent = 0;
  std::from_chars(e[1] == '+' ? e + 2 : e + 1, written.ptr, exponent);
  exponent += power_of_ten;
  const auto end = std::to_chars(e + 1, text + sizeof text, exponent).ptr;
  double shifted = 0.0;
  const auto read = std::from_chars(text, end, shifted);
  if (read.ec != std::errc()) return value * std::pow(10.0, power_of_ten);  // underflow: tiny
  return shifted;
}

double UnitScale::to_si(double given) const {
  return power_of_ten != 0 ? shift_decimal(given, power_of_ten) : given * factor;
}

std::vector<std::string> alternative_spellings(std::string_view key) {
  // Quantities that can be given in more than one form, not just another unit.
  static const std::vector<std::vector<std::string>> kForms{
      {"balance_from_butt_m", "balance_cm", "balance_pts_hl"},
      {"from_tip", "from_butt"},
      {"mass", "equivalent_mass"},       // the forearm: M_F or M_e
      {"EI", "fundamental_free", "RA"},  // the frame's stiffness
      {"cor", "cor_rigid"},              // the frame's COR, or the one it is derived from
      {"impact_duration", "tension"},    // the strings' duration, or the tension it is derived from
  };
  std::vector<std::string> out;
  const auto add_all_units = [&](std::string_view base) {
    for (const Dimension d : kAllDimensions) {
      for (const std::string& k : spellings(base, d)) {
        if (k != key && std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
      }
    }
  };
  for (const Dimension d : kAllDimensions) {
    for (const Unit& unit : units(d)) {
      if (key.size() <= unit.suffix.size() || !key.ends_with(unit.suffix)) continue;
      const std::string base(key.substr(0, key.size() - unit.suffix.size()));
      add_all_units(base);
      for (const auto& form : kForms) {
        if (std::find(form.begin(), form.end(), base) == form.end()) continue;
        for (const std::string& other : form) {
          add_all_units(other);
          if (other == "RA" && std::find(out.begin(), out.end(), other) == out.end())
            out.push_back(other);  // a number without a unit
        }
      }
    }
  }
  for (const auto& form : kForms) {
    if (std::find(form.begin(), form.end(), std::string(key)) == form.end()) continue;
    for (const std::string& other : form) {
      if (other == key) continue;
      out.push_back(other);
      if (key == "RA") add_all_units(other);  // EI_N_m2, fundamental_free_Hz
    }
  }
  return out;
}

FieldOverride::FieldOverride(const std::string& pointer)
    : at_(pointer),
      parent_(at_.parent_pointer()),
      alternatives_(alternative_spellings(at_.back())) {
  // The design's field table spells some quantities in keys of their own
  // (headsize_sq_in or headsize_cm2; angular_speed_rad_s or _rpm), and a
  // swing's speed in another form (speed_at_impact): each other spelling of
  // the row, and of the rows that give it another way, goes too.
  static constexpr std::string_view kOtherForms[][2] = {
      {"angular_speed", "speed_at_impact"},
      // A lead's place: from the butt, from the tip, or on the hoop by the clock.
      {"clock", "from_butt"},
      {"clock", "from_tip"}};
  // A place on the hoop has no offset of its own: a clock given erases one.
  static constexpr std::string_view kErasedBy[][2] = {{"clock", "off_axis"}};
  if (at_.empty()) return;
  const std::string object = design_object_of(
      parent_.to_string().substr(std::min<std::size_t>(1, parent_.to_string().size())));
  const auto spelling = find_spelling(object, at_.back());
  if (!spelling) return;
  const auto add_row = [&](std::string_view stem) {
    for (const DesignField& field : design_fields()) {
      if (field.object != object || field.stem != stem) continue;
      for (std::string& key : spellings_of(field)) {
        if (key != at_.back() &&
            std::find(alternatives_.begin(), alternatives_.end(), key) == alternatives_.end())
          alternatives_.push_back(std::move(key));
      }
    }
  };
  add_row(spelling->field->stem);
  for (const auto& form : kOtherForms) {
    if (form[0] == spelling->field->stem) add_row(form[1]);
    if (form[1] == spelling->field->stem) add_row(form[0]);
  }
  for (const auto& erased : kErasedBy) {
    if (erased[0] == spelling->field->stem) add_row(erased[1]);
  }
  // One head, one size: the implement's head and the string bed's are one
  // quantity in two objects, so a value given for either replaces both.
  static constexpr std::string_view kOneQuantity[][2][2] = {
      {{"implement", "headsize"}, {"strings", "head_size"}}};
  for (const auto& pair : kOneQuantity) {
    for (int side = 0; side < 2; ++side) {
      if (pair[side][0] != object || pair[side][1] != spelling->field->stem) continue;
      const std::string_view other_object = pair[1 - side][0];
      elsewhere_ = parent_.parent_pointer() / std::string(other_object);
      for (const DesignField& field : design_fields()) {
        if (field.object != other_object || field.stem != pair[1 - side][1]) continue;
        for (std::string& key : spellings_of(field)) elsewhere_keys_.push_back(std::move(key));
      }
    }
  }
}

namespace {

// Refuses a path that would index a list past its next entry: nlohmann::json
// would fill the gap with nulls, and the reader then blame the first of them.
// A list made by the path (absent from the document) is empty: only its entry
// 0 can be set.
void check_list_indices(const Json& document, Json::json_pointer at) {
  std::vector<std::string> tokens;
  for (; !at.empty(); at.pop_back()) tokens.push_back(at.back());
  const auto index_of = [](const std::string& token) -> std::optional<std::size_t> {
    std::size_t index = 0;
    const char* first = token.data();
    const char* last = first + token.size();
    const auto [end, error] = std::from_chars(first, last, index);
    if (token.empty() || error != std::errc() || end != last) return std::nullopt;
    return index;
  };
  const Json* here = &document;
  Json::json_pointer walked;
  for (auto token = tokens.rbegin(); token != tokens.rend(); ++token) {
    walked /= *token;
    if (!here) {  // made by the path: a number is an entry of a list made empty
      const auto index = index_of(*token);
      if (index && *index > 0)
        throw PathError(walked.to_string(), "the list is empty: add its first entry, 0");
      continue;
    }
    if (here->is_array()) {
      const auto index = index_of(*token);
      if (!index && *token == "-") return;  // RFC 6901's next entry: nlohmann's to append
      if (!index) {
        throw PathError(
            walked.to_string(),
            "a list's entry is named by its index, a whole number from 0, got \"" + *token + "\"");
      }
      const std::size_t size = here->size();
      if (*index > size) {
        const std::string n = std::to_string(size);
        throw PathError(walked.to_string(),
                        size == 0 ? "the list is empty: add its first entry, 0"
                                  : "the list has " + n + (size == 1 ? " entry" : " entries") +
                                        " (0 to " + std::to_string(size - 1) +
                                        "): set one of them, or add the next, " + n);
      }
      here = *index == size ? nullptr : &(*here)[*index];  // the next: a new entry
    } else if (here->is_object()) {
      const auto found = here->find(*token);
      here = found == here->end() ? nullptr : &*found;
    } else if (here->is_null()) {
      here = nullptr;
      if (const auto index = index_of(*token); index && *index > 0)
        throw PathError(walked.to_string(), "the list is empty: add its first entry, 0");
    } else {
      return;  // through a number or a text: nlohmann's to say
    }
  }
}

}  // namespace

void FieldOverride::apply(Json& document, Json value) const {
  check_list_indices(document, at_);
  Json& parent = document[parent_];
  if (parent.is_object()) {
    for (const std::string& other : alternatives_) parent.erase(other);
  }
  if (!elsewhere_keys_.empty() && document.contains(elsewhere_)) {
    Json& other = document[elsewhere_];
    if (other.is_object()) {
      for (const std::string& key : elsewhere_keys_) other.erase(key);
    }
  }
  document[at_] = std::move(value);
}

std::vector<std::string> FieldOverride::elsewhere_pointers() const {
  std::vector<std::string> out;
  for (const std::string& key : elsewhere_keys_) out.push_back((elsewhere_ / key).to_string());
  return out;
}

void override_field(Json& document, const std::string& pointer, Json value) {
  FieldOverride(pointer).apply(document, std::move(value));
}

namespace {

void override_below(Json& document, const Json& patch, const std::string& pointer) {
  for (const auto& [key, value] : patch.items()) {
    const std::string at = pointer + "/" + escape_pointer_token(key);
    // A patch that itself gives a quantity twice (mass_kg and mass_g) is
    // refused, as a design file is: neither spelling may silently win.
    for (const std::string& other : alternative_spellings(key)) {
      if (other != key && patch.contains(other)) {
        throw std::invalid_argument(at + ": contradicts " + pointer + "/" +
                                    escape_pointer_token(other) +
                                    ": give the quantity once, in one unit");
      }
    }
    if (value.is_object() && !value.empty()) {
      override_below(document, value, at);
    } else {
      override_field(document, at, value);
    }
  }
}

}  // namespace

void override_fields(Json& document, const Json& patch) {
  if (!patch.is_object()) {
    document = patch;
    return;
  }
  if (!document.is_object()) document = Json::object();
  override_below(document, patch, "");
  // A quantity spelled in two objects (the head's size as the implement's and
  // as the string bed's): a leaf set later erased one the patch gave too. Each
  // leaf the patch gives is put back, so that the design read says whether
  // the two agree, as it says for a file that gives both.
  const auto restore = [&](const auto& self, const Json& below,
                           const std::string& pointer) -> void {
    for (const auto& [key, value] : below.items()) {
      const std::string at = pointer + "/" + escape_pointer_token(key);
      if (value.is_object() && !value.empty()) {
        self(self, value, at);
      } else {
        document[Json::json_pointer(at)] = value;
      }
    }
  };
  restore(restore, patch, "");
}

namespace {

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// Unit suffixes that end a key without being a unit of units() (areas, points).
constexpr std::string_view kOtherSuffixes[] = {"_sq_in", "_in2", "_cm2", "_pts_hl"};

// `key` without its unit suffix (the longest that leaves a stem), "" when it has none.
std::string_view stem_of(std::string_view key) {
  std::size_t longest = 0;
  const auto consider = [&](std::string_view suffix) {
    if (key.size() > suffix.size() && key.ends_with(suffix) && suffix.size() > longest)
      longest = suffix.size();
  };
  for (const Dimension d : kAllDimensions) {
    for (const Unit& unit : units(d)) consider(unit.suffix);
  }
  for (const std::string_view suffix : kOtherSuffixes) consider(suffix);
  if (longest == 0) return "";
  std::string_view stem = key.substr(0, key.size() - longest);
  if (stem == "balance_from_butt") stem = "balance";  // balance_from_butt_m, balance_cm, _pts_hl
  return stem;
}

std::string without_underscores(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c != '_') out += c;
  }
  return out;
}

// A key as people mistype it, in the reader's words: lower case, and the
// words of a small synonym list replaced (weight is the mass, inch is in).
std::string normalised(std::string_view key) {
  static const std::vector<std::pair<std::string_view, std::string_view>> kSynonyms{
      {"weight", "mass"}, {"wt", "mass"},       {"inch", "in"},   {"inches", "in"}, {"lbs", "lb"},
      {"pounds", "lb"},   {"pound", "lb"},      {"grams", "g"},   {"gram", "g"},    {"kgs", "kg"},
      {"hz", "Hz"},       {"n", "N"},           {"kmh", "km_h"},  {"kph", "km_h"},  {"sec", "s"},
      {"msec", "ms"},     {"secs", "s"},        {"metres", "m"},  {"meters", "m"},  {"cms", "cm"},
      {"pts", "pts_hl"},  {"points", "pts_hl"}, {"sqin", "sq_in"}};
  std::string lower;
  for (const char c : key) lower += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  std::string out;
  std::size_t start = 0;
  while (start <= lower.size()) {
    const std::size_t end = std::min(lower.find('_', start), lower.size());
    std::string word = lower.substr(start, end - start);
    for (const auto& [typed, meant] : kSynonyms) {
      if (word == typed) word = meant;
    }
    if (!out.empty()) out += '_';
    out += word;
    start = end + 1;
  }
  return out;
}

// Words that end a key as a unit the reader may not accept ("weight_oz").
bool is_unit_word(std::string_view word) {
  constexpr std::string_view kWords[] = {"oz",  "ounce", "ounces", "lb",    "g",  "kg", "m",  "cm",
                                         "mm",  "in",    "ft",     "feet",  "s",  "ms", "Hz", "N",
                                         "mph", "km_h",  "pct",    "sq_in", "yd", "mg"};
  return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string or_list(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    text += i == 0 ? "" : i + 1 == items.size() ? " or " : ", ";
    text += items[i];
  }
  return text;
}

}  // namespace

std::string unknown_key_detail(std::string_view key, const std::vector<std::string>& expected) {
  const std::string list = " (expected one of: " + join(expected) + ")";
  constexpr std::size_t kLongestSuggested = 64;  // a longer key is no typing slip
  if (key.empty() || key.size() > kLongestSuggested || expected.empty())
    return "unknown key" + list;
  const std::string typed = normalised(key);
  // The stem the user meant: the key without a unit the reader knows, or
  // without a last word that reads as a unit, or the key itself.
  std::vector<std::string> stems;
  if (const std::string_view stem = stem_of(typed); !stem.empty()) stems.emplace_back(stem);
  const std::size_t last = typed.rfind('_');
  if (last != std::string::npos && is_unit_word(typed.substr(last + 1)))
    stems.push_back(typed.substr(0, last));
  if (typed.size() > 6 && typed.ends_with("_km_h"))
    stems.push_back(typed.substr(0, typed.size() - 5));
  stems.push_back(typed);
  for (const std::string& stem : stems) {
    std::vector<std::string> same;
    for (const std::string& known : expected) {
      const std::string_view known_stem = stem_of(known);
      const std::string_view base = known_stem.empty() ? std::string_view(known) : known_stem;
      if (without_underscores(base) == without_underscores(stem)) same.push_back(known);
    }
    if (!same.empty()) {
      std::string words(same.size() == 1 && stem_of(same.front()).empty() ? same.front() : stem);
      std::replace(words.begin(), words.end(), '_', ' ');
      return "unknown key; the " + words + " is given as " + or_list(same) + list;
    }
  }
  // A slip of the keyboard: the known keys nearest in edit distance.
  std::size_t best = std::max<std::size_t>(1, std::min<std::size_t>(3, typed.size() / 4)) + 1;
  std::vector<std::string> nearest;
  for (const std::string& known : expected) {
    const std::size_t d = edit_distance(typed, known);
    if (d < best) {
      best = d;
      nearest.clear();
    }
    if (d == best) nearest.push_back(known);
  }
  if (!nearest.empty() && nearest.size() <= 3)
    return "unknown key; did you mean " + or_list(nearest) + "?" + list;
  return "unknown key" + list;
}

ObjectReader::ObjectReader(const Json& value, std::string pointer, std::string canonical,
                           const std::string& source, KeyMap* keys)
    : object_(value),
      pointer_(std::move(pointer)),
      canonical_(std::move(canonical)),
      source_(source),
      keys_(keys) {
  if (!object_.is_object()) {
    throw InputError(source_, pointer_.empty() ? "/" : pointer_,
                     "expected a JSON object, got " + brief(object_));
  }
}

bool ObjectReader::has(std::string_view key) const { return object_.contains(key); }

std::string ObjectReader::pointer_of(std::string_view key) const {
  std::string pointer;
  pointer.reserve(pointer_.size() + 1 + key.size());
  pointer.append(pointer_).push_back('/');
  append_pointer_token(pointer, key);
  return pointer;
}

void ObjectReader::fail(std::string_view key, const std::string& detail) const {
  throw InputError(source_, key.empty() ? pointer_ : pointer_of(key), detail);
}

void ObjectReader::record(std::string_view canonical_key, std::string_view key) {
  if (!keys_) return;
  std::string name;
  name.reserve(canonical_.size() + 1 + canonical_key.size());
  if (!canonical_.empty()) name.append(canonical_).append("/");
  name.append(canonical_key);
  const auto it = object_.find(key);
  keys_->insert_or_assign(std::move(name),
                          KeyOrigin{pointer_of(key), it == object_.end() ? Json() : *it});
}

void ObjectReader::mark_read(const std::string& own_key) {
  if (std::find(read_.begin(), read_.end(), own_key) == read_.end()) read_.push_back(own_key);
}

double ObjectReader::finite_number(const std::string& own_key, const Json& value) {
  mark_read(own_key);
  if (!value.is_number()) fail(own_key, "expected a number, got " + brief(value));
  const double number = value.get<double>();
  if (!std::isfinite(number)) fail(own_key, "expected a finite number, got " + brief(value));
  return number;
}

std::optional<double> ObjectReader::number(std::string_view key) {
  const auto it = object_.find(key);
  if (it == object_.end()) return std::nullopt;
  record(key, key);
  return finite_number(it.key(), *it);
}

std::optional<double> ObjectReader::quantity(std::string_view base, Dimension dimension) {
  // The keys spelling `base` in a unit of `dimension`, found by one pass over
  // the object (no key is built), then taken in the units' order.
  const std::vector<Unit>& list = units(dimension);
  std::array<const std::string*, 8> present{};
  bool any = false;
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    const auto u = unit_index(it.key(), base, dimension);
    if (u && *u < present.size()) {
      present[*u] = &it.key();
      any = true;
    }
  }
  if (!any) return std::nullopt;
  std::optional<double> result;
  const std::string* found = nullptr;
  for (std::size_t u = 0; u < list.size() && u < present.size(); ++u) {
    if (!present[u]) continue;
    if (found)
      fail(*present[u],
           "contradicts " + pointer_of(*found) + ": give the quantity once, in one unit");
    found = present[u];
    const double given = finite_number(*found, object_[*found]);
    result = list[u].scale().to_si(given);
    if (!std::isfinite(*result)) {
      fail(*found, "too large: " + brief(object_[*found]) + " overflows when converted to SI (" +
                       std::string(list.front().suffix.substr(1)) + ")");
    }
  }
  record(std::string(base) + std::string(list.front().suffix), *found);
  return result;
}

std::string ObjectReader::one_of(const std::vector<std::string>& keys) const {
  std::string found;
  for (const auto& key : keys) {
    if (!has(key)) continue;
    if (!found.empty()) fail(key, "contradicts " + pointer_of(found) + ": give only one of them");
    found = key;
  }
  return found;
}

std::optional<std::string> ObjectReader::string(std::string_view key) {
  const auto it = object_.find(key);
  if (it == object_.end()) return std::nullopt;
  mark_read(it.key());
  if (!it->is_string()) fail(key, "expected a string, got " + brief(*it));
  return it->get<std::string>();
}

const Json* ObjectReader::child(std::string_view key) {
  const auto it = object_.find(key);
  if (it == object_.end()) return nullptr;
  mark_read(it.key());
  return &*it;
}

void ObjectReader::finish(const std::vector<std::string>& expected,
                          std::string_view why_not) const {
  for (const auto& [key, value] : object_.items()) {
    if (std::find(read_.begin(), read_.end(), key) != read_.end()) continue;
    if (!why_not.empty()) fail(key, std::string(why_not));
    // A key this object knows that nothing given here reads: not "unknown".
    if (std::find(expected.begin(), expected.end(), key) != expected.end())
      fail(key, "is not read beside what else " + (pointer_.empty() ? "the file" : pointer_) +
                    " gives: it belongs with keys that are missing");
    fail(key, unknown_key_detail(key, expected));
  }
}

void ObjectReader::check_known(const std::vector<std::string>& known) const {
  for (const auto& [key, value] : object_.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end())
      fail(key, unknown_key_detail(key, known));
  }
}

}  // namespace sweetspot::io

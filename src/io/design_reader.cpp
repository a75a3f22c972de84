#include "io/design_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "io/design_fields.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::io {
namespace {

// The parts of a design file; the physics core names an input by its
// canonical SI path below one of them ("hand/grip_length_m").
constexpr std::string_view kDesignParts[] = {"implement", "frame",  "strings", "hand",   "forearm",
                                             "ball",      "impact", "swing",   "support"};

// /frame/cross_section/shape: each shape's name in a design file.
constexpr std::pair<std::string_view, CrossSection::Shape> kSectionShapes[] = {
    {"rectangle", CrossSection::Shape::kRectangle},
    {"circle", CrossSection::Shape::kCircle},
    {"hollow_circle", CrossSection::Shape::kHollowCircle},
    {"ellipse", CrossSection::Shape::kEllipse},
    {"box", CrossSection::Shape::kBox},
    {"profile", CrossSection::Shape::kProfile}};

std::string section_shape_name(CrossSection::Shape shape) {
  for (const auto& [name, s] : kSectionShapes)
    if (s == shape) return std::string(name);
  return "rectangle";
}

bool is_design_path(std::string_view name) {
  const std::string_view part = name.substr(0, name.find('/'));
  if (std::find(std::begin(kDesignParts), std::end(kDesignParts), part) == std::end(kDesignParts))
    return false;
  return name.find_first_not_of(
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_/") ==
         std::string_view::npos;
}

// A range the core refused a value by, stated again in the unit of the file's
// key when the file gave the quantity in another unit ("must be in [4.496,
// 224.8] lb (20 to 1000 N), got 230 lb"), or nothing when it cannot be: no
// range, a value not a number, no unit in the key. The file's unit is the
// ratio of the core's SI value to the value the file gave (every scale of
// the field table is a factor).
// "must be in [4.496, 224.8] lb (20 to 1000 N) WHY, got 230 lb": a range
// [min, max] (SI) stated in a file's unit (per_unit SI in one of it), the SI
// beside it, and the value as the file gave it.
std::string range_in_unit(double min, double max, bool min_open, double per_unit,
                          std::string_view unit, std::string_view si_unit, std::string_view why,
                          const std::string& given, bool max_open = false) {
  std::string text = std::string("must be in ") + (min_open ? "(" : "[") +
                     significant(min / per_unit, 4) + ", " + significant(max / per_unit, 4) +
                     (max_open ? ") " : "] ") + std::string(unit);
  // The SI beside it, when the core's name says its unit ("headsize" does not).
  if (!si_unit.empty())
    text += " (" + significant(min, 4) + " to " + significant(max, 4) + " " + std::string(si_unit) +
            ")";
  if (!why.empty()) text += " " + std::string(why);
  return text + ", got " + given + " " + std::string(unit);
}

std::optional<std::string> range_in_file_unit(const std::invalid_argument& error,
                                              const KeyOrigin& origin, const std::string& si_key,
                                              const std::string& user_key,
                                              const std::string& canonical) {
  const auto* typed = dynamic_cast<const FieldError*>(&error);
  if (!typed || !typed->range() || !origin.given.is_number()) return std::nullopt;
  const FieldError::Range& range = *typed->range();
  const double given = origin.given.get<double>();
  double per_unit = range.value / given;  // SI per file unit
  if (given == 0.0) {
    // 0 in any unit: the unit's factor from the field table ("hand/...": the
    // object "hand"; "implement/point_masses/2/...": "implement/point_masses/N").
    const std::size_t last = canonical.rfind('/');
    const std::string object =
        last == std::string::npos ? "" : design_object_of(canonical.substr(0, last));
    if (const auto spelling = find_spelling(object, user_key))
      per_unit = spelling->scale.to_si(1.0);
  }
  const std::string unit(unit_of_key(user_key));
  const std::string si_unit(unit_of_key(si_key));
  // A subnormal value has lost the digits the ratio needs (1e-320 g is not
  // 1e-323 kg to three figures).
  if (!(std::isfinite(per_unit) && per_unit > 0.0) || unit.empty() ||
      (range.value != 0.0 && !(std::fabs(range.value) >= std::numeric_limits<double>::min())))
    return std::nullopt;
  if (std::isfinite(range.min) && std::isfinite(range.max)) {
    return range_in_unit(range.min, range.max, range.min_open, per_unit, unit, si_unit, range.why,
                         given_text(origin), range.max_open) +
           typed->after();
  }
  if (!std::isfinite(range.min)) return std::nullopt;
  return std::string("must be ") + (range.min_open ? "> " : ">= ") +
         significant(range.min / per_unit, 4) + " " + unit + ", got " + given_text(origin) + " " +
         unit + typed->after();
}

// Whether two keys of the object of `canonical` ("ball/speed_m_s") spell one
// field of the table in two units ("speed_m_s" and "speed_km_h", whose stems
// a split at the last '_' tells apart).
bool same_field(const std::string& canonical, std::string_view a, std::string_view b) {
  const std::size_t last = canonical.rfind('/');
  const std::string object =
      last == std::string::npos ? "" : design_object_of(canonical.substr(0, last));
  const auto field_a = find_spelling(object, a), field_b = find_spelling(object, b);
  return field_a && field_b && field_a->field == field_b->field;
}

// The physics core names a bad argument by its canonical SI path relative to
// the document ("hand/mass_kg: must be ..."), or relative to the implement
// for its lists ("sections/0/length_m", "point_masses/1/mass_kg"); point the
// error at the key the user actually wrote and quote the value written there.
[[noreturn]] void rethrow_at(const std::invalid_argument& error, const std::string& prefix,
                             const KeyMap& keys, const std::string& source,
                             const std::string& fallback_pointer) {
  const std::string message = error.what();
  // The core names the field by type (FieldError); what is left of its
  // messages as text ("options.", a validate() string) is "field: detail".
  const auto* typed = dynamic_cast<const FieldError*>(&error);
  const auto colon = typed ? std::string::npos : message.find(": ");
  if (typed || colon != std::string::npos) {
    const std::string core_name = typed ? typed->field() : message.substr(0, colon);
    std::string detail = typed ? typed->detail() : message.substr(colon + 2);
    std::string name = prefix + core_name;
    if (prefix.empty() &&
        (core_name.starts_with("sections") || core_name.starts_with("point_masses") ||
         core_name.starts_with("profile"))) {
      name = "implement/" + core_name;
    }
    auto it = keys.find(name);
    // The core places the impact from the butt; the file may from the tip,
    // where a range the core gives from the butt is turned about the tip:
    // with the tip at L = x + t, [a, b] from the butt is [L - b, L - a].
    std::optional<FieldError> from_tip;
    if (it == keys.end() && name == "impact/from_butt_m") {
      it = keys.find("impact/from_tip_m");
      const std::string key =
          it == keys.end() ? "" : it->second.pointer.substr(it->second.pointer.rfind('/') + 1);
      const auto spelling = find_spelling("impact", key);
      if (typed && typed->range() && spelling && it->second.given.is_number()) {
        const FieldError::Range& r = *typed->range();
        const double t = spelling->scale.to_si(it->second.given.get<double>());
        const double L = r.value + t;
        from_tip.emplace(typed->field(), detail,
                         FieldError::Range{L - r.max, L - r.min, r.max_open, t, r.why, r.min_open});
      }
    }
    if (it != keys.end()) {
      // The core speaks SI; when the file used another unit or form, quote
      // the file's own value, which the core's SI value may not show (5e-324
      // cm is 0 m).
      const std::string si_key = it->first.substr(it->first.rfind('/') + 1);
      const std::string& pointer = it->second.pointer;
      const std::string user_key = pointer.substr(pointer.rfind('/') + 1);
      // The same quantity in another unit ("tension_lb" for "tension_N") is
      // converted; another quantity ("measured_ring_Hz", "balance_pts_hl") is
      // what the model derived this one from, which it names.
      const std::string stem = si_key.substr(0, si_key.rfind('_') + 1);
      if (!it->second.derived_by.empty())
        detail += " (the file's " + user_key + ": " + given_text(it->second) + ", " +
                  it->second.derived_by + ")";
      else if (si_key != user_key &&
               (user_key.starts_with(stem) || same_field(it->first, si_key, user_key))) {
        if (const auto restated = range_in_file_unit(from_tip ? *from_tip : error, it->second,
                                                     si_key, user_key, it->first))
          detail = *restated;
        else
          detail +=
              " (the file's " + user_key + ": " + given_text(it->second) + ", converted to SI)";
      } else if (si_key != user_key)
        detail += " (" + si_key + ", derived from the file's " + user_key + ": " +
                  given_text(it->second) + ")";
      throw InputError(source, pointer, detail);
    }
    if (name.starts_with("implement/sections") && name.ends_with("/EI_N_m2")) {
      // A section without its own stiffness takes the frame's.
      for (const char* frame_key : {"frame/EI_N_m2", "frame/fundamental_free_Hz"}) {
        const auto frame = keys.find(frame_key);
        if (frame != keys.end())
          throw InputError(source, frame->second.pointer, core_name + ": " + detail);
      }
    }
    if (name.starts_with("implement/")) {
      // Not a key of the file: sections the reader made (fitted to the specs,
      // or the racquet's two halves). The implement is what the file gave.
      throw InputError(source, "/implement", core_name + ": " + detail);
    }
    // A value the file left to its default is still named by its pointer.
    if (is_design_path(name)) throw InputError(source, "/" + name, detail);
    // A quantity the model derived from one part of the design ("hand.grip_start_m",
    // "frame.modes/0/phi", "impact_from_butt_m", "ball_stiffness_N_m"): the
    // part is the input named.
    const std::string part = core_name.substr(0, core_name.find_first_of("./_"));
    for (const char* top : {"implement", "frame", "strings", "hand", "forearm", "ball", "impact",
                            "swing", "support"}) {
      if (part == top) throw InputError(source, "/" + part, core_name + ": " + detail);
    }
  }
  throw InputError(source, fallback_pointer, message);
}

// The keys of `object` that spell one of `stems` (every unit), for the
// message of a key that belongs to another form of the object.
std::vector<std::string> keys_of(std::string_view object,
                                 std::initializer_list<std::string_view> stems) {
  std::vector<std::string> keys;
  for (const DesignField& field : design_fields()) {
    if (field.object != object || std::find(stems.begin(), stems.end(), field.stem) == stems.end())
      continue;
    for (std::string& key : spellings_of(field)) keys.push_back(std::move(key));
  }
  return keys;
}

const std::vector<std::string>& point_mass_keys() {
  return design_keys("implement/point_masses/N");
}

const std::vector<std::string>& impact_keys() { return design_keys("impact"); }

Section read_section(ObjectReader& r) {
  const std::vector<std::string>& kKeys = design_keys("implement/sections/N");
  r.check_known(kKeys);
  Section section;
  const auto length = r.quantity("length", Dimension::kLength);
  const auto mass = r.quantity("mass", Dimension::kMass);
  if (!length) r.fail("", "missing length_m (or length_cm, length_in)");
  if (!mass) r.fail("", "missing mass_kg (or mass_g)");
  section.length_m = *length;
  section.mass_kg = *mass;
  section.EI_N_m2 = r.quantity("EI", Dimension::kStiffness);
  r.finish(kKeys);
  return section;
}

// A round implement's profile: its stations (from the butt, diameter), the
// density and Young's modulus of its material.
RoundProfile read_profile(ObjectReader& r, const std::string& source, KeyMap* keys) {
  const Json* list = r.child("profile");
  if (!list->is_array() || list->size() < 2) {
    r.fail("profile", "expected an array of at least two stations (the butt and the tip), got " +
                          brief(*list));
  }
  r.record("profile", "profile");  // a complaint about the whole profile names it
  const std::vector<std::string>& kKeys = design_keys("implement/profile/N");
  RoundProfile profile;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string index = std::to_string(i);
    ObjectReader s((*list)[i], r.pointer_of("profile") + "/" + index, "implement/profile/" + index,
                   source, keys);
    s.check_known(kKeys);
    const auto from_butt = s.quantity("from_butt", Dimension::kLength);
    const auto diameter = s.quantity("diameter", Dimension::kLength);
    if (!from_butt) s.fail("", "missing from_butt_m (or from_butt_cm, from_butt_in)");
    if (!diameter) s.fail("", "missing diameter_m (or diameter_cm, diameter_in)");
    s.finish(kKeys);
    profile.stations.push_back(ProfileStation{*from_butt, *diameter});
  }
  const auto density = r.number("density_kg_m3");
  if (!density) r.fail("", "missing density_kg_m3 (the profile's material)");
  profile.density_kg_m3 = *density;
  static const std::vector<std::string> kYoungsModulusKeys =
      keys_of("implement", {"youngs_modulus"});
  const std::string modulus_key = r.one_of(kYoungsModulusKeys);
  if (modulus_key.empty()) {
    r.fail("",
           "missing youngs_modulus_Pa (or youngs_modulus_GPa), the profile's material "
           "along its length");
  }
  profile.youngs_modulus_Pa =
      find_spelling("implement", modulus_key)->scale.to_si(*r.number(modulus_key));
  r.record("youngs_modulus_Pa", modulus_key);
  profile.wall_m = r.quantity("wall", Dimension::kLength).value_or(0.0);
  return profile;
}

// A point mass as the file places it (the description), with the keys that
// name its parts in messages.
struct PointMassSpec {
  PointMassDescription described;
  std::string pointer;    // of this entry
  std::string where_key;  // the key that placed it
  std::string mass_key;   // the key that gave its mass
  std::string off_axis_key;
};

std::vector<PointMassSpec> read_point_masses(ObjectReader& implement, const std::string& source,
                                             KeyMap* keys) {
  std::vector<PointMassSpec> points;
  const Json* list = implement.child("point_masses");
  if (!list) return points;
  const std::string pointer = implement.pointer_of("point_masses");
  if (!list->is_array())
    throw InputError(source, pointer, "expected an array, got " + brief(*list));
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string index = std::to_string(i);
    ObjectReader r((*list)[i], pointer + "/" + index, "implement/point_masses/" + index, source,
                   keys);
    r.check_known(point_mass_keys());
    PointMassSpec spec;
    PointMassDescription& d = spec.described;
    spec.pointer = r.pointer();
    const auto mass = r.quantity("mass", Dimension::kMass);
    if (!mass) r.fail("", "missing mass_kg (or mass_g)");
    d.mass_kg = *mass;
    spec.mass_key = r.one_of(spellings("mass", Dimension::kMass));
    d.from_butt_m = r.quantity("from_butt", Dimension::kLength);
    d.from_tip_m = r.quantity("from_tip", Dimension::kLength);
    const auto off_axis = r.quantity("off_axis", Dimension::kLength);
    spec.off_axis_key = r.one_of(spellings("off_axis", Dimension::kLength));
    const bool clock = r.has("clock");
    const int placed = (d.from_butt_m ? 1 : 0) + (d.from_tip_m ? 1 : 0) + (clock ? 1 : 0);
    if (placed == 0) {
      r.fail("",
             "missing its place: from_butt_m or from_tip_m (or _cm, _mm, _in), or clock (12, "
             "[3, 9], \"throat\", \"handle\")");
    }
    if (placed > 1) {
      r.fail(clock ? "clock" : r.one_of(spellings("from_tip", Dimension::kLength)),
             "give the place once: from_butt_*, from_tip_* or clock");
    }
    if (clock && off_axis) {
      r.fail(spec.off_axis_key, "contradicts /clock, which places the mass on the hoop");
    }
    d.off_axis_m = off_axis.value_or(0.0);
    if (clock) {
      spec.where_key = "clock";
      const Json& value = *r.child("clock");
      const auto hours = [&](const Json& item) {
        if (item.is_number()) {
          const double h = item.get<double>();
          if (!(h >= 0.0 && h <= 12.0)) {
            r.fail("clock", "an hour must be in [0, 12] (12 the tip, 3 and 9 the sides), got " +
                                brief(item));
          }
          d.clock_hours.push_back(h);
          return;
        }
        if (item.is_string() && item.get<std::string>() == "throat") {
          d.clock_hours.push_back(6.0);
          return;
        }
        // Under the butt cap ("handle" or "butt") or under the grip ("grip"), as
        // `tune` names them.
        if (item.is_string() && value.is_string()) {
          const std::string word = item.get<std::string>();
          if (word == "handle" || word == "butt") d.handle_from_butt_m = kHandleWeightFromButt_m;
          if (word == "grip") d.handle_from_butt_m = kUnderGripFromButt_m;
          if (d.handle_from_butt_m) return;
          // Hours joined by '/' ("3/9"), as `tune --places` names a pair.
          std::vector<double> joined;
          for (std::size_t start = 0; start <= word.size();) {
            const std::size_t end = std::min(word.find('/', start), word.size());
            double h = 0.0;
            const char* first = word.data() + start;
            const char* last = word.data() + end;
            const auto [ptr, error] = std::from_chars(first, last, h);
            if (first == last || error != std::errc() || ptr != last) {
              joined.clear();
              break;
            }
            joined.push_back(h);
            start = end + 1;
          }
          if (joined.size() >= 2 && joined.size() <= 12) {
            for (const double h : joined) {
              if (!(h >= 0.0 && h <= 12.0)) {
                r.fail("clock", "an hour must be in [0, 12] (12 the tip, 3 and 9 the sides), got " +
                                    brief(value));
              }
            }
            d.clock_hours = joined;
            return;
          }
        }
        r.fail("clock",
               "expected an hour in [0, 12], a list of hours ([3, 9], or \"3/9\"), \"throat\", "
               "\"grip\" or \"handle\" (\"butt\"), got " +
                   brief(value));
      };
      if (value.is_array()) {
        if (value.empty() || value.size() > 12)
          r.fail("clock", "expected 1 to 12 hours, got " + brief(value));
        for (const Json& item : value) hours(item);
      } else {
        hours(value);
      }
    } else {
      std::vector<std::string> keys_given = spellings("from_butt", Dimension::kLength);
      for (const std::string& k : spellings("from_tip", Dimension::kLength))
        keys_given.push_back(k);
      spec.where_key = r.one_of(keys_given);
    }
    r.finish(point_mass_keys());
    points.push_back(std::move(spec));
  }
  return points;
}

std::vector<PointMassDescription> descriptions_of(const std::vector<PointMassSpec>& specs) {
  std::vector<PointMassDescription> out;
  for (const PointMassSpec& spec : specs) out.push_back(spec.described);
  return out;
}

// "must be in [0, 27] in (0 to 0.6858 m), got 28 in": a place along an
// implement of length L refused in the unit of the file's key, or "" when the
// key has no unit of its own (_m: the core's message stands).
std::string along_in_file_unit(std::string_view key, std::string_view base, double L,
                               double value_si, std::string_view why = {}) {
  const std::optional<double> per_unit = unit_factor(key, base, Dimension::kLength);
  const std::string_view unit = unit_of_key(key);
  if (!per_unit || *per_unit == 1.0 || unit.empty()) return {};
  return range_in_unit(0.0, L, false, *per_unit, unit, "m", why,
                       significant(value_si / *per_unit, 6));
}

// The point masses on an implement of length L with this head (a clock list
// becomes one point mass per hour); an entry the geometry cannot place is
// named at the file's entry (the core would name the expanded list's index).
std::vector<PointMass> place_point_masses(const std::vector<PointMassSpec>& specs, double L,
                                          const std::optional<HeadShape>& head,
                                          const std::string& source) {
  try {
    return place_point_masses(descriptions_of(specs), L, head);
  } catch (const PointMassError& error) {
    const PointMassSpec& spec = specs[error.entry];
    if (error.key == "implement") throw InputError(source, "/implement", error.what());
    const std::string key = error.key == "mass"       ? spec.mass_key
                            : error.key == "where"    ? spec.where_key
                            : error.key == "off_axis" ? spec.off_axis_key
                                                      : error.key;
    std::string detail = error.what();
    // A mass given in grams is refused in grams, the range in kg beside it.
    const auto spelling = find_spelling("implement/point_masses/N", spec.mass_key);
    if (error.key == "mass" && spelling && spec.mass_key != "mass_kg") {
      const double per_g = spelling->scale.to_si(1.0);
      detail = range_in_unit(0.0, kMaxMass_kg, false, per_g, unit_of_key(spec.mass_key), "kg", {},
                             significant(spec.described.mass_kg / per_g, 6));
    }
    // A place along the implement given in cm or in is refused in that unit.
    const std::optional<double> along =
        spec.described.from_tip_m ? spec.described.from_tip_m : spec.described.from_butt_m;
    if (error.key == "where" && along && !(*along >= 0.0 && *along <= L)) {
      const std::string restated = along_in_file_unit(
          spec.where_key, spec.described.from_tip_m ? "from_tip" : "from_butt", L, *along);
      if (!restated.empty()) detail = restated;
    }
    throw InputError(source, key.empty() ? spec.pointer : spec.pointer + "/" + key, detail);
  }
}

// The head (implement.headsize_sq_in or headsize_cm2, head_aspect_ratio,
// hoop_width_*) and the measured twistweight, when given.
struct HeadRead {
  std::optional<HeadShape> head;
  std::string key;  // headsize_sq_in or headsize_cm2, as given
  std::optional<double> twistweight_kg_m2;
};

HeadRead read_head(ObjectReader& r) {
  HeadRead out;
  static const std::vector<std::string> kHeadsizeKeys = keys_of("implement", {"headsize"});
  const std::string key = r.one_of(kHeadsizeKeys);
  if (!key.empty()) {
    const double given = *r.number(key);
    HeadShape head;
    head.area_m2 = find_spelling("implement", key)->scale.to_si(given);
    if (!(head.area_m2 > 0.0)) r.fail(key, "must be > 0, got " + brief(given));
    if (const auto aspect = r.number("head_aspect_ratio")) {
      if (!(*aspect >= 1.0 && *aspect <= 10.0)) {
        r.fail("head_aspect_ratio",
               "must be in [1, 10] (strung length over width), got " + brief(*aspect));
      }
      head.aspect_ratio = *aspect;
    }
    if (const auto hoop = r.quantity("hoop_width", Dimension::kLength)) {
      if (!(*hoop >= 0.0 && *hoop <= 1.0)) {
        const std::string hoop_key = r.one_of(spellings("hoop_width", Dimension::kLength));
        r.fail(
            hoop_key,
            range_in_unit(0.0, 1.0, false, find_spelling("implement", hoop_key)->scale.to_si(1.0),
                          unit_of_key(hoop_key), unit_of_key(hoop_key) == "m" ? "" : "m", "",
                          brief(*r.number(hoop_key))));
      }
      head.hoop_width_m = *hoop;
    }
    r.record("headsize", key);
    out.head = head;
    out.key = key;
  } else {
    for (const char* shape_key :
         {"head_aspect_ratio", "hoop_width_m", "hoop_width_cm", "hoop_width_mm", "hoop_width_in"}) {
      if (r.has(shape_key)) r.fail(shape_key, "describes the head: give headsize_sq_in with it");
    }
  }
  out.twistweight_kg_m2 = r.quantity("twistweight", Dimension::kInertia);
  if (out.twistweight_kg_m2 && !(*out.twistweight_kg_m2 > 0.0)) {
    r.fail(r.one_of(spellings("twistweight", Dimension::kInertia)),
           "must be > 0, got " + brief(*out.twistweight_kg_m2 * 1e4) + " kg cm^2");
  }
  return out;
}

std::vector<std::string> with_head_keys(std::initializer_list<std::string_view> stems) {
  std::vector<std::string> keys = keys_of("implement", stems);
  const std::vector<std::string> head =
      keys_of("implement", {"headsize", "head_aspect_ratio", "hoop_width", "twistweight"});
  keys.insert(keys.end(), head.begin(), head.end());
  return keys;
}

struct ImplementRead {
  Implement implement;
  std::string form;
  HeadRead head;
};

// One head, one size: the string bed's size given alone (strings.head_size_*)
// is the racquet's head, on which a lead's clock position is placed before the
// strings are read. A value that is no size is left to read_strings() to name.
std::optional<HeadShape> bed_head_given_alone(const Json& document) {
  const auto strings = document.find("strings");
  if (strings == document.end() || !strings->is_object()) return std::nullopt;
  for (const std::string& key : keys_of("strings", {"head_size"})) {
    const auto it = strings->find(key);
    if (it == strings->end()) continue;
    if (!it->is_number()) return std::nullopt;
    HeadShape head;  // the default aspect ratio and hoop width of head_geometry.hpp
    head.area_m2 = find_spelling("strings", key)->scale.to_si(it->get<double>());
    if (!(head.area_m2 > 0.0 && std::isfinite(head.area_m2))) return std::nullopt;
    return head;
  }
  return std::nullopt;
}

// `described`, when given, receives the implement's numbers before it is built.
ImplementRead read_implement(const Json& document, const std::string& source, KeyMap* keys,
                             ImplementDescription* described) {
  const auto it = document.find("implement");
  // A ball onto a rigid plate needs no implement: the Table I racquet stands
  // in for it, and no output of it is given (Evaluation::support).
  static const Json kStandIn = {
      {"length_m", 0.7}, {"mass_kg", 0.25}, {"head_to_handle_mass_ratio", 0.8}};
  const auto support = document.find("support");
  const bool plate = support != document.end() && support->is_string() &&
                     support->get<std::string>() == "rigid_surface";
  if (it == document.end() && !plate)
    throw InputError(source, "/implement",
                     "missing: every design needs an implement (but one on support "
                     "\"rigid_surface\")");
  const Json& given = it == document.end() ? kStandIn : *it;
  if (it == document.end()) keys = nullptr;  // not the file's: no key of it to name
  ObjectReader r(given, "/implement", "implement", source, keys);
  r.check_known(design_keys("implement"));
  // Every key left unread is the implement's (check_known), of another form
  // than the one read: a second implement, not a key nobody knows.
  const auto given_one_way = [](std::string_view form) {
    return std::string(kAnotherFormsKey) + " the implement than its " + std::string(form) +
           ": give it one way (its sections, its profile, length and mass with "
           "head_to_handle_mass_ratio, or a spec sheet's length, mass, balance and swingweight)";
  };
  const std::vector<PointMassSpec> point_specs = read_point_masses(r, source, keys);
  const HeadRead head = read_head(r);
  std::vector<PointMass> points;
  // The head is checked against the implement's length by validate(); here
  // it places the clock positions, and a head too long for the implement is
  // named at its key.
  const auto place = [&](double length_m) {
    // A length that is no length is the builder's to name, at its key: no
    // head or lead is placed on it (each builder refuses it before using them).
    if (!(length_m > 0.0 && std::isfinite(length_m))) return;
    if (head.head) {
      try {
        (void)string_bed(*head.head, length_m);
      } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        const auto* typed = dynamic_cast<const FieldError*>(&error);
        if (typed && typed->range()) {
          // The largest head that fits, in the file's unit of area.
          const FieldError::Range& range = *typed->range();
          r.fail(head.key, range_in_unit(range.min, range.max, range.min_open,
                                         find_spelling("implement", head.key)->scale.to_si(1.0),
                                         unit_of_key(head.key), "m²", range.why,
                                         brief(*r.number(head.key)), range.max_open));
        }
        r.fail(head.key, message.substr(message.find(": ") + 2));
      }
    }
    points = place_point_masses(point_specs, length_m,
                                head.head ? head.head : bed_head_given_alone(document), source);
  };
  try {
    if (r.has("profile")) {
      const RoundProfile profile = read_profile(r, source, keys);
      static const std::vector<std::string> kKeys =
          with_head_keys({"profile", "density_kg_m3", "youngs_modulus", "wall", "point_masses"});
      r.finish(kKeys, given_one_way("profile"));
      const double length_m = profile.stations.back().from_butt_m;
      if (std::isfinite(length_m) && length_m > 0.0) place(length_m);
      if (described) {
        described->form = ImplementDescription::Form::kProfile;
        described->profile = profile;
        described->point_masses = descriptions_of(point_specs);
        described->head = head.head;
      }
      return {Implement::from_profile(profile, std::move(points)), "profile", head};
    }
    if (r.has("sections")) {
      const Json* list = r.child("sections");
      if (!list->is_array() || list->empty()) {
        r.fail("sections", "expected a non-empty array of sections, got " + brief(*list));
      }
      std::vector<Section> sections;
      for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string index = std::to_string(i);
        ObjectReader s((*list)[i], r.pointer_of("sections") + "/" + index,
                       "implement/sections/" + index, source, keys);
        sections.push_back(read_section(s));
      }
      static const std::vector<std::string> kKeys = with_head_keys({"sections", "point_masses"});
      r.finish(kKeys, given_one_way("sections"));
      double total_length_m = 0.0;
      for (const Section& section : sections) total_length_m += section.length_m;
      if (std::isfinite(total_length_m) && total_length_m > 0.0) place(total_length_m);
      if (described) {
        described->form = ImplementDescription::Form::kSections;
        described->sections = sections;
        described->point_masses = descriptions_of(point_specs);
        described->head = head.head;
      }
      return {Implement::from_sections(std::move(sections), std::move(points)), "sections", head};
    }
    const auto length = r.quantity("length", Dimension::kLength);
    const auto mass = r.quantity("mass", Dimension::kMass);
    if (!length) r.fail("", "missing length_m (or length_in, length_cm), or give sections");
    if (!mass) r.fail("", "missing mass_kg (or mass_g), or give sections");
    if (r.has("head_to_handle_mass_ratio")) {
      const double ratio = *r.number("head_to_handle_mass_ratio");
      static const std::vector<std::string> kKeys =
          with_head_keys({"length", "mass", "head_to_handle_mass_ratio", "point_masses"});
      r.finish(kKeys, given_one_way("head_to_handle_mass_ratio"));
      place(*length);
      if (described) {
        *described = ImplementDescription{.form = ImplementDescription::Form::kHeadToHandleRatio,
                                          .length_m = *length,
                                          .mass_kg = *mass,
                                          .head_to_handle_mass_ratio = ratio,
                                          .sections = {},
                                          .profile = {},
                                          .point_masses = descriptions_of(point_specs),
                                          .head = head.head};
      }
      return {Implement::paper_racquet(*length, *mass, ratio, std::move(points)),
              "head_to_handle_mass_ratio", head};
    }
    static const std::vector<std::string> kBalanceKeys = keys_of("implement", {"balance"});
    const std::string balance_key = r.one_of(kBalanceKeys);
    if (balance_key.empty()) {
      r.fail("",
             "missing the mass distribution: give head_to_handle_mass_ratio, sections, or "
             "balance_from_butt_m (or balance_cm, balance_pts_hl) with swingweight_kg_cm2");
    }
    double balance = *r.number(balance_key);
    balance = find_spelling("implement", balance_key)->scale.to_si(balance);
    const double balance_as_given = balance;
    if (balance_key == "balance_pts_hl") {
      const double limit = points_head_light_limit(*length);
      if (!(balance > -limit && balance < limit)) {
        r.fail(balance_key, "must put the balance inside the length, |points| < " +
                                significant(limit, 6) + ", got " + significant(balance, 6));
      }
      balance = balance_from_points_head_light(*length, balance);
    }
    r.record("balance_from_butt_m", balance_key);
    const auto swingweight = r.quantity("swingweight", Dimension::kInertia);
    if (!swingweight)
      r.fail("", "missing swingweight_kg_cm2 (with the balance it fixes the inertia)");
    static const std::vector<std::string> kKeys =
        with_head_keys({"length", "mass", "balance", "swingweight", "point_masses"});
    r.finish(kKeys, given_one_way("balance and swingweight"));
    place(*length);
    if (described) {
      *described = ImplementDescription{.form = ImplementDescription::Form::kSpecs,
                                        .length_m = *length,
                                        .mass_kg = *mass,
                                        .balance_in_points = balance_key == "balance_pts_hl",
                                        .balance = balance_as_given,
                                        .swingweight_kg_m2 = *swingweight,
                                        .sections = {},
                                        .profile = {},
                                        .point_masses = descriptions_of(point_specs),
                                        .head = head.head};
    }
    return {Implement::from_specs(IndustrySpecs{*length, *mass, balance, *swingweight},
                                  std::move(points)),
            "specs", head};
  } catch (const std::invalid_argument& error) {
    if (!keys) throw;  // a lean read: the caller reads again with the key map
    rethrow_at(error, "implement/", *keys, source, "/implement");
  }
}

ImplementDescription::Form implement_form_of(const std::string& form) {
  if (form == "sections") return ImplementDescription::Form::kSections;
  if (form == "profile") return ImplementDescription::Form::kProfile;
  if (form == "specs") return ImplementDescription::Form::kSpecs;
  return ImplementDescription::Form::kHeadToHandleRatio;
}

// A length in cm to the nearest 0.5 cm, as the reports write positions ("18 cm", "18.5 cm").
std::string half_cm_text(double metres) {
  const double half_cm = std::round(metres * 200.0) / 2.0;
  if (half_cm == std::floor(half_cm)) return fmt::format("{:.0f} cm", half_cm == 0 ? 0.0 : half_cm);
  return fmt::format("{:.1f} cm", half_cm);
}

// Reads one optional section of the design ("hand": {...}) with defaults.
class Part {
 public:
  Part(ObjectReader& document, const char* name, KeyMap* keys,
       std::map<std::string, std::string>* provenance)
      : name_(name), provenance_(provenance) {
    static const Json kEmpty = Json::object();
    const Json* part = document.child(name);
    reader_.emplace(part ? *part : kEmpty, std::string("/") + name, name, document.source(), keys);
    reader_->check_known(design_keys(name));
  }
  ObjectReader& reader() { return *reader_; }

  // The quantity, or `fallback` when absent; records where it came from.
  double get(std::string_view base, Dimension dimension, std::string_view si_key, double fallback) {
    const auto value = reader_->quantity(base, dimension);
    if (provenance_)
      (*provenance_)[name_ + "/" + std::string(si_key)] = value ? "given" : "default";
    return value.value_or(fallback);
  }
  double get_number(std::string_view key, double fallback) {
    const auto value = reader_->number(key);
    if (provenance_) (*provenance_)[name_ + "/" + std::string(key)] = value ? "given" : "default";
    return value.value_or(fallback);
  }

 private:
  std::string name_;
  std::map<std::string, std::string>* provenance_;
  std::optional<ObjectReader> reader_;
};

// What the steps of reading a design share: where the file came from, the
// key map and provenance kept with `bookkeeping` (null without), the design
// being read and the defaults it starts from.
struct Reading {
  const std::string& source;
  KeyMap* keys;
  std::map<std::string, std::string>* provenance;
  const Design& defaults;
  Design& design;
  // The string bed came from a stringer's ticket (a pattern, families, a loss,
  // a measurement), which the bindings of catalogues and studies leave to this reader.
  bool string_ticket = false;
  void note(const std::string& input, const std::string& how) const {
    if (provenance) (*provenance)[input] = how;
  }
};

// /frame/cross_section: the shape and its sizes (Cowper's shear coefficient
// for the shape, beam_modes.hpp), each size the shape's own.
CrossSection read_cross_section(ObjectReader& c) {
  CrossSection section;
  if (const auto name = c.string("shape")) {
    const auto* found = std::find_if(std::begin(kSectionShapes), std::end(kSectionShapes),
                                     [&](const auto& k) { return k.first == *name; });
    if (found == std::end(kSectionShapes)) {
      c.fail("shape", "expected rectangle, circle, hollow_circle, ellipse, box or profile, got " +
                          brief(*name));
    }
    section.shape = found->second;
  }
  const auto width = c.quantity("width", Dimension::kLength);
  const auto thickness = c.quantity("thickness", Dimension::kLength);
  const auto diameter = c.quantity("diameter", Dimension::kLength);
  const auto wall = c.quantity("wall", Dimension::kLength);
  const auto refuse = [&](std::string_view stem, Dimension dimension, const std::string& why) {
    c.fail(c.one_of(spellings(stem, dimension)), why);
  };
  static constexpr std::string_view kWords[] = {"a rectangle", "a circle", "a tube",
                                                "an ellipse",  "a box",    "a profile"};
  const std::string shape(kWords[static_cast<int>(section.shape)]);
  if (section.shape == CrossSection::Shape::kProfile) {
    const std::string own =
        "is one section's size: a profile's sections take theirs from "
        "implement.profile";
    if (width) refuse("width", Dimension::kLength, own);
    if (thickness) refuse("thickness", Dimension::kLength, own);
    if (diameter) refuse("diameter", Dimension::kLength, own);
    if (wall) refuse("wall", Dimension::kLength, own + " (its wall, implement.wall)");
  } else if (sized_by_width(section.shape)) {
    if (diameter) {
      refuse("diameter", Dimension::kLength,
             "is a circle's: " + shape + " has a width and a thickness");
    }
    if (!width || !thickness) {
      c.fail("", shape + " needs width_m and thickness_m (for Timoshenko theory)");
    }
    section.width_m = *width;
    section.thickness_m = *thickness;
  } else {
    const std::string sized = "is a rectangle's: " + shape + " has a diameter";
    if (width) refuse("width", Dimension::kLength, sized);
    if (thickness) refuse("thickness", Dimension::kLength, sized);
    if (!diameter) c.fail("", shape + " needs diameter_m (its outer diameter)");
    section.diameter_m = *diameter;
  }
  if (has_wall(section.shape)) {
    if (!wall) c.fail("", shape + " needs wall_m (its wall's thickness)");
    section.wall_m = *wall;
  } else if (wall && section.shape != CrossSection::Shape::kProfile) {
    refuse("wall", Dimension::kLength, "is a hollow section's: give shape hollow_circle or box");
  }
  section.poisson_ratio = c.number("poisson_ratio").value_or(0.0);
  return section;
}

// /frame: the COR (given or derived) and the stiffness in one of its forms.
void read_frame(ObjectReader& top, Reading& in) {
  Part frame(top, "frame", in.keys, in.provenance);
  in.design.cor = frame.get_number("cor", in.defaults.cor);
  {
    ObjectReader& r = frame.reader();
    in.design.cor_given = r.has("cor");
    in.design.cor_rigid = r.number("cor_rigid");
    if (in.design.cor_rigid && r.has("cor")) {
      r.fail("cor_rigid",
             "contradicts /frame/cor: give the COR, or cor_rigid to derive it from the frame's "
             "vibration");
    }
    if (in.design.cor_rigid)
      in.note("frame/cor", "derived from cor_rigid and the frame's vibration");
    in.design.stiffness.EI_N_m2 = r.quantity("EI", Dimension::kStiffness);
    in.design.stiffness.fundamental_free_Hz = r.quantity("fundamental_free", Dimension::kFrequency);
    if (in.design.stiffness.EI_N_m2 && in.design.stiffness.fundamental_free_Hz) {
      r.fail("fundamental_free_Hz", "contradicts /frame/EI_N_m2: give the stiffness once");
    }
    in.design.stiffness.RA = r.number("RA");
    if (in.design.stiffness.RA &&
        (in.design.stiffness.EI_N_m2 || in.design.stiffness.fundamental_free_Hz)) {
      r.fail("RA", std::string("contradicts /frame/") +
                       (in.design.stiffness.EI_N_m2 ? "EI_N_m2" : "fundamental_free_Hz") +
                       ": give the stiffness once (RA derives the free fundamental)");
    }
    if (const Json* section = r.child("cross_section")) {
      ObjectReader c(*section, "/frame/cross_section", "frame/cross_section", in.source, in.keys);
      c.check_known(design_keys("frame/cross_section"));
      in.design.stiffness.shear_modulus_Pa = c.number("shear_modulus_Pa");
      if (!in.design.stiffness.shear_modulus_Pa)
        c.fail("", "give shear_modulus_Pa and the section's size (for Timoshenko theory)");
      in.design.stiffness.cross_section = read_cross_section(c);
      c.finish(design_keys("frame/cross_section"));
    }
    r.finish(design_keys("frame"));
  }
}

// A string of the ticket (docs/design-files.md, "A stringer's ticket"): its
// material by name, its gauge in mm or the trade's number.
StringMaterial read_material(ObjectReader& r, StringMaterial fallback) {
  const auto name = r.string("material");
  if (!name) return fallback;
  static constexpr std::pair<std::string_view, StringMaterial> kNames[] = {
      {"natural_gut", StringMaterial::kNaturalGut},
      {"nylon", StringMaterial::kNylon},
      {"multifilament", StringMaterial::kMultifilament},
      {"polyester", StringMaterial::kPolyester},
      {"kevlar", StringMaterial::kKevlar}};
  for (const auto& [known, material] : kNames)
    if (*name == known) return material;
  r.fail("material", "expected one of natural_gut, nylon, multifilament, polyester, kevlar, got " +
                         brief(*name));
}

// The trade's gauges and the middle of each one's diameter range [m] (the
// USRSA's gauge chart: 15 is 1.41-1.49 mm, 15L 1.34-1.40, 16 1.26-1.33, 16L
// 1.22-1.28, 17 1.16-1.24, 18 1.06-1.16, 19 1.00-1.06).
std::optional<double> read_gauge(ObjectReader& r, std::optional<double> fallback) {
  static constexpr std::pair<std::string_view, double> kGauges[] = {
      {"15", 1.45e-3}, {"15L", 1.37e-3}, {"16", 1.295e-3}, {"16L", 1.25e-3},
      {"17", 1.20e-3}, {"18", 1.11e-3},  {"19", 1.03e-3}};
  const std::string key = r.one_of({"gauge_m", "gauge_mm", "gauge"});
  if (key.empty()) return fallback;
  double gauge_m = 0.0;
  if (key == "gauge_m") {
    gauge_m = *r.number("gauge_m");
  } else if (key == "gauge_mm") {
    gauge_m = *r.number("gauge_mm") * 1e-3;
  } else {
    const Json* given = r.child("gauge");
    std::string trade = given->is_number_integer() ? std::to_string(given->get<long long>())
                        : given->is_string()       ? given->get<std::string>()
                                                   : std::string();
    bool found = false;
    for (const auto& [name, diameter] : kGauges) {
      if (trade == name) {
        gauge_m = diameter;
        found = true;
      }
    }
    if (!found) {
      r.fail("gauge", "expected a trade gauge (15, 15L, 16, 16L, 17, 18, 19) or gauge_mm, got " +
                          brief(*given));
    }
  }
  if (!(gauge_m >= kMinGauge_m && gauge_m <= kMaxGauge_m)) {
    r.fail(key, "must be in [" + brief(kMinGauge_m * 1e3) + ", " + brief(kMaxGauge_m * 1e3) +
                    "] mm, got " + brief(gauge_m * 1e3) + " mm");
  }
  r.record("gauge_m", key);
  return gauge_m;
}

// What a family of strings (mains or crosses, or both at /strings) says.
struct StringFamilyRead {
  std::optional<double> pull_tension_N;
  std::optional<double> spacing_m;
  StringMaterial material = StringMaterial::kNylon;
  std::optional<double> gauge_m;
  std::optional<double> linear_density_kg_m;
  bool described = false;  // a material, gauge or linear density given here or above
  std::string pointer;     // of the object that gave it
};

StringFamilyRead read_family(ObjectReader& r, const StringFamilyRead& inherited, bool is_family) {
  StringFamilyRead f = inherited;
  f.pointer = r.pointer();
  if (is_family) {
    f.pull_tension_N = r.quantity("tension", Dimension::kForce);
    f.spacing_m = r.quantity("spacing", Dimension::kLength);
    if (f.pull_tension_N && inherited.pull_tension_N) {
      r.fail(r.one_of(spellings("tension", Dimension::kForce)),
             "contradicts " + inherited.pointer +
                 "/tension: give one tension for both families there, or one in each of mains "
                 "and crosses");
    }
    if (f.pull_tension_N && !(*f.pull_tension_N > 0.0)) {
      const std::string key = r.one_of(spellings("tension", Dimension::kForce));
      r.fail(key, "must be > 0, got " + brief(*r.number(key)));
    }
    if (f.spacing_m && !(*f.spacing_m > 0.0)) {
      const std::string key = r.one_of(spellings("spacing", Dimension::kLength));
      r.fail(key, "must be > 0, got " + brief(*r.number(key)));
    }
    if (!f.pull_tension_N) f.pull_tension_N = inherited.pull_tension_N;
  }
  // A string's description is given once: for both families at /strings, or in each.
  const std::pair<const char*, bool> kStems[] = {
      {"material", r.has("material")},
      {"gauge", !r.one_of({"gauge_mm", "gauge"}).empty()},
      {"linear_density",
       !r.one_of(spellings("linear_density", Dimension::kLinearDensity)).empty()}};
  for (const auto& [stem, here] : kStems) {
    if (is_family && here && inherited.described) {
      r.fail(stem == std::string_view("material") ? std::string(stem)
             : stem == std::string_view("gauge")
                 ? r.one_of({"gauge_mm", "gauge"})
                 : r.one_of(spellings(stem, Dimension::kLinearDensity)),
             "contradicts " + inherited.pointer +
                 ": describe the string once, for both families there or in each of mains and "
                 "crosses");
    }
    if (here) f.described = true;
  }
  f.material = read_material(r, inherited.material);
  f.gauge_m = read_gauge(r, inherited.gauge_m);
  if (const auto mu = r.quantity("linear_density", Dimension::kLinearDensity)) {
    if (!(*mu >= kMinStringLinearDensity_kg_m && *mu <= kMaxStringLinearDensity_kg_m)) {
      r.fail(r.one_of(spellings("linear_density", Dimension::kLinearDensity)),
             "must be in [" + brief(kMinStringLinearDensity_kg_m * 1e3) + ", " +
                 brief(kMaxStringLinearDensity_kg_m * 1e3) + "] g/m, got " + brief(*mu * 1e3) +
                 " g/m");
    }
    f.linear_density_kg_m = mu;
  }
  return f;
}

double linear_density_of(const StringFamilyRead& f) {
  if (f.linear_density_kg_m) return *f.linear_density_kg_m;
  return string_linear_density(f.material, f.gauge_m.value_or(1.30e-3));
}

// "16x19" (or "16X19", "16×19", "16 x 19"): the mains and the crosses.
std::pair<int, int> read_pattern(ObjectReader& r) {
  const std::string text = *r.string("pattern");
  std::string normal;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "\u00d7") == 0) {
      normal += 'x';
      ++i;
    } else if (text[i] != ' ') {
      normal += text[i] == 'X' ? 'x' : text[i];
    }
  }
  // Digits only (no sign, no overflow): std::from_chars, then 'x', then the end.
  int mains = 0, crosses = 0;
  const char* const end = normal.data() + normal.size();
  const auto [after_mains, mains_error] = std::from_chars(normal.data(), end, mains);
  bool read = mains_error == std::errc() && after_mains != end && *after_mains == 'x';
  if (read) {
    const auto [after_crosses, crosses_error] = std::from_chars(after_mains + 1, end, crosses);
    read = crosses_error == std::errc() && after_crosses == end;
  }
  if (!read || mains < 4 || mains > 40 || crosses < 4 || crosses > 40) {
    r.fail("pattern", "expected mains x crosses, each 4-40, such as \"16x19\", got " + brief(text));
  }
  return {mains, crosses};
}

// /strings: the impact duration, or the string bed that derives it (a plain
// tension, or a stringer's ticket); the string bed's size when given (its
// area in SI, returned).
std::optional<double> read_strings(ObjectReader& top, Reading& in, const ImplementRead& implement) {
  std::optional<double> head_area_m2;
  Part strings(top, "strings", in.keys, in.provenance);
  in.design.impact_duration_s = strings.get("impact_duration", Dimension::kTime,
                                            "impact_duration_s", in.defaults.impact_duration_s);
  {
    ObjectReader& r = strings.reader();
    StringFamilyRead both = read_family(r, StringFamilyRead{}, false);
    both.pull_tension_N = r.quantity("tension", Dimension::kForce);
    if (both.pull_tension_N && !(*both.pull_tension_N > 0.0)) {
      // The range the bed's tension takes (design.hpp), in the file's unit.
      const std::string key = r.one_of(spellings("tension", Dimension::kForce));
      const double per_unit = unit_factor(key, "tension", Dimension::kForce).value_or(1.0);
      const std::string unit(unit_of_key(key));
      const std::string given = brief(*r.number(key));
      r.fail(key, per_unit == 1.0 ? "must be in [" + significant(kMinTension_N, 4) + ", " +
                                        significant(kMaxTension_N, 4) + "] N, got " + given + " N"
                                  : range_in_unit(kMinTension_N, kMaxTension_N, false, per_unit,
                                                  unit, "N", "", given));
    }
    const Json* mains_json = r.child("mains");
    const Json* crosses_json = r.child("crosses");
    if (static_cast<bool>(mains_json) != static_cast<bool>(crosses_json)) {
      r.fail(mains_json ? "mains" : "crosses",
             "needs its partner: give both mains and crosses (or neither, for one string)");
    }
    StringFamilyRead mains = both, crosses = both;
    if (mains_json) {
      ObjectReader m(*mains_json, r.pointer_of("mains"), "strings/mains", in.source, in.keys);
      m.check_known(design_keys("strings/mains"));
      mains = read_family(m, both, true);
      m.finish(design_keys("strings/mains"));
      ObjectReader c(*crosses_json, r.pointer_of("crosses"), "strings/crosses", in.source, in.keys);
      c.check_known(design_keys("strings/crosses"));
      crosses = read_family(c, both, true);
      c.finish(design_keys("strings/crosses"));
      if (static_cast<bool>(mains.pull_tension_N) != static_cast<bool>(crosses.pull_tension_N)) {
        (mains.pull_tension_N ? c : m)
            .fail("", "missing tension_lb (or tension_kg, tension_N): the other family has one");
      }
      if (static_cast<bool>(mains.spacing_m) != static_cast<bool>(crosses.spacing_m)) {
        (mains.spacing_m ? c : m)
            .fail("", "missing spacing_mm (or spacing_m): the other family has one");
      }
    }
    const auto measured_ring = r.quantity("measured_ring", Dimension::kFrequency);
    const auto measured_stiffness = r.quantity("measured_stiffness", Dimension::kSpringRate);
    if (measured_ring && measured_stiffness) {
      r.fail(r.one_of(spellings("measured_stiffness", Dimension::kSpringRate)),
             "contradicts /strings/measured_ring_Hz: calibrate to one measurement");
    }
    for (const auto& [value, stem, dimension] :
         {std::tuple{measured_ring, "measured_ring", Dimension::kFrequency},
          std::tuple{measured_stiffness, "measured_stiffness", Dimension::kSpringRate}}) {
      if (value && !(*value > 0.0))
        r.fail(r.one_of(spellings(stem, dimension)), "must be > 0, got " + brief(*value));
    }
    const double loss = r.number("tension_loss").value_or(0.0);
    if (!(loss >= 0.0 && loss <= kMaxTensionLoss)) {
      r.fail("tension_loss", "must be in [0, " + brief(kMaxTensionLoss) +
                                 "] (the share of the pull the bed loses), got " + brief(loss));
    }
    const bool has_bed = mains.pull_tension_N || measured_ring || measured_stiffness;
    in.string_ticket = mains_json || measured_ring || measured_stiffness || r.has("pattern") ||
                       loss != 0.0 || both.described;
    if (has_bed) {
      if (r.has("impact_duration_s") || r.has("impact_duration_ms")) {
        const std::string tension_key = r.one_of(spellings("tension", Dimension::kForce));
        const std::string measured_key =
            r.one_of(measured_ring ? spellings("measured_ring", Dimension::kFrequency)
                                   : spellings("measured_stiffness", Dimension::kSpringRate));
        r.fail(!tension_key.empty() ? tension_key
               : mains_json         ? "mains"
                                    : measured_key,
               "contradicts the impact duration: give the duration, or the tension to derive it");
      }
      StringBed bed;
      static const std::vector<std::string> kHeadSizeKeys = keys_of("strings", {"head_size"});
      const std::string head = r.one_of(kHeadSizeKeys);
      // The head: the implement's, strings.head_size, else the default bed's.
      double area_m2 = in.design.head ? in.design.head->area_m2
                                      : 3.141592653589793 * bed.head_radius_m * bed.head_radius_m;
      double aspect = in.design.head ? in.design.head->aspect_ratio : kDefaultHeadAspectRatio;
      if (!head.empty()) {
        const double given = *r.number(head);
        area_m2 = find_spelling("strings", head)->scale.to_si(given);
        if (!(area_m2 > 0)) r.fail(head, "must be > 0, got " + brief(*r.number(head)));
        if (in.design.head && !same_head_area(area_m2, in.design.head->area_m2)) {
          r.fail(head, "contradicts /implement/" + implement.head.key +
                           ": one head, one size: give it once, as implement." +
                           implement.head.key + " (the string bed's size is the head's)");
        }
        head_area_m2 = area_m2;
        r.record("head_radius_m", head);
      }
      if (in.design.head || !head.empty()) bed.head_radius_m = head_radius_from_area(area_m2);
      // One head, one size: the bed's size given alone is the head's (as
      // build_design() takes it), so the twist, the map and the page know it.
      if (!in.design.head && !head.empty()) {
        HeadShape given_head;  // the default aspect ratio and hoop width of head_geometry.hpp
        given_head.area_m2 = area_m2;
        in.design.head = given_head;
        if (in.keys) {  // a complaint about the head names the size the file gave
          const auto it = in.keys->find("strings/head_radius_m");
          if (it != in.keys->end()) (*in.keys)["implement/headsize"] = it->second;
        }
      }
      // The bed's radius from the implement's head: a complaint about it names
      // the head's size as the file gave it.
      if (in.keys && in.design.head && head.empty()) {
        for (const std::string& key : keys_of("implement", {"headsize"})) {
          const auto it = in.keys->find("implement/" + key);
          if (it == in.keys->end()) continue;
          KeyOrigin origin = it->second;
          origin.derived_by = "as the radius in m of a circle of that area";
          (*in.keys)["strings/head_radius_m"] = origin;
        }
      }
      // The spacing: the pattern over the head, each family's, or one for both.
      const auto spacing = r.quantity("string_spacing", Dimension::kLength);
      const bool pattern = r.has("pattern");
      if (pattern + static_cast<bool>(spacing) + static_cast<bool>(mains.spacing_m) > 1) {
        r.fail(pattern ? "pattern" : r.one_of(spellings("string_spacing", Dimension::kLength)),
               "gives the spacing twice: give the pattern, string_spacing, or each family's "
               "spacing");
      }
      if (spacing && !(*spacing > 0.0)) {
        const std::string key = r.one_of(spellings("string_spacing", Dimension::kLength));
        r.fail(key, "must be > 0, got " + brief(*r.number(key)));
      }
      double main_spacing = spacing.value_or(bed.string_spacing_m);
      double cross_spacing = main_spacing;
      if (pattern) {
        // Mains run along the head, spaced across its width; crosses across it.
        const auto [n_mains, n_crosses] = read_pattern(r);
        const double width = 2.0 * std::sqrt(area_m2 / (3.141592653589793 * aspect));
        main_spacing = width / n_mains;
        cross_spacing = width * aspect / n_crosses;
        r.record("string_spacing_m", "pattern");
      } else if (mains.spacing_m) {
        main_spacing = *mains.spacing_m;
        cross_spacing = *crosses.spacing_m;
        if (!(main_spacing > 0.0 && cross_spacing > 0.0)) {
          r.fail("mains", "spacing must be > 0, got " + brief(main_spacing) + " and " +
                              brief(cross_spacing) + " m");
        }
      }
      bed.string_spacing_m = std::sqrt(main_spacing * cross_spacing);
      bed.cross_spacing_ratio = cross_spacing / main_spacing;
      bed.main_linear_density_kg_m = linear_density_of(mains);
      bed.cross_linear_density_kg_m = linear_density_of(crosses);
      bed.contact_radius_m =
          r.quantity("contact_radius", Dimension::kLength).value_or(bed.contact_radius_m);
      // The tension in the bed: the pull less its loss, or solved from a measurement.
      bed.tension_N = mains.pull_tension_N.value_or(StringBed{}.tension_N) * (1.0 - loss);
      if (mains.pull_tension_N)
        bed.cross_tension_ratio = *crosses.pull_tension_N / *mains.pull_tension_N;
      if (!(bed.tension_N > 0.0 && std::isfinite(bed.cross_tension_ratio) &&
            bed.cross_tension_ratio > 0.0)) {
        r.fail(mains_json ? "mains" : r.one_of(spellings("tension", Dimension::kForce)),
               "the tension must be > 0, got " + brief(bed.tension_N) + " N");
      }
      // The mains' tension is the bed's: a complaint about it names the mains' key.
      if (in.keys && mains_json && in.keys->count("strings/mains/tension_N"))
        (*in.keys)["strings/tension_N"] = in.keys->at("strings/mains/tension_N");
      // ... and says that the bed keeps the pull less its loss.
      if (in.keys && loss > 0.0 && in.keys->count("strings/tension_N"))
        (*in.keys)["strings/tension_N"].derived_by =
            "less its tension_loss of " + significant(loss * 100.0, 4) + " %";
      std::string how =
          loss > 0.0 ? "the pull less its tension_loss of " + significant(loss * 100.0, 4) + " %"
                     : "the whole pull, tension_loss 0";
      if (measured_ring || measured_stiffness) {
        const bool ring = measured_ring.has_value();
        const double measured = ring ? *measured_ring : *measured_stiffness;
        const std::string key =
            r.one_of(ring ? spellings("measured_ring", Dimension::kFrequency)
                          : spellings("measured_stiffness", Dimension::kSpringRate));
        std::string predicted;
        if (mains.pull_tension_N) {
          const double model = ring ? string_bed_ring_frequency(bed) : string_bed_stiffness(bed);
          const double off = (model / measured - 1.0) * 100.0;
          predicted = "; the ticket (" + how + ") predicted " + significant(model, 4) +
                      (ring ? " Hz" : " N/m") + ", " + significant(std::fabs(off), 3) + " % " +
                      (off >= 0.0 ? "above" : "below") + " it";
        }
        try {
          bed.tension_N =
              ring ? tension_for_ring(bed, measured) : tension_for_stiffness(bed, measured);
        } catch (const std::invalid_argument& e) {
          r.fail(key, e.what());
        }
        r.record("tension_N", key);  // a tension out of range is the measurement's
        how = "solved from the measured " + std::string(ring ? "ring " : "stiffness ") +
              significant(measured, 4) + (ring ? " Hz" : " N/m") + predicted;
      }
      bed.tension_loss = loss;
      in.design.strings = bed;
      in.note("strings/impact_duration_s", "derived from the string tension");
      in.note("strings/tension_N", how);
    } else {
      for (const char* key : {"pattern", "tension_loss", "material", "gauge", "gauge_mm"}) {
        if (r.has(key))
          r.fail(key, "describes a string bed: give its tension (strings.tension_lb)");
      }
      for (const char* stem : {"string_spacing", "contact_radius"}) {
        const std::string key = r.one_of(spellings(stem, Dimension::kLength));
        if (!key.empty())
          r.fail(key, "describes a string bed: give its tension (strings.tension_lb)");
      }
      if (const std::string key = r.one_of(keys_of("strings", {"head_size"})); !key.empty()) {
        r.fail(key,
               "is the string bed's size: give its tension (strings.tension_lb), or the head's "
               "size as implement.headsize_sq_in");
      }
      if (!both.linear_density_kg_m) {
        // nothing: no bed
      } else {
        r.fail(r.one_of(spellings("linear_density", Dimension::kLinearDensity)),
               "describes a string bed: give its tension (strings.tension_lb)");
      }
    }
    // The solved collision's string bed: its moving mass and loss.
    in.design.string_bed_mass_kg =
        r.quantity("bed_mass", Dimension::kMass).value_or(in.defaults.string_bed_mass_kg);
    in.design.string_bed_damping_ratio =
        r.number("bed_damping_ratio").value_or(in.defaults.string_bed_damping_ratio);
    r.finish(design_keys("strings"));
  }
  return head_area_m2;
}

// A grip's tightness by its name in a design file.
constexpr std::string_view kGripExpected = "expected \"paper\", \"light\", \"medium\" or \"tight\"";
std::optional<GripTightness> grip_tightness(std::string_view name) {
  if (name == "paper") return GripTightness::kPaper;
  if (name == "light") return GripTightness::kLight;
  if (name == "medium") return GripTightness::kMedium;
  if (name == "tight") return GripTightness::kTight;
  return std::nullopt;
}

// /hand: the paper's hand and its grip.
void read_hand(ObjectReader& top, Reading& in) {
  Part hand(top, "hand", in.keys, in.provenance);
  in.design.hand.mass_kg = hand.get("mass", Dimension::kMass, "mass_kg", in.defaults.hand.mass_kg);
  in.design.hand.center_from_butt_m =
      hand.get("center_from_butt", Dimension::kLength, "center_from_butt_m",
               in.defaults.hand.center_from_butt_m);
  in.design.hand.grip_length_m =
      hand.get("grip_length", Dimension::kLength, "grip_length_m", in.defaults.hand.grip_length_m);
  // The grip by its tightness (beam_modes.hpp: the paper's hand, or Savage's
  // light, medium and tight grips): its stiffness and damping, either of which
  // given beside it replaces the grip's own (a sweep of one over a named grip).
  ObjectReader& r = hand.reader();
  GripCoefficients fallback{in.defaults.hand.grip_stiffness_N_m2,
                            in.defaults.hand.grip_damping_N_s_m2};
  if (const std::optional<std::string> grip = r.string("grip")) {
    const auto tightness = grip_tightness(*grip);
    if (!tightness) r.fail("grip", std::string(kGripExpected) + ", got " + brief(*grip));
    r.record("grip", "grip");  // listed with the inputs as given
    fallback = grip_coefficients(*tightness);
  }
  in.design.hand.grip_stiffness_N_m2 = hand.get("grip_stiffness", Dimension::kStiffness,
                                                "grip_stiffness_N_m2", fallback.stiffness_N_m2);
  in.design.hand.grip_damping_N_s_m2 =
      hand.get("grip_damping", Dimension::kDamping, "grip_damping_N_s_m2", fallback.damping_N_s_m2);
  r.finish(design_keys("hand"));
}

// /forearm: its equivalent mass, or its mass (Eq. 7; returned when given).
std::optional<double> read_forearm(ObjectReader& top, Reading& in) {
  Part forearm(top, "forearm", in.keys, in.provenance);
  std::optional<double> forearm_mass_kg;
  {
    ObjectReader& r = forearm.reader();
    const std::string key =
        r.one_of({"equivalent_mass_kg", "equivalent_mass_g", "mass_kg", "mass_g"});
    if (key.starts_with("mass")) {
      const double forearm_mass = *r.quantity("mass", Dimension::kMass);
      forearm_mass_kg = forearm_mass;
      try {
        in.design.forearm_equivalent_mass_kg = forearm_equivalent_mass(forearm_mass);  // Eq. (7)
      } catch (const std::invalid_argument&) {
        r.fail(key, "must be >= 0 kg, got " + brief(forearm_mass) + " kg");
      }
      r.record("equivalent_mass_kg", key);
      in.note("forearm/equivalent_mass_kg", "derived from forearm/mass_kg (Eq. 7)");
    } else {
      in.design.forearm_equivalent_mass_kg =
          forearm.get("equivalent_mass", Dimension::kMass, "equivalent_mass_kg",
                      in.defaults.forearm_equivalent_mass_kg);
    }
    r.finish(design_keys("forearm"));
  }
  return forearm_mass_kg;
}

// /ball: its mass, speed and contact law.
void read_ball(ObjectReader& top, Reading& in) {
  Part ball(top, "ball", in.keys, in.provenance);
  in.design.ball.mass_kg = ball.get("mass", Dimension::kMass, "mass_kg", in.defaults.ball.mass_kg);
  in.design.ball.speed_m_s =
      ball.get("speed", Dimension::kSpeed, "speed_m_s", in.defaults.ball.speed_m_s);
  in.design.ball.cor_on_rigid_surface = ball.reader().number("cor_on_rigid_surface");
  in.design.ball.diameter_m =
      ball.get("diameter", Dimension::kLength, "diameter_m", in.defaults.ball.diameter_m);
  if (const Json* contact = ball.reader().child("contact")) {
    // The ball's contact law (ball_contact.hpp): the power law F = k x^n +
    // b x^p x', the calibrated tennis ball for every coefficient not given, or
    // the hysteretic or the two-mass tennis ball by name.
    ObjectReader c(*contact, "/ball/contact", "ball/contact", in.source, in.keys);
    c.check_known(design_keys("ball/contact"));
    const std::optional<std::string> law = c.string("law");
    if (law && *law != "power" && *law != "hysteretic" && *law != "two_mass")
      c.fail("law", "expected \"power\", \"hysteretic\" or \"two_mass\", got \"" + *law + "\"");
    if (law) c.record("law", "law");  // listed with the inputs as given
    if (law == "hysteretic" || law == "two_mass") {
      for (const char* coefficient : {"stiffness", "exponent", "damping", "damping_exponent"}) {
        if (c.has(coefficient))
          c.fail(coefficient, "is a coefficient of the power law, not of the " + *law +
                                  " ball (give \"law\": \"power\" or leave it out)");
      }
      in.design.ball_contact = law == "two_mass" ? kTwoMassTennisBallLaw : kHystereticTennisBallLaw;
    } else {
      in.design.ball_contact.stiffness = c.number("stiffness").value_or(kTennisBallLaw.stiffness);
      in.design.ball_contact.exponent = c.number("exponent").value_or(kTennisBallLaw.exponent);
      in.design.ball_contact.damping = c.number("damping").value_or(kTennisBallLaw.damping);
      in.design.ball_contact.damping_exponent =
          c.number("damping_exponent").value_or(kTennisBallLaw.damping_exponent);
    }
    c.finish(design_keys("ball/contact"));
  }
  ball.reader().finish(design_keys("ball"));
}

// /swing: the racquet swung at the ball (swing.hpp); absent, none is given.
// Its speed is an angular speed (rad/s or rpm) or the racquet's speed at the
// impact point (m/s, km/h, mph), about a pivot beyond the butt; a reference
// swingweight scales it to the design's (Cross & Bower 2006).
void read_swing(ObjectReader& top, Reading& in) {
  if (!top.child("swing")) return;
  Part swing(top, "swing", in.keys, in.provenance);
  ObjectReader& r = swing.reader();
  const auto rad_s = r.number("angular_speed_rad_s");
  const auto rpm = r.number("angular_speed_rpm");
  const auto at_impact = r.quantity("speed_at_impact", Dimension::kSpeed);
  if (int{rad_s.has_value()} + int{rpm.has_value()} + int{at_impact.has_value()} != 1) {
    r.fail("",
           "give the swing's speed once: angular_speed_rad_s, angular_speed_rpm or "
           "speed_at_impact_m_s (or _km_h, _mph)");
  }
  const auto pivot = r.quantity("pivot_beyond_butt", Dimension::kLength);
  if (!pivot) {
    r.fail("",
           "needs pivot_beyond_butt_m (or _cm, _in): how far beyond the butt the swing's pivot "
           "is (the wrist about 0.05 m, the shoulder about 0.6 m)");
  }
  const std::string pivot_key = r.one_of(spellings("pivot_beyond_butt", Dimension::kLength));
  if (!(*pivot >= 0.0 && *pivot <= kMaxPivotBeyondButt_m)) {
    r.fail(pivot_key,
           "must be in [0, " + brief(kMaxPivotBeyondButt_m) + "] m, got " + brief(*pivot) + " m");
  }
  Swing s;
  s.pivot_beyond_butt_m = *pivot;
  constexpr double kRadPerRev = 2.0 * 3.141592653589793;
  if (rad_s) {
    s.angular_speed_rad_s = *rad_s;
  } else if (rpm) {
    s.angular_speed_rad_s = *rpm * kRadPerRev / 60.0;
    r.record("angular_speed_rad_s", "angular_speed_rpm");
  } else {
    const std::string key = r.one_of(spellings("speed_at_impact", Dimension::kSpeed));
    const double arm = *pivot + in.design.impact_from_butt_m;
    if (!(*at_impact > 0.0 && *at_impact <= kMaxSpeed_m_s)) {
      r.fail(key,
             "must be in (0, " + brief(kMaxSpeed_m_s) + "] m/s, got " + brief(*at_impact) + " m/s");
    }
    if (!(arm > 0.0)) {
      r.fail(key,
             "the impact is at the pivot (pivot_beyond_butt 0 and the impact at the butt): give "
             "angular_speed_rad_s");
    }
    s.angular_speed_rad_s = *at_impact / arm;
    r.record("angular_speed_rad_s", key);
  }
  if (!(s.angular_speed_rad_s > 0.0 && s.angular_speed_rad_s <= kMaxAngularSpeed_rad_s)) {
    const std::string limit =
        "the swing's angular speed must be in (0, " + brief(kMaxAngularSpeed_rad_s) + "] rad/s (" +
        fmt::format("{:.0f}", kMaxAngularSpeed_rad_s * 60.0 / kRadPerRev) + " rpm), got ";
    if (rad_s) r.fail("angular_speed_rad_s", limit + brief(*rad_s) + " rad/s");
    if (rpm) r.fail("angular_speed_rpm", limit + brief(*rpm) + " rpm");
    // A speed at the impact point: say the speed the file gave, in its unit,
    // and the angular speed it makes about the pivot.
    const std::string key = r.one_of(spellings("speed_at_impact", Dimension::kSpeed));
    r.fail(key, limit + brief(*r.child(key)) + " " + std::string(unit_of_key(key)) +
                    " at the impact point, " + brief(*pivot + in.design.impact_from_butt_m) +
                    " m from the pivot: " + brief(s.angular_speed_rad_s) + " rad/s");
  }
  s.reference_swingweight_kg_m2 = r.quantity("reference_swingweight", Dimension::kInertia);
  if (s.reference_swingweight_kg_m2 && !(*s.reference_swingweight_kg_m2 > 0.0)) {
    r.fail(r.one_of(spellings("reference_swingweight", Dimension::kInertia)),
           "must be > 0 (the swingweight of the racquet the swing was measured with), got " +
               brief(*s.reference_swingweight_kg_m2));
  }
  r.finish(design_keys("swing"));
  in.design.swing = s;
}

// /support: what holds the implement (Design::support), by name, or a pivot
// as {"pivot_from_butt_m" (or _cm, _mm, _in): ...}; absent, free.
constexpr std::pair<std::string_view, Support::Kind> kSupportNames[] = {
    {"free", Support::Kind::kFree},
    {"hand", Support::Kind::kHand},
    {"head_clamped", Support::Kind::kHeadClamped},
    {"handle_clamped", Support::Kind::kHandleClamped},
    {"rigid_surface", Support::Kind::kRigidSurface}};
constexpr std::string_view kSupportExpected =
    "expected \"free\", \"hand\", \"head_clamped\", \"handle_clamped\", \"rigid_surface\" "
    "or {\"pivot_from_butt_cm\": ...}";

void read_support(ObjectReader& top, Reading& in) {
  const Json* given = top.child("support");
  if (!given) return;
  Support support;
  if (given->is_string()) {
    const std::string name = given->get<std::string>();
    const auto* found = std::find_if(std::begin(kSupportNames), std::end(kSupportNames),
                                     [&](const auto& named) { return named.first == name; });
    if (found == std::end(kSupportNames)) {
      top.fail("support", name == "pivot"
                              ? "a pivot needs its place: give {\"pivot_from_butt_cm\": ...}"
                              : std::string(kSupportExpected) + ", got " + brief(*given));
    }
    support.kind = found->second;
    top.record("support", "support");  // listed with the inputs as given
  } else if (given->is_object()) {
    Part part(top, "support", in.keys, in.provenance);
    ObjectReader& r = part.reader();
    const auto pivot = r.quantity("pivot_from_butt", Dimension::kLength);
    if (!pivot) {
      r.fail("", "a pivot needs its place: pivot_from_butt_m (or _cm, _mm, _in) from the butt");
    }
    r.finish(design_keys("support"));
    support.kind = Support::Kind::kPivot;
    support.pivot_from_butt_m = *pivot;
  } else {
    top.fail("support", std::string(kSupportExpected) + ", got " + brief(*given));
  }
  in.design.support = support;
}

// Where the ball hits, as the file gives it (or the default of its kind).
struct ImpactRead {
  ImpactPlace place = ImpactPlace::kFromTip;
  double m = kPaperImpactFromTip_m;
  bool given = true;
};

// /impact: from the tip, from the butt or the default, and off the axis.
ImpactRead read_impact(ObjectReader& top, Reading& in, double L, const std::string& form) {
  Part impact(top, "impact", in.keys, in.provenance);
  ImpactPlace impact_place = ImpactPlace::kFromTip;
  double impact_m = kPaperImpactFromTip_m;
  bool impact_given = true;
  {
    ObjectReader& r = impact.reader();
    r.check_known(impact_keys());
    const auto from_tip = r.quantity("from_tip", Dimension::kLength);
    const auto from_butt = r.quantity("from_butt", Dimension::kLength);
    if (from_tip && from_butt) r.fail("", "give the impact point once: from_tip_m or from_butt_m");
    if (from_tip) {
      if (!(*from_tip >= 0.0 && *from_tip <= L)) {
        const std::string key = r.one_of(spellings("from_tip", Dimension::kLength));
        const std::string restated =
            along_in_file_unit(key, "from_tip", L, *from_tip, "on the implement");
        r.fail(key, !restated.empty()
                        ? restated
                        : "must be in [0, " + brief(L) + "] m (on the implement), got " +
                              brief(*from_tip) + " m");
      }
      in.design.impact_from_butt_m = L - *from_tip;
      impact_m = *from_tip;
      in.note("impact/from_butt_m", "given (from the tip)");
    } else if (from_butt) {
      in.design.impact_from_butt_m = *from_butt;
      impact_place = ImpactPlace::kFromButt;
      impact_m = *from_butt;
      in.note("impact/from_butt_m", "given");
    } else {
      impact_given = false;
      impact_place = default_impact(in.design, implement_form_of(form));
      if (impact_place == ImpactPlace::kCentreOfStrings) {
        const double centre = centre_of_strings_from_tip_m(in.design);
        in.design.impact_from_butt_m = L - centre;
        if (in.provenance) {
          (*in.provenance)["impact/from_butt_m"] =
              "default for a racquet: the centre of the strings, " + half_cm_text(centre) +
              " from the tip";
        }
      } else {
        in.design.impact_from_butt_m = L - kPaperImpactFromTip_m;
        in.note("impact/from_butt_m", "default: 5 cm from the tip, as in the paper's Table I");
      }
    }
    if (const auto off_axis = r.quantity("off_axis", Dimension::kLength)) {
      in.design.impact_off_axis_m = *off_axis;
      in.note("impact/off_axis_m", "given");
    }
    r.finish(impact_keys());
  }
  return ImpactRead{impact_place, impact_m, impact_given};
}

// /reference: published values of named outputs, kept as given.
Json read_reference(ObjectReader& top, const std::string& source) {
  Json reference;
  if (const Json* given = top.child("reference")) {
    ObjectReader r(*given, "/reference", "reference", source, nullptr);
    r.string("source");
    std::vector<std::string> expected{"source"};
    for (const OutputSpec& output : output_specs()) {
      expected.emplace_back(output.name);
      r.number(output.name);
    }
    r.finish(expected);
    reference = *given;
  }
  return reference;
}

// With `bookkeeping`, the provenance of every input and the key map that
// lets a later error name the user's own key; without, neither (a core error
// is then rethrown as it is, for the caller to read again with them).
// `described`, when given, receives the numbers as the file gives them.
DesignFile read_design_impl(const Json& document, const std::string& source, bool bookkeeping,
                            std::optional<DesignDescription>* described = nullptr) {
  KeyMap key_map;
  KeyMap* const keys = bookkeeping ? &key_map : nullptr;
  std::map<std::string, std::string> provenance_map;
  std::map<std::string, std::string>* const provenance = bookkeeping ? &provenance_map : nullptr;
  const auto note = [&](const char* input, const char* how) {
    if (provenance) (*provenance)[input] = how;
  };
  ObjectReader top(document, "", "", source, keys);
  top.check_known(design_keys(""));
  // The file name stands in for a missing name; it need not be UTF-8, a name must.
  const std::string name = top.string("name").value_or(valid_utf8(source));
  top.string("description");
  top.string("$schema");
  const std::string fidelity = top.string("fidelity").value_or("auto");
  try {
    parse_fidelity(fidelity);
  } catch (const std::invalid_argument& e) {
    top.fail("fidelity", e.what());
  }
  ImplementDescription implement_described;
  ImplementRead implement =
      read_implement(document, source, keys, described ? &implement_described : nullptr);
  top.child("implement");
  const double L = implement.implement.length_m();

  const Design defaults{implement.implement};
  Design design = defaults;
  design.head = implement.head.head;
  design.twistweight_kg_m2 = implement.head.twistweight_kg_m2;
  if (design.twistweight_kg_m2) {
    note("implement/twistweight_kg_m2", "given");
  } else if (design.head) {
    note("implement/twistweight_kg_m2", "estimated from the head's size (about +-15 %)");
  }

  Reading in{source, keys, provenance, defaults, design};
  read_frame(top, in);
  // The frame's EI is for the sections without their own: where every
  // section has one (a profile, or sections each with EI_N_m2) it would be
  // read and never used.
  if (const std::vector<Section>& sections = implement.implement.sections();
      design.stiffness.EI_N_m2 && !sections.empty() &&
      std::all_of(sections.begin(), sections.end(),
                  [](const Section& s) { return s.EI_N_m2.has_value(); })) {
    std::string key = "EI_N_m2";
    for (const auto& [name, value] : document.at("frame").items()) {
      if (name.starts_with("EI_")) key = name;
    }
    throw InputError(
        source, "/frame/" + key,
        implement.form == "profile"
            ? "contradicts /implement/youngs_modulus: the profile gives the stiffness; "
              "give it once"
            : "every section gives its own EI_N_m2, so this one would not be used; "
              "give the stiffness once");
  }
  const std::optional<double> head_area_m2 = read_strings(top, in, implement);
  read_hand(top, in);
  const std::optional<double> forearm_mass_kg = read_forearm(top, in);
  read_ball(top, in);
  const ImpactRead impact = read_impact(top, in, L, implement.form);
  read_swing(top, in);
  read_support(top, in);
  Json reference = read_reference(top, source);
  top.finish(design_keys(""));

  try {
    validate(design);
  } catch (const std::invalid_argument& error) {
    if (!bookkeeping) throw;
    rethrow_at(error, "", key_map, source, "");
  }
  if (described) {
    described->emplace(DesignDescription{std::move(implement_described), design,
                                         forearm_mass_kg.has_value(), forearm_mass_kg.value_or(0.0),
                                         impact.place, impact.m, impact.given, head_area_m2,
                                         in.string_ticket});
  }
  return DesignFile{source,
                    name,
                    std::move(design),
                    implement.form,
                    std::move(provenance_map),
                    std::move(reference),
                    std::move(key_map),
                    fidelity};
}

}  // namespace

DesignFile read_design(const Json& document, const std::string& source) {
  return read_design_impl(document, source, true);
}

DesignFile read_design_lean(const Json& document, const std::string& source) {
  try {
    return read_design_impl(document, source, false);
  } catch (const std::invalid_argument&) {
    return read_design_impl(document, source, true);  // throws the error at the user's key
  }
}

DesignDescription describe_design(const Json& document, const std::string& source) {
  std::optional<DesignDescription> described;
  try {
    read_design_impl(document, source, false, &described);
  } catch (const std::invalid_argument&) {
    read_design_impl(document, source, true);  // throws the error at the user's key
    throw;
  }
  return std::move(*described);
}

void rethrow_in(const DesignFile& design, const std::invalid_argument& error) {
  rethrow_at(error, "", design.keys, design.source, "");
}

DesignFile load_design(const std::string& path) {
  return read_design(read_json_file(path), input_name(path));
}

namespace {

// Writes `value` under the field table's SI key of `stem` in `object`, so a
// field the table renames is renamed here (a stem it does not hold throws).
void put(Json& into, std::string_view object, std::string_view stem, Json value) {
  into[si_key(object, stem)] = std::move(value);
}

}  // namespace

Json design_to_json(const DesignFile& file) {
  const Design& d = file.design;
  const Implement& implement = d.implement;
  Json j;
  put(j, "", "name", file.name);
  Json& impl = j[si_key("", "implement")];
  // A profile whose slices give the frame's cross-section is written as the
  // profile (its slices' sections alone would lose their diameters).
  if (implement.profile() && d.stiffness.shear_modulus_Pa &&
      d.stiffness.cross_section.shape == CrossSection::Shape::kProfile) {
    const RoundProfile& profile = *implement.profile();
    Json& stations = impl[si_key("implement", "profile")] = Json::array();
    for (const ProfileStation& s : profile.stations) {
      Json station = Json::object();
      put(station, "implement/profile/N", "from_butt", s.from_butt_m);
      put(station, "implement/profile/N", "diameter", s.diameter_m);
      stations.push_back(std::move(station));
    }
    put(impl, "implement", "density_kg_m3", profile.density_kg_m3);
    put(impl, "implement", "youngs_modulus", profile.youngs_modulus_Pa);
    if (profile.wall_m != 0.0) put(impl, "implement", "wall", profile.wall_m);
  } else if (implement.has_mass_distribution()) {
    Json& sections = impl[si_key("implement", "sections")] = Json::array();
    for (const Section& s : implement.sections()) {
      Json section = Json::object();
      put(section, "implement/sections/N", "length", s.length_m);
      put(section, "implement/sections/N", "mass", s.mass_kg);
      if (s.EI_N_m2) put(section, "implement/sections/N", "EI", *s.EI_N_m2);
      sections.push_back(std::move(section));
    }
  } else {
    const MassProperties& frame = implement.frame_mass_properties();
    put(impl, "implement", "length", implement.length_m());
    put(impl, "implement", "mass", frame.mass_kg);
    put(impl, "implement", "balance", frame.com_from_butt_m);
    put(impl, "implement", "swingweight", swingweight_kg_m2(frame));
  }
  if (!implement.point_masses().empty()) {
    Json& points = impl[si_key("implement", "point_masses")] = Json::array();
    for (const PointMass& p : implement.point_masses()) {
      Json point = Json::object();
      put(point, "implement/point_masses/N", "mass", p.mass_kg);
      put(point, "implement/point_masses/N", "from_butt", p.from_butt_m);
      if (p.off_axis_m != 0.0) put(point, "implement/point_masses/N", "off_axis", p.off_axis_m);
      points.push_back(std::move(point));
    }
  }
  if (d.head) {
    put(impl, "implement", "headsize", d.head->area_m2 * 1e4);
    put(impl, "implement", "head_aspect_ratio", d.head->aspect_ratio);
    put(impl, "implement", "hoop_width", d.head->hoop_width_m);
  }
  if (d.twistweight_kg_m2) put(impl, "implement", "twistweight", *d.twistweight_kg_m2);
  // A strung design without a COR has it derived by the solved collision.
  Json& frame = j[si_key("", "frame")] = Json::object();
  if (d.cor_rigid) {
    put(frame, "frame", "cor_rigid", *d.cor_rigid);
  } else if (d.cor_given || !d.strings) {
    put(frame, "frame", "cor", d.cor);
  }
  if (d.stiffness.EI_N_m2) put(frame, "frame", "EI", *d.stiffness.EI_N_m2);
  if (d.stiffness.fundamental_free_Hz)
    put(frame, "frame", "fundamental_free", *d.stiffness.fundamental_free_Hz);
  if (d.stiffness.RA) put(frame, "frame", "RA", *d.stiffness.RA);
  if (d.stiffness.shear_modulus_Pa) {
    Json& section = frame[si_key("frame", "cross_section")] = Json::object();
    put(section, "frame/cross_section", "shear_modulus_Pa", *d.stiffness.shear_modulus_Pa);
    const CrossSection& c = d.stiffness.cross_section;
    using Shape = CrossSection::Shape;
    if (c.shape != Shape::kRectangle)
      section[si_key("frame/cross_section", "shape")] = section_shape_name(c.shape);
    if (sized_by_width(c.shape)) {
      put(section, "frame/cross_section", "width", c.width_m);
      put(section, "frame/cross_section", "thickness", c.thickness_m);
    } else if (sized_by_diameter(c.shape)) {
      put(section, "frame/cross_section", "diameter", c.diameter_m);
    }
    if (has_wall(c.shape)) put(section, "frame/cross_section", "wall", c.wall_m);
    if (c.poisson_ratio != 0.0)
      put(section, "frame/cross_section", "poisson_ratio", c.poisson_ratio);
  }
  Json& strings = j[si_key("", "strings")] = Json::object();
  if (d.strings) {
    const StringBed& bed = *d.strings;
    if (bed.cross_tension_ratio == 1.0 && bed.cross_spacing_ratio == 1.0 &&
        bed.cross_linear_density_kg_m == bed.main_linear_density_kg_m) {
      put(strings, "strings", "tension", bed.tension_N);
      put(strings, "strings", "string_spacing", bed.string_spacing_m);
      if (bed.main_linear_density_kg_m != kDefaultStringLinearDensity_kg_m)
        put(strings, "strings", "linear_density", bed.main_linear_density_kg_m);
    } else {
      // A hybrid or a pattern: each family as the bed holds it.
      for (const auto& [family, tension, spacing, density] :
           {std::tuple{"mains", bed.tension_N, bed.main_spacing_m(), bed.main_linear_density_kg_m},
            std::tuple{"crosses", bed.cross_tension_N(), bed.cross_spacing_m(),
                       bed.cross_linear_density_kg_m}}) {
        const std::string object = std::string("strings/") + family;
        Json& f = strings[family] = Json::object();
        put(f, object, "tension", tension);
        put(f, object, "spacing", spacing);
        put(f, object, "linear_density", density);
      }
    }
    // One head, one size: the implement's head gives the bed's (written
    // above), and the bed's size written here becomes the head's when read
    // back; the default bed with no head is written as none.
    if (!d.head && d.strings->head_radius_m != StringBed{}.head_radius_m)
      put(strings, "strings", "head_size",
          3.141592653589793 * d.strings->head_radius_m * d.strings->head_radius_m * 1e4);
    put(strings, "strings", "contact_radius", d.strings->contact_radius_m);
  } else {
    put(strings, "strings", "impact_duration", d.impact_duration_s);
  }
  // The solved collision's inputs, when not the defaults.
  if (d.string_bed_mass_kg != kStringBedMass_kg)
    put(strings, "strings", "bed_mass", d.string_bed_mass_kg);
  if (d.string_bed_damping_ratio != kStringBedDampingRatio)
    put(strings, "strings", "bed_damping_ratio", d.string_bed_damping_ratio);
  Json& hand = j[si_key("", "hand")] = Json::object();
  put(hand, "hand", "mass", d.hand.mass_kg);
  put(hand, "hand", "center_from_butt", d.hand.center_from_butt_m);
  put(hand, "hand", "grip_length", d.hand.grip_length_m);
  put(hand, "hand", "grip_stiffness", d.hand.grip_stiffness_N_m2);
  put(hand, "hand", "grip_damping", d.hand.grip_damping_N_s_m2);
  put(j[si_key("", "forearm")], "forearm", "equivalent_mass", d.forearm_equivalent_mass_kg);
  Json& ball = j[si_key("", "ball")] = Json::object();
  put(ball, "ball", "mass", d.ball.mass_kg);
  put(ball, "ball", "speed", d.ball.speed_m_s);
  put(ball, "ball", "diameter", d.ball.diameter_m);
  if (d.ball.cor_on_rigid_surface)
    put(ball, "ball", "cor_on_rigid_surface", *d.ball.cor_on_rigid_surface);
  const BallContactLaw& c = d.ball_contact;
  const BallContactLaw& t = kTennisBallLaw;
  if (is_hysteretic(c.form)) {
    ball[si_key("ball", "contact")] = Json{{"law", to_string(c.form)}};
  } else if (c.stiffness != t.stiffness || c.exponent != t.exponent || c.damping != t.damping ||
             c.damping_exponent != t.damping_exponent) {
    Json& contact = ball[si_key("ball", "contact")] = Json::object();
    put(contact, "ball/contact", "stiffness", c.stiffness);
    put(contact, "ball/contact", "exponent", c.exponent);
    put(contact, "ball/contact", "damping", c.damping);
    put(contact, "ball/contact", "damping_exponent", c.damping_exponent);
  }
  Json& impact = j[si_key("", "impact")] = Json::object();
  put(impact, "impact", "from_butt", d.impact_from_butt_m);
  if (d.impact_off_axis_m != 0.0) put(impact, "impact", "off_axis", d.impact_off_axis_m);
  if (d.swing) {
    Json& swing = j[si_key("", "swing")] = Json::object();
    put(swing, "swing", "angular_speed", d.swing->angular_speed_rad_s);
    put(swing, "swing", "pivot_beyond_butt", d.swing->pivot_beyond_butt_m);
    if (d.swing->reference_swingweight_kg_m2)
      put(swing, "swing", "reference_swingweight", *d.swing->reference_swingweight_kg_m2);
  }
  if (d.support.kind == Support::Kind::kPivot) {
    Json& support = j[si_key("", "support")] = Json::object();
    put(support, "support", "pivot_from_butt", d.support.pivot_from_butt_m);
  } else if (d.support.kind != Support::Kind::kFree) {
    j[si_key("", "support")] = std::string(to_string(d.support.kind));
  }
  return j;
}

void require_player_file(const DesignFile& file, std::string_view what) {
  try {
    require_player(file.design, what);
  } catch (const std::invalid_argument& e) {
    rethrow_in(file, e);
  }
}

Evaluation evaluate_design_file(const DesignFile& file, std::string_view fidelity, double rel_tol) {
  try {
    const std::string_view name = fidelity.empty() ? std::string_view(file.fidelity) : fidelity;
    return evaluate(file.design, resolve_fidelity(name, file.design), {.rel_tol = rel_tol});
  } catch (const std::invalid_argument& e) {
    rethrow_in(file, e);
  }
}

}  // namespace sweetspot::io

#include "studies/design_binding.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <utility>

#include "io/design_fields.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::studies {
namespace {

using Setter = void (*)(io::DesignDescription&, std::size_t, double);
using Form = io::ImplementDescription::Form;
using D = io::DesignDescription;

// What a binding may set: a field of the design's field table (`object`,
// `stem`; `key` when one spelling sets it differently, "" for every
// spelling), whether the design as read has that number in that form (entry
// `index` of a list), how the SI value is written, and whether the implement
// is rebuilt from it. The spellings and their conversions are the table's;
// only the writing is here.
struct FieldSetter {
  std::string_view object;
  std::string_view stem;
  std::string_view key;
  bool (*available)(const D&, std::size_t index);
  Setter set;
  bool implement = false;
};

bool always(const D&, std::size_t) { return true; }
bool ratio_or_specs(const D& d, std::size_t) {
  return d.implement.form == Form::kHeadToHandleRatio || d.implement.form == Form::kSpecs;
}
bool specs(const D& d, std::size_t) { return d.implement.form == Form::kSpecs; }
bool has_head(const D& d, std::size_t) { return d.implement.head.has_value() && !d.string_ticket; }
bool has_section(const D& d, std::size_t k) {
  return d.implement.form == Form::kSections && k < d.implement.sections.size();
}
bool profile(const D& d, std::size_t) { return d.implement.form == Form::kProfile; }
bool has_station(const D& d, std::size_t k) {
  return d.implement.form == Form::kProfile && k < d.implement.profile.stations.size();
}
const io::PointMassDescription* entry(const D& d, std::size_t k) {
  return k < d.implement.point_masses.size() ? &d.implement.point_masses[k] : nullptr;
}
bool has_strings(const D& d, std::size_t) {
  return d.design.strings.has_value() && !d.string_ticket;
}
bool has_cross_section(const D& d, std::size_t) {
  return d.design.stiffness.shear_modulus_Pa.has_value();
}
// A size of the section's own shape: a rectangle's width, a circle's diameter.
template <CrossSection::Shape... Shapes>
bool has_section_of(const D& d, std::size_t k) {
  return has_cross_section(d, k) && ((d.design.stiffness.cross_section.shape == Shapes) || ...);
}

// The impact given from the tip or from the butt: settable when the file
// gives it that way, or gives none (the pointer then places it).
template <io::ImpactPlace Place>
bool impact_available(const D& d, std::size_t) {
  return d.impact_place == Place || !d.impact_given;
}
template <io::ImpactPlace Place>
void set_impact(D& x, std::size_t, double v) {
  x.impact_place = Place;
  x.impact_given = true;
  x.impact_m = v;
}

// Every number a sweep, a study or a catalogue column can set. A test checks
// each row names a field of the table.
const std::vector<FieldSetter>& field_setters() {
  static const std::vector<FieldSetter> kSetters{
      {"implement", "length", "", ratio_or_specs,
       [](D& x, std::size_t, double v) { x.implement.length_m = v; }, true},
      {"implement", "mass", "", ratio_or_specs,
       [](D& x, std::size_t, double v) { x.implement.mass_kg = v; }, true},
      {"implement", "head_to_handle_mass_ratio", "",
       [](const D& d, std::size_t) { return d.implement.form == Form::kHeadToHandleRatio; },
       [](D& x, std::size_t, double v) { x.implement.head_to_handle_mass_ratio = v; }, true},
      {"implement", "balance", "balance_pts_hl", specs,
       [](D& x, std::size_t, double v) {
         x.implement.balance_in_points = true;
         x.implement.balance = v;
       },
       true},
      {"implement", "balance", "", specs,
       [](D& x, std::size_t, double v) {
         x.implement.balance_in_points = false;
         x.implement.balance = v;
       },
       true},
      {"implement", "swingweight", "", specs,
       [](D& x, std::size_t, double v) { x.implement.swingweight_kg_m2 = v; }, true},
      {"implement", "headsize", "", has_head,
       [](D& x, std::size_t, double v) { x.implement.head->area_m2 = v; }, true},
      {"implement", "head_aspect_ratio", "", has_head,
       [](D& x, std::size_t, double v) { x.implement.head->aspect_ratio = v; }, true},
      {"implement", "hoop_width", "", has_head,
       [](D& x, std::size_t, double v) { x.implement.head->hoop_width_m = v; }, true},
      {"implement/sections/N", "length", "", has_section,
       [](D& x, std::size_t k, double v) { x.implement.sections[k].length_m = v; }, true},
      {"implement/sections/N", "mass", "", has_section,
       [](D& x, std::size_t k, double v) { x.implement.sections[k].mass_kg = v; }, true},
      {"implement/sections/N", "EI", "",
       [](const D& d, std::size_t k) {
         return has_section(d, k) && d.implement.sections[k].EI_N_m2.has_value();
       },
       [](D& x, std::size_t k, double v) { x.implement.sections[k].EI_N_m2 = v; }, true},
      {"implement/profile/N", "from_butt", "", has_station,
       [](D& x, std::size_t k, double v) { x.implement.profile.stations[k].from_butt_m = v; },
       true},
      {"implement/profile/N", "diameter", "", has_station,
       [](D& x, std::size_t k, double v) { x.implement.profile.stations[k].diameter_m = v; }, true},
      {"implement", "density_kg_m3", "", profile,
       [](D& x, std::size_t, double v) { x.implement.profile.density_kg_m3 = v; }, true},
      {"implement", "youngs_modulus", "", profile,
       [](D& x, std::size_t, double v) { x.implement.profile.youngs_modulus_Pa = v; }, true},
      {"implement", "wall", "", profile,
       [](D& x, std::size_t, double v) { x.implement.profile.wall_m = v; }, true},
      // Entry N of the file's list, whatever it holds (a clock pair is one
      // entry; its mass is each piece's).
      {"implement/point_masses/N", "mass", "",
       [](const D& d, std::size_t k) { return entry(d, k) != nullptr; },
       [](D& x, std::size_t k, double v) { x.implement.point_masses[k].mass_kg = v; }, true},
      {"implement/point_masses/N", "from_butt", "",
       [](const D& d, std::size_t k) { return entry(d, k) && entry(d, k)->from_butt_m; },
       [](D& x, std::size_t k, double v) { x.implement.point_masses[k].from_butt_m = v; }, true},
      {"implement/point_masses/N", "from_tip", "",
       [](const D& d, std::size_t k) { return entry(d, k) && entry(d, k)->from_tip_m; },
       [](D& x, std::size_t k, double v) { x.implement.point_masses[k].from_tip_m = v; }, true},
      {"implement/point_masses/N", "off_axis", "",
       [](const D& d, std::size_t k) {
         const io::PointMassDescription* e = entry(d, k);
         return e && !e->handle_from_butt_m && e->clock_hours.empty();
       },
       [](D& x, std::size_t k, double v) { x.implement.point_masses[k].off_axis_m = v; }, true},
      {"implement/point_masses/N", "clock", "",
       [](const D& d, std::size_t k) {
         return entry(d, k) && entry(d, k)->clock_hours.size() == 1;
       },
       [](D& x, std::size_t k, double v) { x.implement.point_masses[k].clock_hours = {v}; }, true},
      {"frame", "cor", "", [](const D& d, std::size_t) { return !d.design.cor_rigid; },
       [](D& x, std::size_t, double v) { x.design.cor = v; }},
      {"frame", "cor_rigid", "",
       [](const D& d, std::size_t) { return d.design.cor_rigid.has_value(); },
       [](D& x, std::size_t, double v) { x.design.cor_rigid = v; }},
      {"frame", "EI", "",
       [](const D& d, std::size_t) { return d.design.stiffness.EI_N_m2.has_value(); },
       [](D& x, std::size_t, double v) { x.design.stiffness.EI_N_m2 = v; }},
      {"frame", "fundamental_free", "",
       [](const D& d, std::size_t) { return d.design.stiffness.fundamental_free_Hz.has_value(); },
       [](D& x, std::size_t, double v) { x.design.stiffness.fundamental_free_Hz = v; }},
      {"frame", "RA", "", [](const D& d, std::size_t) { return d.design.stiffness.RA.has_value(); },
       [](D& x, std::size_t, double v) { x.design.stiffness.RA = v; }},
      {"frame/cross_section", "shear_modulus_Pa", "", has_cross_section,
       [](D& x, std::size_t, double v) { x.design.stiffness.shear_modulus_Pa = v; }},
      {"frame/cross_section", "width", "",
       has_section_of<CrossSection::Shape::kRectangle, CrossSection::Shape::kEllipse,
                      CrossSection::Shape::kBox>,
       [](D& x, std::size_t, double v) { x.design.stiffness.cross_section.width_m = v; }},
      {"frame/cross_section", "thickness", "",
       has_section_of<CrossSection::Shape::kRectangle, CrossSection::Shape::kEllipse,
                      CrossSection::Shape::kBox>,
       [](D& x, std::size_t, double v) { x.design.stiffness.cross_section.thickness_m = v; }},
      {"frame/cross_section", "diameter", "",
       has_section_of<CrossSection::Shape::kCircle, CrossSection::Shape::kHollowCircle>,
       [](D& x, std::size_t, double v) { x.design.stiffness.cross_section.diameter_m = v; }},
      {"frame/cross_section", "wall", "",
       has_section_of<CrossSection::Shape::kHollowCircle, CrossSection::Shape::kBox>,
       [](D& x, std::size_t, double v) { x.design.stiffness.cross_section.wall_m = v; }},
      {"frame/cross_section", "poisson_ratio", "", has_cross_section,
       [](D& x, std::size_t, double v) { x.design.stiffness.cross_section.poisson_ratio = v; }},
      {"strings", "impact_duration", "", [](const D& d, std::size_t) { return !d.design.strings; },
       [](D& x, std::size_t, double v) { x.design.impact_duration_s = v; }},
      {"strings", "tension", "", has_strings,
       [](D& x, std::size_t, double v) { x.design.strings->tension_N = v; }},
      {"strings", "string_spacing", "", has_strings,
       [](D& x, std::size_t, double v) { x.design.strings->string_spacing_m = v; }},
      {"strings", "contact_radius", "", has_strings,
       [](D& x, std::size_t, double v) { x.design.strings->contact_radius_m = v; }},
      {"strings", "head_size", "",
       [](const D& d, std::size_t) { return has_strings(d, 0) && d.head_area_m2; },
       // The head's size when the implement gives none: clock positions move.
       [](D& x, std::size_t, double v) { x.head_area_m2 = v; }, true},
      {"hand", "mass", "", always, [](D& x, std::size_t, double v) { x.design.hand.mass_kg = v; }},
      {"hand", "center_from_butt", "", always,
       [](D& x, std::size_t, double v) { x.design.hand.center_from_butt_m = v; }},
      {"hand", "grip_length", "", always,
       [](D& x, std::size_t, double v) { x.design.hand.grip_length_m = v; }},
      {"hand", "grip_stiffness", "", always,
       [](D& x, std::size_t, double v) { x.design.hand.grip_stiffness_N_m2 = v; }},
      {"hand", "grip_damping", "", always,
       [](D& x, std::size_t, double v) { x.design.hand.grip_damping_N_s_m2 = v; }},
      {"forearm", "equivalent_mass", "",
       [](const D& d, std::size_t) { return !d.forearm_from_mass; },
       [](D& x, std::size_t, double v) { x.design.forearm_equivalent_mass_kg = v; }},
      {"forearm", "mass", "", [](const D& d, std::size_t) { return d.forearm_from_mass; },
       [](D& x, std::size_t, double v) { x.forearm_mass_kg = v; }},
      {"ball", "mass", "", always, [](D& x, std::size_t, double v) { x.design.ball.mass_kg = v; }},
      {"ball", "speed", "", always,
       [](D& x, std::size_t, double v) { x.design.ball.speed_m_s = v; }},
      // A file without an impact takes the one written at the pointer.
      {"impact", "from_tip", "", impact_available<io::ImpactPlace::kFromTip>,
       set_impact<io::ImpactPlace::kFromTip>},
      {"impact", "from_butt", "", impact_available<io::ImpactPlace::kFromButt>,
       set_impact<io::ImpactPlace::kFromButt>},
  };
  return kSetters;
}

// "0", "12" (no sign, no leading zero, as a JSON pointer's array index).
std::optional<std::size_t> index_of(std::string_view token) {
  if (token.empty() || token.size() > 6 || (token.size() > 1 && token[0] == '0'))
    return std::nullopt;
  std::size_t value = 0;
  for (const char c : token) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  return value;
}

std::vector<std::string_view> tokens_of(std::string_view pointer) {
  std::vector<std::string_view> tokens;
  if (!pointer.starts_with('/') || pointer.find('~') != std::string_view::npos) return tokens;
  pointer.remove_prefix(1);
  while (true) {
    const auto slash = pointer.find('/');
    tokens.push_back(pointer.substr(0, slash));
    if (slash == std::string_view::npos) break;
    pointer.remove_prefix(slash + 1);
  }
  return tokens;
}

}  // namespace

std::vector<std::pair<std::string_view, std::string_view>> bindable_fields() {
  std::vector<std::pair<std::string_view, std::string_view>> fields;
  for (const FieldSetter& s : field_setters()) fields.emplace_back(s.object, s.stem);
  return fields;
}

std::optional<FieldBinding> bind_field(const io::DesignDescription& d, std::string_view pointer) {
  const std::vector<std::string_view> t = tokens_of(pointer);
  if (t.size() < 2) return std::nullopt;
  // The table's object of the pointer: "implement/point_masses/2/mass_g" is
  // key mass_g of "implement/point_masses/N", entry 2. One index at most.
  std::string object;
  std::optional<std::size_t> index;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (i > 0) object += '/';
    if (const auto k = index_of(t[i])) {
      if (index) return std::nullopt;
      index = k;
      object += 'N';
    } else {
      object += t[i];
    }
  }
  const bool list = object.ends_with("/N");
  if (list != index.has_value() || (index && object.find('N') != object.size() - 1))
    return std::nullopt;
  const std::string_view key = t.back();
  const auto spelling = io::find_spelling(object, key);
  if (!spelling) return std::nullopt;
  const std::size_t at = index.value_or(0);
  for (const FieldSetter& s : field_setters()) {
    if (s.object != spelling->field->object || s.stem != spelling->field->stem) continue;
    if (!s.key.empty() && s.key != key) continue;
    if (!s.available(d, at)) return std::nullopt;
    return FieldBinding{std::string(pointer),    spelling->scale,      s.set, at, s.implement,
                        spelling->field->object, spelling->field->stem};
  }
  return std::nullopt;
}

std::optional<CompiledDesign> CompiledDesign::compile(io::DesignDescription description,
                                                      std::span<const std::string> pointers) {
  CompiledDesign compiled(std::move(description));
  for (const std::string& pointer : pointers) {
    auto binding = bind_field(compiled.description_, pointer);
    if (!binding) return std::nullopt;
    compiled.rebuilds_implement_ = compiled.rebuilds_implement_ || binding->implement;
    compiled.bindings_.push_back(std::move(*binding));
  }
  return compiled;
}

BoundDesign::BoundDesign(const CompiledDesign& compiled)
    : compiled_(&compiled),
      live_(compiled.description()),
      last_si_(compiled.bindings().size(), std::numeric_limits<double>::quiet_NaN()),
      implement_built_(!compiled.rebuilds_implement()) {}

const Design* BoundDesign::at(std::span<const double> values) {
  const std::vector<FieldBinding>& bindings = compiled_->bindings();
  bool rebuild = !implement_built_;
  for (std::size_t i = 0; i < bindings.size(); ++i) {
    const FieldBinding& b = bindings[i];
    if (!std::isfinite(values[i])) return nullptr;  // the reader wants a finite number
    const double si = b.scale.to_si(values[i]);
    if (b.implement) {
      // Bit for bit: -0.0 and 0.0 need not build the same implement.
      rebuild =
          rebuild || std::bit_cast<std::uint64_t>(si) != std::bit_cast<std::uint64_t>(last_si_[i]);
      last_si_[i] = si;
    }
    b.set(live_, b.index, si);
  }
  try {
    if (rebuild) {
      implement_built_ = false;
      live_.design.implement = io::build_implement(live_);
      implement_built_ = true;
    }
    io::derive(live_);
  } catch (const std::exception&) {
    return nullptr;
  }
  return &live_.design;
}

}  // namespace sweetspot::studies

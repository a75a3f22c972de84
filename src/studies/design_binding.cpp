#include "studies/design_binding.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <utility>

#include "io/json_reader.hpp"

namespace sweetspot::studies {
namespace {

using Setter = void (*)(io::DesignDescription&, std::size_t, double);
using Form = io::ImplementDescription::Form;

// A number of one part of the design: a quantity spelled base + a unit suffix
// of `dimension`, or (`dimension` empty) a plain number under exactly `base`.
struct Field {
  std::string_view base;
  std::optional<io::Dimension> dimension;
  Setter set;
  bool available;  // whether the design as read has this number in this form
};

// The conversion of `key` if it spells one of `fields`, with that field.
std::optional<std::pair<io::UnitScale, Setter>> match(std::string_view key,
                                                      std::initializer_list<Field> fields) {
  for (const Field& f : fields) {
    if (!f.available) continue;
    if (!f.dimension) {
      if (key == f.base) return std::pair{io::UnitScale{}, f.set};
      continue;
    }
    if (const auto scale = io::unit_scale(key, f.base, *f.dimension))
      return std::pair{*scale, f.set};
  }
  return std::nullopt;
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

std::optional<FieldBinding> bind_field(const io::DesignDescription& d, std::string_view pointer) {
  const std::vector<std::string_view> t = tokens_of(pointer);
  if (t.size() < 2) return std::nullopt;
  const Design& design = d.design;
  const io::ImplementDescription& implement = d.implement;
  std::optional<std::pair<io::UnitScale, Setter>> found;
  bool rebuilds = false;
  std::size_t index = 0;
  if (t[0] == "implement" && t.size() == 2) {
    const bool ratio = implement.form == Form::kHeadToHandleRatio;
    const bool specs = implement.form == Form::kSpecs;
    rebuilds = true;
    found = match(
        t[1], {{"length", io::Dimension::kLength,
                [](io::DesignDescription& x, std::size_t, double v) { x.implement.length_m = v; },
                ratio || specs},
               {"mass", io::Dimension::kMass,
                [](io::DesignDescription& x, std::size_t, double v) { x.implement.mass_kg = v; },
                ratio || specs},
               {"head_to_handle_mass_ratio", std::nullopt,
                [](io::DesignDescription& x, std::size_t, double v) {
                  x.implement.head_to_handle_mass_ratio = v;
                },
                ratio},
               {"balance_from_butt_m", std::nullopt,
                [](io::DesignDescription& x, std::size_t, double v) {
                  x.implement.balance_in_points = false;
                  x.implement.balance = v;
                },
                specs},
               {"balance_pts_hl", std::nullopt,
                [](io::DesignDescription& x, std::size_t, double v) {
                  x.implement.balance_in_points = true;
                  x.implement.balance = v;
                },
                specs},
               {"swingweight", io::Dimension::kInertia,
                [](io::DesignDescription& x, std::size_t, double v) {
                  x.implement.swingweight_kg_m2 = v;
                },
                specs},
               {"head_aspect_ratio", std::nullopt,
                [](io::DesignDescription& x, std::size_t, double v) {
                  x.implement.head->aspect_ratio = v;
                },
                implement.head.has_value()},
               {"hoop_width", io::Dimension::kLength,
                [](io::DesignDescription& x, std::size_t, double v) {
                  x.implement.head->hoop_width_m = v;
                },
                implement.head.has_value()}});
    // The reader scales a balance in cm and a head in cm^2 as a unit does.
    if (!found && specs && t[1] == "balance_cm") {
      found = std::pair{io::UnitScale{0.01, -2},
                        Setter{[](io::DesignDescription& x, std::size_t, double v) {
                          x.implement.balance_in_points = false;
                          x.implement.balance = v;
                        }}};
    }
    if (!found && implement.head && (t[1] == "headsize_sq_in" || t[1] == "headsize_cm2")) {
      found = std::pair{
          t[1] == "headsize_sq_in" ? io::UnitScale{io::kSquareInch_m2, 0} : io::UnitScale{1e-4, -4},
          Setter{[](io::DesignDescription& x, std::size_t, double v) {
            x.implement.head->area_m2 = v;
          }}};
    }
  } else if (t[0] == "implement" && t.size() == 4 &&
             (t[1] == "sections" || t[1] == "point_masses")) {
    const auto i = index_of(t[2]);
    if (!i) return std::nullopt;
    index = *i;
    rebuilds = true;
    if (t[1] == "sections") {
      const bool has = implement.form == Form::kSections && index < implement.sections.size();
      found = match(t[3], {{"length", io::Dimension::kLength,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.sections[k].length_m = v;
                            },
                            has},
                           {"mass", io::Dimension::kMass,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.sections[k].mass_kg = v;
                            },
                            has},
                           {"EI", io::Dimension::kStiffness,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.sections[k].EI_N_m2 = v;
                            },
                            has && implement.sections[index].EI_N_m2.has_value()}});
    } else {
      // Entry N of the file's list, whatever it holds (a clock pair is one
      // entry; its mass is each piece's).
      const bool has = index < implement.point_masses.size();
      const io::PointMassDescription* entry = has ? &implement.point_masses[index] : nullptr;
      const bool on_axis = entry && !entry->handle && entry->clock_hours.empty();
      found = match(t[3], {{"from_butt", io::Dimension::kLength,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.point_masses[k].from_butt_m = v;
                            },
                            entry && entry->from_butt_m.has_value()},
                           {"from_tip", io::Dimension::kLength,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.point_masses[k].from_tip_m = v;
                            },
                            entry && entry->from_tip_m.has_value()},
                           {"off_axis", io::Dimension::kLength,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.point_masses[k].off_axis_m = v;
                            },
                            on_axis},
                           {"clock", std::nullopt,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.point_masses[k].clock_hours = {v};
                            },
                            entry && entry->clock_hours.size() == 1},
                           {"mass", io::Dimension::kMass,
                            [](io::DesignDescription& x, std::size_t k, double v) {
                              x.implement.point_masses[k].mass_kg = v;
                            },
                            has}});
    }
  } else if (t.size() == 2 && t[0] == "frame") {
    found = match(
        t[1],
        {{"cor", std::nullopt,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.cor = v; },
          !design.cor_rigid},
         {"cor_rigid", std::nullopt,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.cor_rigid = v; },
          design.cor_rigid.has_value()},
         {"EI", io::Dimension::kStiffness,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.stiffness.EI_N_m2 = v; },
          design.stiffness.EI_N_m2.has_value()},
         {"fundamental_free", io::Dimension::kFrequency,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.stiffness.fundamental_free_Hz = v;
          },
          design.stiffness.fundamental_free_Hz.has_value()},
         {"RA", std::nullopt,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.stiffness.RA = v; },
          design.stiffness.RA.has_value()}});
  } else if (t.size() == 3 && t[0] == "frame" && t[1] == "cross_section") {
    const bool has = design.stiffness.shear_modulus_Pa.has_value();
    found = match(
        t[2],
        {{"shear_modulus_Pa", std::nullopt,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.stiffness.shear_modulus_Pa = v;
          },
          has},
         {"width", io::Dimension::kLength,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.stiffness.width_m = v; },
          has},
         {"thickness", io::Dimension::kLength,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.stiffness.thickness_m = v;
          },
          has}});
  } else if (t.size() == 2 && t[0] == "strings") {
    const bool bed = design.strings.has_value();
    found = match(
        t[1],
        {{"impact_duration", io::Dimension::kTime,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.impact_duration_s = v; },
          !bed},
         {"tension", io::Dimension::kForce,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.strings->tension_N = v; },
          bed},
         {"string_spacing", io::Dimension::kLength,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.strings->string_spacing_m = v;
          },
          bed},
         {"contact_radius", io::Dimension::kLength,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.strings->contact_radius_m = v;
          },
          bed}});
    // The reader's factors for a head size, as it writes them.
    if (!found && bed && d.head_area_m2 && (t[1] == "head_size_in2" || t[1] == "head_size_cm2")) {
      found = std::pair{
          t[1] == "head_size_in2" ? io::UnitScale{io::kSquareInch_m2, 0} : io::UnitScale{1e-4, -4},
          Setter{[](io::DesignDescription& x, std::size_t, double v) { x.head_area_m2 = v; }}};
    }
  } else if (t.size() == 2 && t[0] == "hand") {
    found = match(
        t[1],
        {{"mass", io::Dimension::kMass,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.hand.mass_kg = v; }, true},
         {"center_from_butt", io::Dimension::kLength,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.hand.center_from_butt_m = v;
          },
          true},
         {"grip_length", io::Dimension::kLength,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.hand.grip_length_m = v; },
          true},
         {"grip_stiffness", io::Dimension::kStiffness,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.hand.grip_stiffness_N_m2 = v;
          },
          true},
         {"grip_damping", io::Dimension::kDamping,
          [](io::DesignDescription& x, std::size_t, double v) {
            x.design.hand.grip_damping_N_s_m2 = v;
          },
          true}});
  } else if (t.size() == 2 && t[0] == "forearm") {
    found = match(t[1],
                  {{"equivalent_mass", io::Dimension::kMass,
                    [](io::DesignDescription& x, std::size_t, double v) {
                      x.design.forearm_equivalent_mass_kg = v;
                    },
                    !d.forearm_from_mass},
                   {"mass", io::Dimension::kMass,
                    [](io::DesignDescription& x, std::size_t, double v) { x.forearm_mass_kg = v; },
                    d.forearm_from_mass}});
  } else if (t.size() == 2 && t[0] == "ball") {
    found = match(
        t[1],
        {{"mass", io::Dimension::kMass,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.ball.mass_kg = v; }, true},
         {"speed", io::Dimension::kSpeed,
          [](io::DesignDescription& x, std::size_t, double v) { x.design.ball.speed_m_s = v; },
          true}});
  } else if (t.size() == 2 && t[0] == "impact") {
    // A file without an impact takes the one written at the pointer.
    found = match(t[1], {{"from_tip", io::Dimension::kLength,
                          [](io::DesignDescription& x, std::size_t, double v) {
                            x.impact_place = io::ImpactPlace::kFromTip;
                            x.impact_given = true;
                            x.impact_m = v;
                          },
                          d.impact_place == io::ImpactPlace::kFromTip || !d.impact_given},
                         {"from_butt", io::Dimension::kLength,
                          [](io::DesignDescription& x, std::size_t, double v) {
                            x.impact_place = io::ImpactPlace::kFromButt;
                            x.impact_given = true;
                            x.impact_m = v;
                          },
                          d.impact_place == io::ImpactPlace::kFromButt || !d.impact_given}});
  }
  if (!found) return std::nullopt;
  return FieldBinding{std::string(pointer), found->first, found->second, index, rebuilds};
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
      live_.design.implement = io::build_implement(live_.implement);
      implement_built_ = true;
    }
    io::derive(live_);
  } catch (const std::exception&) {
    return nullptr;
  }
  return &live_.design;
}

}  // namespace sweetspot::studies

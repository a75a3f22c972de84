#include "studies/rigid_columns.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "sweetspot/kernels.hpp"

namespace sweetspot::studies {
namespace {

using Form = io::ImplementDescription::Form;

constexpr std::array<std::string_view, 9> kOutputs = {
    "effective_mass_kg",   "apparent_cor",      "rebound_speed_m_s",  "impulse_N_s",
    "peak_impact_force_N", "wrist_force_ratio", "peak_wrist_force_N", "cor",
    "impact_duration_s"};

// The role of the field (object, stem) in a paper racquet's rigid case; -1: none.
int role_of(std::string_view object, std::string_view stem) {
  struct Row {
    std::string_view object, stem;
  };
  static constexpr Row kRows[] = {
      {"implement", "length"},
      {"implement", "mass"},
      {"implement", "head_to_handle_mass_ratio"},
      {"hand", "mass"},
      {"hand", "center_from_butt"},
      {"forearm", "equivalent_mass"},
      {"ball", "mass"},
      {"ball", "speed"},
      {"frame", "cor"},
      {"strings", "impact_duration"},
  };
  for (std::size_t k = 0; k < std::size(kRows); ++k) {
    if (kRows[k].object == object && kRows[k].stem == stem) return static_cast<int>(k);
  }
  if (object == "impact" && (stem == "from_tip" || stem == "from_butt")) return 10;
  return -1;
}

}  // namespace

std::span<const std::string_view> rigid_column_outputs() { return kOutputs; }

std::optional<RigidColumns> RigidColumns::compile(const CompiledDesign& compiled) {
  const io::DesignDescription& d = compiled.description();
  const Design& design = d.design;
  if (d.implement.form != Form::kHeadToHandleRatio || !d.implement.point_masses.empty() ||
      design.strings || design.cor_rigid || design.impact_off_axis_m != 0.0 || d.head_area_m2 ||
      design.swing || is_rig(design.support) ||
      d.impact_place == io::ImpactPlace::kCentreOfStrings) {
    return std::nullopt;
  }
  RigidColumns columns;
  columns.impact_from_tip_ = d.impact_place == io::ImpactPlace::kFromTip;
  const double base[kRoles] = {d.implement.length_m,
                               d.implement.mass_kg,
                               d.implement.head_to_handle_mass_ratio,
                               design.hand.mass_kg,
                               design.hand.center_from_butt_m,
                               design.forearm_equivalent_mass_kg,
                               design.ball.mass_kg,
                               design.ball.speed_m_s,
                               design.cor,
                               design.impact_duration_s,
                               d.impact_m};
  std::copy(std::begin(base), std::end(base), columns.base_);
  std::fill(std::begin(columns.column_), std::end(columns.column_), -1);
  const std::vector<FieldBinding>& bindings = compiled.bindings();
  for (std::size_t j = 0; j < bindings.size(); ++j) {
    const int role = role_of(bindings[j].object, bindings[j].stem);
    if (role < 0 || columns.column_[role] >= 0) return std::nullopt;
    if (role == static_cast<int>(Role::kImpact) &&
        (bindings[j].stem == "from_tip") != columns.impact_from_tip_) {
      return std::nullopt;
    }
    columns.column_[role] = static_cast<int>(j);
    columns.scale_[role] = bindings[j].scale;
  }
  return columns;
}

void RigidColumns::run(std::span<const ColumnView> columns, std::size_t from, std::size_t to,
                       std::span<const std::size_t> wanted, std::span<double* const> outputs,
                       std::span<unsigned char> answered) const {
  constexpr std::size_t kBlock = 512;
  // Each role's values for a block: the base's (filled once), a column read
  // in place (contiguous, in SI), or a column converted into the buffer.
  double buffer[kRoles][kBlock];
  const double* values[kRoles];
  for (std::size_t role = 0; role < kRoles; ++role) {
    if (column_[role] < 0) std::fill(buffer[role], buffer[role] + kBlock, base_[role]);
    values[role] = buffer[role];
  }
  double x[kBlock];
  double scratch[7][kBlock];
  for (std::size_t begin = from; begin < to; begin += kBlock) {
    const std::size_t n = std::min(kBlock, to - begin);
    for (std::size_t role = 0; role < kRoles; ++role) {
      if (column_[role] < 0) continue;
      const ColumnView& c = columns[static_cast<std::size_t>(column_[role])];
      const double* data = c.data + static_cast<std::ptrdiff_t>(begin) * c.stride;
      const io::UnitScale& scale = scale_[role];
      const bool si = scale.factor == 1.0 && scale.power_of_ten == 0;
      if (si && c.stride == 1) {
        values[role] = data;
        continue;
      }
      double* into = buffer[role];
      for (std::size_t i = 0; i < n; ++i) {
        const double given = data[static_cast<std::ptrdiff_t>(i) * c.stride];
        into[i] = si ? given : scale.to_si(given);
      }
      values[role] = into;
    }
    const double* L = values[static_cast<std::size_t>(Role::kLength)];
    const double* impact = values[static_cast<std::size_t>(Role::kImpact)];
    // The impact from the butt, as the reader places it (derive()): the
    // length is the sum of the two halves.
    for (std::size_t i = 0; i < n; ++i)
      x[i] = impact_from_tip_ ? (0.5 * L[i] + 0.5 * L[i]) - impact[i] : impact[i];
    // The kernel writes the outputs wanted in place, the others aside.
    double* kernel_out[7];
    for (std::size_t k = 0; k < 7; ++k) kernel_out[k] = scratch[k];
    static constexpr int kKernelSlot[] = {0, 1, -1, 2, 3, 5, 6, -1, -1};  // per output
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      if (const int slot = kKernelSlot[wanted[k]]; slot >= 0) kernel_out[slot] = outputs[k] + begin;
    }
    // A setting no column varies (none, or a scalar's) is one value for every
    // row, checked once.
    const auto in = [&](Role r) {
      const auto role = static_cast<std::size_t>(r);
      const bool constant =
          column_[role] < 0 || columns[static_cast<std::size_t>(column_[role])].stride == 0;
      const bool once = constant && r != Role::kLength && r != Role::kMass && r != Role::kRatio &&
                        r != Role::kImpact;
      return std::span<const double>(values[role], once ? 1 : n);
    };
    const auto out = [&](std::size_t slot) { return std::span<double>(kernel_out[slot], n); };
    unsigned char* ok = answered.data() + (begin - from);
    paper_rigid_outcomes(PaperRigidCases{in(Role::kLength),
                                         in(Role::kMass),
                                         in(Role::kRatio),
                                         in(Role::kHandMass),
                                         in(Role::kHandCenter),
                                         in(Role::kForearm),
                                         in(Role::kBallMass),
                                         in(Role::kBallSpeed),
                                         in(Role::kCor),
                                         in(Role::kDuration),
                                         {x, n}},
                         RigidOutcomes{out(0), out(1), out(2), out(3), out(4), out(5), out(6)},
                         std::span<unsigned char>(ok, n));
    // The reader refuses an impact given off the implement, whatever x is.
    if (impact_from_tip_) {
      const double* __restrict from_tip = impact;
      const double* __restrict length = L;
      unsigned char* __restrict answered_here = ok;  // a char may alias the columns otherwise
      for (std::size_t i = 0; i < n; ++i) {
        answered_here[i] = static_cast<unsigned char>(
            answered_here[i] & ((from_tip[i] >= 0.0) & (from_tip[i] <= length[i])));
      }
    }
    const double* speed = values[static_cast<std::size_t>(Role::kBallSpeed)];
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      double* target = outputs[k] + begin;
      switch (wanted[k]) {
        case 2:  // the rebound speed e_A v1, as evaluate() forms it
          for (std::size_t i = 0; i < n; ++i) target[i] = kernel_out[1][i] * speed[i];
          break;
        case 7:
          std::copy(values[static_cast<std::size_t>(Role::kCor)],
                    values[static_cast<std::size_t>(Role::kCor)] + n, target);
          break;
        case 8:
          std::copy(values[static_cast<std::size_t>(Role::kDuration)],
                    values[static_cast<std::size_t>(Role::kDuration)] + n, target);
          break;
        default:
          break;
      }
    }
  }
}

}  // namespace sweetspot::studies

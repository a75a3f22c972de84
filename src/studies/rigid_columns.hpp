#pragma once

// The rigid model of one design in the paper's parametrisation over columns
// of numbers, a block of rows at a time through the core's column-wise
// kernel (paper_rigid_outcomes(), kernels.hpp): what a million-row table of
// Table I racquets costs when no row needs the design rebuilt. A row the
// kernel cannot vouch for is left to the caller, who evaluates it as a
// design (and says why it is refused); every row it answers is, bit for bit,
// what evaluate() gives that design.

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "studies/design_binding.hpp"

namespace sweetspot::studies {

// Row i of a column at data[i * stride] (stride 0: one value for every row).
struct ColumnView {
  const double* data = nullptr;
  std::ptrdiff_t stride = 1;
};

// The outputs (io::output_specs() names) the column-wise path answers.
std::span<const std::string_view> rigid_column_outputs();

class RigidColumns {
 public:
  // The design's column-wise path, or std::nullopt unless: it is a racquet
  // in the paper's parametrisation (length, mass, head-to-handle ratio) with
  // no point masses, a given COR and impact duration (no string tension, no
  // cor_rigid), held by a player (no rig) and hit at rest (no swing: evaluate() solves a swung
  // racquet at the speed the ball and the racquet meet, which moves with the impact point), on
  // the long axis at a point given from the tip or the butt; and each binding sets one of its
  // numbers: the implement's length, mass or ratio, the hand's mass or centre, the forearm's
  // equivalent mass, the ball's mass or speed, the COR, the duration, the impact point.
  static std::optional<RigidColumns> compile(const CompiledDesign& design);

  // Rows [from, to) of `columns` (binding i's values in column i):
  // answered[i - from] = 1 and outputs[k][i] = output wanted[k] (an index
  // into rigid_column_outputs()) where the kernel answers row i; 0 where it
  // leaves the row to the caller, who writes that row's outputs (they hold
  // unspecified numbers until then).
  void run(std::span<const ColumnView> columns, std::size_t from, std::size_t to,
           std::span<const std::size_t> wanted, std::span<double* const> outputs,
           std::span<unsigned char> answered) const;

 private:
  enum class Role {
    kLength,
    kMass,
    kRatio,
    kHandMass,
    kHandCenter,
    kForearm,
    kBallMass,
    kBallSpeed,
    kCor,
    kDuration,
    kImpact,
  };
  static constexpr std::size_t kRoles = 11;
  RigidColumns() = default;

  double base_[kRoles] = {};     // the design's value of each role, in SI
  int column_[kRoles] = {};      // the column that sets it, -1: the base's
  io::UnitScale scale_[kRoles];  // its key's conversion to SI
  bool impact_from_tip_ = true;  // the impact value is from the tip (else the butt)
};

}  // namespace sweetspot::studies

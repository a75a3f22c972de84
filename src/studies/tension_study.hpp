#pragma once

// The solved collision (collision.hpp) of the typical racquet over string
// tension and frame stiffness, the string bed's mass and loss, and the
// frames that give Table I's COR: the numbers of
// reports/tension-and-stiffness.md (reports/tension_report.hpp writes them).

#include <optional>
#include <string>
#include <vector>

namespace sweetspot::studies {

// The racquet strung at `tension_N` with the free fundamental
// `fundamental_free_Hz`, its collision solved.
struct TensionPoint {
  double tension_N = 0.0;
  double fundamental_free_Hz = 0.0;
  double rebound_m_s = 0.0;
  double contact_s = 0.0;
  double vibration_J = 0.0;  // the energy the frame's modes keep
  double wrist_N = 0.0;
  double peak_N = 0.0;
  double compression_m = 0.0;
};

// The tension effect at one string-bed mass and damping ratio.
struct BedSensitivity {
  double mass_kg = 0.0;
  double damping_ratio = 0.0;
  TensionPoint at_180_N, at_280_N, at_250_N;  // f1 = 155 Hz
};

// The free fundamentals [Hz] in 50-1000 Hz at which the Table I racquet,
// strung at `tension_N`, has the COR 0.8 and 0.6 (none when no frame does).
struct Table1Frames {
  double tension_N = 0.0;
  std::optional<double> for_cor_08_Hz, for_cor_06_Hz;
};

struct TensionStudy {
  double ball_speed_m_s = 0.0;         // the typical racquet's ball
  std::vector<double> tensions_N;      // 180-300 N
  std::vector<double> frequencies_Hz;  // 100-200 Hz
  // Every tension at every frequency, frequency by frequency.
  std::vector<TensionPoint> grid;
  // 180 and 280 N at the racquet's own 155 Hz, beside published numbers.
  TensionPoint low, high;
  std::vector<BedSensitivity> bed;   // masses 1-8 g, damping ratios 0-0.02
  std::vector<Table1Frames> table1;  // at 180 and 250 N
};

// Reads `designs_dir`/racquets/tour-100.json and table1/row1.json and solves
// every point. Throws like io::load_design.
TensionStudy tension_study(const std::string& designs_dir);

}  // namespace sweetspot::studies

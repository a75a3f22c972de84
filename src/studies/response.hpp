#pragma once

// How the implement moves after the ball hits it (`sweetspot response`; Cross
// (2004) Figs. 3 and 4 free, 6 and 7 hand-held), the COR derived from the
// frame's stiffness and the impact duration from the string tension: the
// numbers of reports/response_report.hpp, computed.

#include <optional>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "sweetspot/impact_response.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::studies {

struct ResponseRequest {
  std::vector<double> points_from_butt_m{0.02, 0.16};  // where the velocity is observed
  std::vector<double> impacts_from_butt_m;             // empty: the design's impact point
  bool hand_held = false;
  double until_s = 0.02;  // the time window after the impact starts
  int samples = 401;      // times in [0, until_s]
};

struct ResponseData {
  io::DesignFile design;
  ResponseRequest request;
  std::vector<double> time_s;
  std::vector<double> peak_force_N;       // per impact (Eq. 15 with the design's COR and T)
  std::vector<double> duration_s;         // per impact
  std::vector<ImpactResponse> responses;  // per impact
};

// Throws InputError at the design's JSON path when it cannot give modes.
ResponseData compute_response(const io::DesignFile& design, const ResponseRequest& request);

// The paper's figures of the beam's motion (`designs_dir`/paper-beam.json):
// impacts every 6 cm from d = 4 cm, observed 2 and 16 cm from the handle end,
// T = 8 ms (Sec. IV), free at 1.2 m/s and hand-held at 3.2 m/s (Sec. II).
struct PaperBeamResponses {
  ResponseData free, hand_held;
};
PaperBeamResponses paper_beam_responses(const std::string& designs_dir);

// The derived COR of the Table I racquet (`designs_dir`/table1/row1.json, a
// flexible frame, hit 5 cm from the tip) against the free fundamental
// 80-300 Hz, at cor_rigid 0.85 and 0.90, and the fundamentals that give the
// paper's 0.8 (stiff) and 0.6 (flexible).
struct CorAtFundamental {
  double fundamental_free_Hz = 0.0;
  DerivedCor at_085, at_090;  // cor_rigid 0.85, 0.90
};
struct FundamentalsForCor {
  double cor_rigid = 0.0;
  std::optional<double> stiff_Hz, flexible_Hz;  // e = 0.8, e = 0.6 in 50-1000 Hz
};
struct CorFromStiffness {
  std::vector<CorAtFundamental> rows;
  std::vector<FundamentalsForCor> fundamentals;  // cor_rigid 0.85, 0.90
};
CorFromStiffness cor_from_stiffness(const std::string& designs_dir);

// The impact duration of the same racquet and ball from the string tension
// 50-400 N (Eq. 17, springs in series) and the tensions that give Table I's
// 4 and 6 ms.
struct DurationAtTension {
  double tension_N = 0.0;
  TensionDuration duration;
};
struct DurationFromTension {
  double effective_mass_kg = 0.0;  // at the impact point
  std::vector<DurationAtTension> rows;
  std::optional<double> tension_for_4_ms_N, tension_for_6_ms_N;
};
DurationFromTension duration_from_tension(const std::string& designs_dir);

// The three above, for reports/: the paper beam's motion, the derived COR and
// the duration from the tension.
struct ResponseReports {
  PaperBeamResponses beam;
  CorFromStiffness cor;
  DurationFromTension duration;
};
ResponseReports response_reports(const std::string& designs_dir);

}  // namespace sweetspot::studies

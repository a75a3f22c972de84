#pragma once

// `sweetspot tune`: how much lead, and where, brings a racquet to target
// specs (mass, balance, swingweight, twistweight), and `tune --match`: a set
// of racquets brought to common specs. Lead only adds mass, so every added
// mass is >= 0.
//
// With m_j >= 0 the lead at place j (x_j from the butt, y_jk its pieces' off
// the long axis), the racquet of mass M0, balance c0, swingweight SW0 and
// polar inertia P0 becomes, exactly (point masses, parallel-axis theorem):
//   mass         M0 + sum m_j                         = M*
//   balance      sum m_j (x_j - B*)                   = M0 (B* - c0)
//   swingweight  SW0 + sum m_j (x_j - 0.10 m)^2       = SW*
//   twistweight  P0 + sum m_j <y_j^2>                 = P*
// each linear in the m_j (the balance row for any B*). Solved in two exact
// phases (solve_lead()): the nearest reachable specs (non-negative least
// squares), then the least added lead that reaches them (a linear programme).
// Both enumerate the supports of the solution: with at most four equations
// an optimum has at most four places with lead, so every set of at most
// four independent columns is tried (Eigen's column-pivoting Householder QR
// for each), which is exact and fast for the few places a racquet offers.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/design_reader.hpp"
#include "io/json_reader.hpp"
#include "studies/comparison.hpp"

namespace sweetspot::studies {

// Lead under the grip, 9 cm from the butt (head_geometry.hpp).
using sweetspot::kUnderGripFromButt_m;
// A "strip" of lead tape: 1/4-inch tape about 4 inches (10 cm) long, 1 g.
// Standard 1/2-inch tape weighs 0.44-0.5 g per inch (8 in about 3.5 g; A.
// Vihn, "Lead tape and its application", tennis4you.com), so 1/4-inch tape
// about a quarter gram per inch. `--strip-g` gives another.
inline constexpr double kDefaultStrip_kg = 0.001;
// At most this many places in one tune (the support search grows as the
// number of sets of up to four places).
inline constexpr std::size_t kMaxLeadPlaces = 24;

// Where lead may go: a clock position on the hoop (one hour, or a pair
// such as 3/9 with half the lead at each), the throat (6 o'clock), under the
// grip ("grip", kUnderGripFromButt_m) or under the butt cap ("butt" or
// "handle", as the design file's clock "handle", kHandleWeightFromButt_m).
struct LeadPlace {
  enum class Kind { kClock, kThroat, kUnderGrip, kButtCap };
  Kind kind = Kind::kClock;
  std::vector<double> hours;  // kClock: one hour, or two (a pair); kThroat: 6
  std::string label;          // as the user wrote it: "12", "3/9", "throat", "grip", "butt"
};

// The places of a --places list ("12,3/9,grip"). Throws
// std::invalid_argument naming the item and what is expected for an empty
// item, an hour outside [0, 12], an unknown name, the same place twice or
// more than kMaxLeadPlaces places.
std::vector<LeadPlace> parse_lead_places(std::string_view text);

// The specs a customiser measures, in SI.
struct RacquetSpecs {
  double mass_kg = 0.0;
  double balance_from_butt_m = 0.0;
  double swingweight_kg_m2 = 0.0;           // about the axis 10 cm from the butt
  std::optional<double> twistweight_kg_m2;  // polar inertia about the long axis
  bool twistweight_estimated = false;       // from the head's size, not measured
};

// The specs of a design, point masses included (twistweight absent when the
// design gives neither head nor twistweight).
RacquetSpecs specs_of(const Design& design);

// What to reach: any of the four, in SI; at least one.
struct TuneTargets {
  std::optional<double> mass_kg;
  std::optional<double> balance_from_butt_m;
  // The balance in points head-light, as a spec sheet gives it: tune() puts it
  // from the butt with the design's own length (never both balances).
  std::optional<double> balance_pts_hl;
  std::optional<double> swingweight_kg_m2;
  std::optional<double> twistweight_kg_m2;
  bool has_balance() const { return balance_from_butt_m || balance_pts_hl; }
  bool empty() const {
    return !mass_kg && !has_balance() && !swingweight_kg_m2 && !twistweight_kg_m2;
  }
};

// A --target list ("mass_g=330,balance_cm=32,swingweight_kg_cm2=325"): each
// name a design file's spelling of implement mass, balance, swingweight or
// twistweight with its unit (mass_g, balance_cm, balance_pts_hl,
// swingweight_kg_cm2, twistweight_kg_cm2, ...), each value a finite number
// > 0 (points head-light any finite number: negative is head-heavy). Throws
// std::invalid_argument naming the item and what is expected.
TuneTargets parse_tune_targets(std::string_view text);

// The targets a racquet's own specs give (for "the specs of this other
// racquet"): its mass, balance and swingweight, and its twistweight when
// `with_twistweight` and it has one.
TuneTargets targets_from(const RacquetSpecs& specs, bool with_twistweight);

// The lead found for one place.
struct PlacedLead {
  LeadPlace place;
  double mass_kg = 0.0;           // in all at the place (a pair: half at each hour)
  std::vector<PointMass> pieces;  // where it sits, each piece's mass_kg (of 1 kg in all)
};

// Why a target is missed.
struct TargetMiss {
  std::string spec;    // "mass", "balance", "swingweight", "twistweight"
  std::string reason;  // a sentence
};

// The answer of tune().
struct TuneResult {
  RacquetSpecs before;
  RacquetSpecs reached;
  TuneTargets targets;
  std::vector<PlacedLead> lead;  // one per place, in the order given
  double added_kg = 0.0;
  bool exact = false;              // every target reached (to 1 mg, 0.01 mm, 0.001 kg cm^2)
  std::vector<TargetMiss> misses;  // when !exact: why
};

// The least lead at `places` on `design` that reaches `targets` or, when no
// lead there can, the least that reaches the nearest specs it can: nearest in
// the units a customiser measures, one gram of mass, one millimetre of
// balance and one kg cm^2 of swingweight or twistweight weighed alike.
// Throws std::invalid_argument naming "--target" or "--places" for targets
// the design cannot take (a twistweight without head or measured
// twistweight; a clock place without a head; no target).
TuneResult tune(const io::DesignFile& design, const TuneTargets& targets,
                const std::vector<LeadPlace>& places);

// The design file of the tuned racquet: `document` (the design as read) with
// each place's lead appended to implement.point_masses in grams (a pair as
// {"clock": [3, 9]} with each piece's mass; the throat "throat"; the butt cap
// "handle"; under the grip from_butt_cm) and " (tuned)" added to its name.
io::Json tuned_document(const io::Json& document, const TuneResult& result);

// The racquet before and after a tune, each evaluated at its file's own
// fidelity (compare_one()): the tuned one read from `tuned` (its design file,
// tuned_document()) under the name `tuned_name`.
struct TuneEvaluations {
  ComparedDesign before, after;
};
TuneEvaluations evaluate_tune(const io::DesignFile& original, const io::Json& tuned,
                              const std::string& tuned_name, double rel_tol);

// The least-lead solution of A m = b, m >= 0 (rows the equations, columns
// the places), or of the nearest reachable b' = A m (least squares of the
// rows scaled by `row_scale`); `cost` per column (1 for lead). At most four
// rows; exact (support enumeration, above).
struct LeadSolution {
  std::vector<double> m;
  double scaled_residual = 0.0;  // |row_scale (A m - b)| at the nearest
};
LeadSolution solve_lead(const std::vector<std::vector<double>>& A, const std::vector<double>& b,
                        const std::vector<double>& row_scale, const std::vector<double>& cost);

// `tune --match`: the common specs (mass, balance, swingweight) that every
// racquet of `designs` reaches with lead at `places` with the least lead in
// all, which is the least common mass (lead only adds mass); each racquet's
// tune to them. Throws like tune(); std::invalid_argument naming "--match"
// for fewer than two designs.
struct MatchResult {
  TuneTargets common;
  std::vector<TuneResult> tuned;
};
MatchResult match(const std::vector<io::DesignFile>& designs, const std::vector<LeadPlace>& places);

}  // namespace sweetspot::studies

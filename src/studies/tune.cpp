#include "studies/tune.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "io/design_description.hpp"
#include "io/design_fields.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/mass_properties.hpp"

namespace sweetspot::studies {
namespace {

// What "reached" means, per spec, in SI: 1 mg, 0.01 mm, 0.001 kg cm^2.
constexpr double kMassTolerance_kg = 1e-6;
constexpr double kBalanceTolerance_m = 1e-5;
constexpr double kInertiaTolerance_kg_m2 = 1e-7;
// Nearest in a customiser's units: 1 g, 1 mm, 1 kg cm^2 weigh alike.
constexpr double kMassUnit_kg = 1e-3;
constexpr double kBalanceUnit_m = 1e-3;
constexpr double kInertiaUnit_kg_m2 = 1e-4;
// The support search tries at most this many sets of columns (four racquets
// with four places each, 450 000 sets, take a few seconds).
constexpr std::size_t kMaxSupports = 600'000;

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> items;
  for (std::size_t start = 0;;) {
    const std::size_t at = text.find(separator, start);
    items.push_back(text.substr(start, at == std::string_view::npos ? at : at - start));
    if (at == std::string_view::npos) return items;
    start = at + 1;
  }
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::optional<double> finite_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// Every subset of {0..n-1} of size <= k, in order of size, through `visit`.
template <typename Visit>
void for_each_support(std::size_t n, std::size_t k, Visit visit) {
  std::vector<std::size_t> s;
  for (std::size_t size = 0; size <= std::min(n, k); ++size) {
    s.resize(size);
    for (std::size_t i = 0; i < size; ++i) s[i] = i;
    for (;;) {
      visit(s);
      std::size_t i = size;
      while (i > 0 && s[i - 1] == n - size + i - 1) --i;
      if (i == 0) break;
      ++s[i - 1];
      for (std::size_t j = i; j < size; ++j) s[j] = s[j - 1] + 1;
    }
  }
}

double binomial_sum(std::size_t n, std::size_t k) {
  double total = 0.0, term = 1.0;
  for (std::size_t s = 0; s <= std::min(n, k); ++s) {
    total += term;
    term = term * static_cast<double>(n - s) / static_cast<double>(s + 1);
  }
  return total;
}

// The least-squares solution on the columns `support` of the scaled system,
// or nullopt when those columns are dependent.
std::optional<Eigen::VectorXd> solve_on(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                        const std::vector<std::size_t>& support) {
  Eigen::MatrixXd As(A.rows(), static_cast<Eigen::Index>(support.size()));
  for (std::size_t j = 0; j < support.size(); ++j)
    As.col(static_cast<Eigen::Index>(j)) = A.col(static_cast<Eigen::Index>(support[j]));
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(As);
  qr.setThreshold(1e-10);
  if (qr.rank() < As.cols()) return std::nullopt;
  return Eigen::VectorXd(qr.solve(b));
}

}  // namespace

std::vector<LeadPlace> parse_lead_places(std::string_view text) {
  std::vector<LeadPlace> places;
  std::size_t item = 0;
  for (std::string_view raw : split(text, ',')) {
    ++item;
    const std::string_view word = trimmed(raw);
    LeadPlace place;
    place.label = std::string(word);
    if (word.empty()) {
      throw std::invalid_argument(fmt::format(
          "an empty place (item {}; expected clock hours such as 12 or 3/9, throat, grip, "
          "butt or handle, separated by commas)",
          item));
    } else if (word == "throat") {
      place.kind = LeadPlace::Kind::kThroat;
      place.hours = {6.0};  // the same place as 6 o'clock
    } else if (word == "grip") {
      place.kind = LeadPlace::Kind::kUnderGrip;
    } else if (word == "butt" || word == "handle") {
      // One word, one place: "handle" is the butt cap, as in a design file's clock.
      place.kind = LeadPlace::Kind::kButtCap;
    } else {
      const std::vector<std::string_view> hours = split(word, '/');
      for (std::string_view h : hours) {
        const std::optional<double> hour = finite_number(trimmed(h));
        if (!hour || hours.size() > 2 || *hour < 0.0 || *hour > 12.0) {
          throw std::invalid_argument(fmt::format(
              "item {} \"{}\" is not a place (expected an hour in [0, 12] such as 12 or 10.5, a "
              "pair of hours such as 3/9, throat, grip, butt or handle)",
              item, io::one_line(word)));
        }
        place.hours.push_back(*hour == 0.0 ? 12.0 : *hour);
      }
      if (place.hours.size() == 2 && place.hours[0] == place.hours[1]) {
        throw std::invalid_argument(
            fmt::format("item {} \"{}\" is a pair of one hour (give it once: {})", item,
                        io::one_line(word), io::one_line(trimmed(hours[0]))));
      }
    }
    for (const LeadPlace& other : places) {
      std::vector<double> a = other.hours, b = place.hours;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      // The throat is 6 o'clock: one place by either name.
      const auto on_hoop = [](LeadPlace::Kind k) {
        return k == LeadPlace::Kind::kClock || k == LeadPlace::Kind::kThroat;
      };
      if ((other.kind == place.kind || (on_hoop(other.kind) && on_hoop(place.kind))) && a == b) {
        throw std::invalid_argument(
            fmt::format("item {} \"{}\" is the same place as \"{}\" (give each place once)", item,
                        io::one_line(word), other.label));
      }
    }
    places.push_back(std::move(place));
  }
  if (places.size() > kMaxLeadPlaces) {
    throw std::invalid_argument(fmt::format("{} places, at most {} (expected a few places)",
                                            places.size(), kMaxLeadPlaces));
  }
  return places;
}

RacquetSpecs specs_of(const Design& design) {
  // A ball onto a rigid plate has no implement: the Table I racquet the
  // design carries stands in for none, so it has no specs to reach or take.
  if (design.support.kind == Support::Kind::kRigidSurface)
    throw FieldError("support", "a rigid surface has no implement, so no specs to tune");
  const MassProperties& body = design.implement.mass_properties();
  RacquetSpecs specs;
  specs.mass_kg = body.mass_kg;
  specs.balance_from_butt_m = body.com_from_butt_m;
  specs.swingweight_kg_m2 = swingweight_kg_m2(body);
  specs.twistweight_kg_m2 = polar_inertia_kg_m2(design);
  specs.twistweight_estimated = specs.twistweight_kg_m2 && polar_inertia_estimated(design);
  return specs;
}

TuneTargets parse_tune_targets(std::string_view text) {
  TuneTargets targets;
  std::size_t item = 0;
  const char* expected =
      "expected NAME=VALUE with a name such as mass_g, balance_cm, balance_pts_hl, "
      "swingweight_kg_cm2 or twistweight_kg_cm2";
  for (std::string_view raw : split(text, ',')) {
    ++item;
    const std::string_view piece = trimmed(raw);
    const std::size_t equals = piece.find('=');
    if (equals == std::string_view::npos) {
      throw std::invalid_argument(
          fmt::format("item {} \"{}\": {}", item, io::one_line(piece), expected));
    }
    const std::string name(trimmed(piece.substr(0, equals)));
    const std::string_view value_text = trimmed(piece.substr(equals + 1));
    const std::optional<io::FieldSpelling> spelling = io::find_spelling("implement", name);
    const std::string_view stem = spelling ? spelling->field->stem : std::string_view();
    if (!spelling ||
        (stem != "mass" && stem != "balance" && stem != "swingweight" && stem != "twistweight")) {
      throw std::invalid_argument(
          fmt::format("item {}: unknown target \"{}\" ({})", item, io::one_line(name), expected));
    }
    // Points head-light may be negative (head-heavy); every other target is > 0.
    const bool points = name == "balance_pts_hl";
    const std::optional<double> value = finite_number(value_text);
    if (!value || !(points || *value > 0.0)) {
      throw std::invalid_argument(fmt::format(
          "item {}: {} must be a finite number{}, got {}", item, name, points ? "" : " > 0",
          value_text.empty() ? std::string("nothing") : io::one_line(value_text)));
    }
    std::optional<double>& slot = stem == "mass"          ? targets.mass_kg
                                  : points                ? targets.balance_pts_hl
                                  : stem == "balance"     ? targets.balance_from_butt_m
                                  : stem == "swingweight" ? targets.swingweight_kg_m2
                                                          : targets.twistweight_kg_m2;
    if (slot || (stem == "balance" && targets.has_balance())) {
      throw std::invalid_argument(
          fmt::format("item {}: the {} is given twice (give each target once)", item, stem));
    }
    slot = spelling->scale.to_si(*value);
    // A mass no design file holds is no target: lead cannot be written for it.
    if (stem == "mass" && !(*slot <= kMaxMass_kg)) {
      const double per_unit = spelling->scale.to_si(1.0);
      throw std::invalid_argument(fmt::format(
          "item {}: {} must be at most {} {} ({} kg, the most an implement may weigh), got {}",
          item, name, io::significant(kMaxMass_kg / per_unit, 4), io::unit_of_key(name),
          io::significant(kMaxMass_kg, 4), io::one_line(value_text)));
    }
  }
  return targets;
}

TuneTargets targets_from(const RacquetSpecs& specs, bool with_twistweight) {
  TuneTargets t;
  t.mass_kg = specs.mass_kg;
  t.balance_from_butt_m = specs.balance_from_butt_m;
  t.swingweight_kg_m2 = specs.swingweight_kg_m2;
  if (with_twistweight) t.twistweight_kg_m2 = specs.twistweight_kg_m2;
  return t;
}

namespace {

// Where a kilogram of lead at `place` sits on `design`.
std::vector<PointMass> unit_pieces(const io::DesignFile& file, const LeadPlace& place) {
  const Design& d = file.design;
  const double L = d.implement.length_m();
  switch (place.kind) {
    case LeadPlace::Kind::kUnderGrip:
    case LeadPlace::Kind::kButtCap: {
      const double x = place.kind == LeadPlace::Kind::kUnderGrip ? kUnderGripFromButt_m
                                                                 : kHandleWeightFromButt_m;
      if (!(x <= L)) {
        throw std::invalid_argument(fmt::format(
            "--places: \"{}\" is {} cm from the butt, beyond the {} cm of {}", place.label,
            io::significant(x * 100.0, 4), io::significant(L * 100.0, 4), file.source));
      }
      return {PointMass{x, 1.0, 0.0}};
    }
    case LeadPlace::Kind::kThroat:
    case LeadPlace::Kind::kClock: {
      if (is_round(d)) {
        throw std::invalid_argument(fmt::format(
            "--places: \"{}\" is on a racquet's hoop, and {} is round (given by its profile, "
            "a bat): give grip or butt (the knob)",
            place.label, io::one_line(file.source)));
      }
      if (!d.head) {
        throw std::invalid_argument(
            fmt::format("--places: \"{}\" is on the hoop, which needs the head "
                        "(implement.headsize_sq_in in {})",
                        place.label, io::one_line(file.source)));
      }
      const std::vector<double> hours =
          place.kind == LeadPlace::Kind::kThroat ? std::vector<double>{6.0} : place.hours;
      std::vector<PointMass> pieces;
      for (double h : hours) {
        const FacePoint p = clock_position(*d.head, L, h);
        pieces.push_back(
            PointMass{p.from_butt_m, 1.0 / static_cast<double>(hours.size()), p.off_axis_m});
      }
      return pieces;
    }
  }
  return {};
}

// Each place's column: its mass, first moment about the butt, inertia about
// the swingweight axis and about the long axis per kilogram.
struct PlaceColumn {
  double mass = 1.0, x = 0.0, sw = 0.0, polar = 0.0;
};

PlaceColumn column_of(const std::vector<PointMass>& pieces) {
  PlaceColumn c;
  for (const PointMass& p : pieces) {
    const double arm = p.from_butt_m - kSwingweightAxisFromButt_m;
    c.x += p.mass_kg * p.from_butt_m;
    c.sw += p.mass_kg * arm * arm;
    c.polar += p.mass_kg * p.off_axis_m * p.off_axis_m;
  }
  return c;
}

RacquetSpecs specs_after(const RacquetSpecs& before, const std::vector<PlaceColumn>& columns,
                         const std::vector<double>& m) {
  RacquetSpecs after = before;
  double moment = before.mass_kg * before.balance_from_butt_m;
  for (std::size_t j = 0; j < columns.size(); ++j) {
    after.mass_kg += m[j];
    moment += m[j] * columns[j].x;
    after.swingweight_kg_m2 += m[j] * columns[j].sw;
    if (after.twistweight_kg_m2) *after.twistweight_kg_m2 += m[j] * columns[j].polar;
  }
  after.balance_from_butt_m = moment / after.mass_kg;
  return after;
}

std::string grams(double kg) { return fmt::format("{:.1f} g", kg * 1e3); }
std::string centimetres(double m) { return fmt::format("{:.1f} cm", m * 1e2); }
std::string kg_cm2(double kg_m2) { return fmt::format("{:.1f} kg·cm²", kg_m2 * 1e4); }

// Why each missed target is missed: lead only adds mass and inertia, and
// moves the balance only towards the places.
std::vector<TargetMiss> explain_misses(const TuneResult& r, const std::vector<PlaceColumn>& cols,
                                       const std::vector<LeadPlace>& places) {
  std::vector<TargetMiss> misses;
  const TuneTargets& t = r.targets;
  const auto missed = [](const std::optional<double>& target, double reached, double tol) {
    return target && std::abs(*target - reached) > tol;
  };
  if (missed(t.mass_kg, r.reached.mass_kg, kMassTolerance_kg)) {
    misses.push_back({"mass", *t.mass_kg < r.before.mass_kg
                                  ? fmt::format("lead only adds mass: the racquet weighs {} "
                                                "already, more than the {} asked",
                                                grams(r.before.mass_kg), grams(*t.mass_kg))
                                  : fmt::format("{} asked, {} reached", grams(*t.mass_kg),
                                                grams(r.reached.mass_kg))});
  }
  // A mass and a balance fix the lead's mass dM and its centre xl; wherever
  // it sits it adds at least dM (xl - 0.10 m)^2 to the swingweight (the
  // parallel-axis theorem, its own inertia about its centre >= 0).
  bool swingweight_said = false;
  if (t.mass_kg && t.balance_from_butt_m && t.swingweight_kg_m2 && *t.mass_kg > r.before.mass_kg &&
      *t.swingweight_kg_m2 >= r.before.swingweight_kg_m2) {
    const double dM = *t.mass_kg - r.before.mass_kg;
    const double xl =
        (*t.mass_kg * *t.balance_from_butt_m - r.before.mass_kg * r.before.balance_from_butt_m) /
        dM;
    const double least_sw =
        dM * (xl - kSwingweightAxisFromButt_m) * (xl - kSwingweightAxisFromButt_m);
    if (*t.swingweight_kg_m2 < r.before.swingweight_kg_m2 + least_sw - kInertiaTolerance_kg_m2) {
      swingweight_said = true;
      misses.push_back(
          {"swingweight",
           fmt::format("the mass and balance asked for need {} of lead centred {} from the "
                       "butt, which adds at least {} to the swingweight wherever it sits: "
                       "with that mass and balance the swingweight cannot be below {}",
                       grams(dM), centimetres(xl), kg_cm2(least_sw),
                       kg_cm2(r.before.swingweight_kg_m2 + least_sw))});
    }
  }
  if (!swingweight_said &&
      missed(t.swingweight_kg_m2, r.reached.swingweight_kg_m2, kInertiaTolerance_kg_m2)) {
    misses.push_back(
        {"swingweight",
         *t.swingweight_kg_m2 < r.before.swingweight_kg_m2
             ? fmt::format("lead only adds swingweight: the racquet has {} "
                           "already, more than the {} asked",
                           kg_cm2(r.before.swingweight_kg_m2), kg_cm2(*t.swingweight_kg_m2))
             : fmt::format("{} asked, {} reached", kg_cm2(*t.swingweight_kg_m2),
                           kg_cm2(r.reached.swingweight_kg_m2))});
  }
  if (r.reached.twistweight_kg_m2 &&
      missed(t.twistweight_kg_m2, *r.reached.twistweight_kg_m2, kInertiaTolerance_kg_m2)) {
    const double before = *r.before.twistweight_kg_m2;
    misses.push_back(
        {"twistweight",
         *t.twistweight_kg_m2 < before
             ? fmt::format("lead only adds twistweight: the racquet has {} already, more than "
                           "the {} asked",
                           kg_cm2(before), kg_cm2(*t.twistweight_kg_m2))
             : fmt::format("{} asked, {} reached (only lead off the long axis, at 3 and 9 "
                           "o'clock or between, adds twistweight)",
                           kg_cm2(*t.twistweight_kg_m2), kg_cm2(*r.reached.twistweight_kg_m2))});
  }
  if (missed(t.balance_from_butt_m, r.reached.balance_from_butt_m, kBalanceTolerance_m)) {
    const double B = *t.balance_from_butt_m, c0 = r.before.balance_from_butt_m;
    std::size_t lo = 0, hi = 0;
    for (std::size_t j = 1; j < cols.size(); ++j) {
      if (cols[j].x < cols[lo].x) lo = j;
      if (cols[j].x > cols[hi].x) hi = j;
    }
    std::string reason;
    if (cols.empty() || (B > c0 && B >= cols[hi].x) || (B < c0 && B <= cols[lo].x)) {
      const std::size_t far = B > c0 ? hi : lo;
      reason = cols.empty() ? "no place to put lead"
                            : fmt::format(
                                  "lead moves the balance only towards where it sits, and "
                                  "the place farthest {} ({}) is {} from the butt",
                                  B > c0 ? "towards the tip" : "towards the butt",
                                  places[far].label, centimetres(cols[far].x));
    } else {
      reason = fmt::format("{} asked, {} reached", centimetres(B),
                           centimetres(r.reached.balance_from_butt_m));
    }
    misses.push_back({"balance", reason});
  }
  if (misses.size() >= 2) {
    bool each_alone = true;
    for (const TargetMiss& miss : misses) {
      each_alone = each_alone && miss.reason.find(" asked, ") != std::string::npos;
    }
    if (each_alone) {
      misses.push_back({"together",
                        "lead at these places cannot meet these targets together: another "
                        "place, or one target fewer, would be needed"});
    }
  }
  return misses;
}

}  // namespace

LeadSolution solve_lead(const std::vector<std::vector<double>>& A_rows,
                        const std::vector<double>& b_in, const std::vector<double>& row_scale,
                        const std::vector<double>& cost) {
  const std::size_t rows = A_rows.size(), cols = cost.size();
  if (binomial_sum(cols, rows) > static_cast<double>(kMaxSupports)) {
    throw std::invalid_argument(fmt::format(
        "--places: {} unknowns in {} equations are too many for the exact search (give fewer "
        "places or racquets)",
        cols, rows));
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  Eigen::VectorXd b(static_cast<Eigen::Index>(rows));
  for (std::size_t i = 0; i < rows; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    for (std::size_t j = 0; j < cols; ++j)
      A(r, static_cast<Eigen::Index>(j)) = row_scale[i] * A_rows[i][j];
    b(r) = row_scale[i] * b_in[i];
  }
  // The scale of a negligible entry: a column's values below this are round-off.
  const double tiny = 1e-12 * (1.0 + b.lpNorm<Eigen::Infinity>());
  const auto full = [&](const std::vector<std::size_t>& s, const Eigen::VectorXd& z) {
    Eigen::VectorXd m = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(cols));
    for (std::size_t j = 0; j < s.size(); ++j)
      m(static_cast<Eigen::Index>(s[j])) = std::max(0.0, z(static_cast<Eigen::Index>(j)));
    return m;
  };
  // Phase 1, the nearest reachable b' (non-negative least squares): the
  // optimum's support has independent columns and its entries are the
  // unconstrained least squares on them.
  double best = (b).norm();
  Eigen::VectorXd nearest = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(cols));
  for_each_support(cols, rows, [&](const std::vector<std::size_t>& s) {
    if (s.empty()) return;
    const std::optional<Eigen::VectorXd> z = solve_on(A, b, s);
    if (!z || z->minCoeff() < -tiny * 1e3) return;
    const Eigen::VectorXd m = full(s, *z);
    const double residual = (A * m - b).norm();
    if (residual < best) {
      best = residual;
      nearest = m;
    }
  });
  // Phase 2, the least cost reaching b' exactly (a linear programme): its
  // optimum is a basic feasible solution, the exact solution on some set of
  // independent columns.
  const Eigen::VectorXd reached = A * nearest;
  const double exact_tol = 1e-9 * (1.0 + reached.norm());
  double least = std::numeric_limits<double>::infinity();
  Eigen::VectorXd answer = nearest;
  for_each_support(cols, rows, [&](const std::vector<std::size_t>& s) {
    Eigen::VectorXd z;
    if (!s.empty()) {
      const std::optional<Eigen::VectorXd> solved = solve_on(A, reached, s);
      if (!solved || solved->minCoeff() < -tiny * 1e3) return;
      z = *solved;
    }
    const Eigen::VectorXd m = full(s, z);
    if ((A * m - reached).norm() > exact_tol) return;
    double c = 0.0;
    for (std::size_t j = 0; j < cols; ++j) c += cost[j] * m(static_cast<Eigen::Index>(j));
    if (c < least) {
      least = c;
      answer = m;
    }
  });
  // Round-off left on a place without lead (1e-17 kg) is no lead.
  for (Eigen::Index j = 0; j < answer.size(); ++j) {
    if (answer(j) < 1e-12 * (1.0 + answer.lpNorm<Eigen::Infinity>())) answer(j) = 0.0;
  }
  LeadSolution out;
  out.m.assign(answer.data(), answer.data() + answer.size());
  out.scaled_residual = (A * answer - b).norm();
  return out;
}

namespace {

struct TuneSystem {
  std::vector<std::vector<double>> A;
  std::vector<double> b, scale;
};

// The rows of the targets given, for a racquet with `before` and `cols`.
TuneSystem tune_system(const RacquetSpecs& before, const TuneTargets& t,
                       const std::vector<PlaceColumn>& cols) {
  TuneSystem s;
  const auto row = [&](auto coefficient, double rhs, double scale) {
    std::vector<double> r;
    for (const PlaceColumn& c : cols) r.push_back(coefficient(c));
    s.A.push_back(std::move(r));
    s.b.push_back(rhs);
    s.scale.push_back(scale);
  };
  const double mass_ref = t.mass_kg ? std::max(*t.mass_kg, before.mass_kg) : before.mass_kg;
  if (t.mass_kg)
    row([](const PlaceColumn& c) { return c.mass; }, *t.mass_kg - before.mass_kg,
        1.0 / kMassUnit_kg);
  if (t.balance_from_butt_m) {
    const double B = *t.balance_from_butt_m;
    // (the first moment's miss is the mass times the balance's)
    row([B](const PlaceColumn& c) { return c.x - B; },
        before.mass_kg * (B - before.balance_from_butt_m), 1.0 / (mass_ref * kBalanceUnit_m));
  }
  if (t.swingweight_kg_m2)
    row([](const PlaceColumn& c) { return c.sw; }, *t.swingweight_kg_m2 - before.swingweight_kg_m2,
        1.0 / kInertiaUnit_kg_m2);
  if (t.twistweight_kg_m2)
    row([](const PlaceColumn& c) { return c.polar; },
        *t.twistweight_kg_m2 - *before.twistweight_kg_m2, 1.0 / kInertiaUnit_kg_m2);
  return s;
}

struct PlacedColumns {
  std::vector<std::vector<PointMass>> pieces;
  std::vector<PlaceColumn> cols;
};

PlacedColumns place_all(const io::DesignFile& design, const std::vector<LeadPlace>& places) {
  PlacedColumns p;
  for (const LeadPlace& place : places) {
    p.pieces.push_back(unit_pieces(design, place));
    p.cols.push_back(column_of(p.pieces.back()));
  }
  return p;
}

TuneResult result_of(const io::DesignFile& design, const TuneTargets& targets,
                     const std::vector<LeadPlace>& places, const PlacedColumns& placed,
                     const std::vector<double>& m) {
  TuneResult r;
  r.before = specs_of(design.design);
  r.targets = targets;
  for (std::size_t j = 0; j < places.size(); ++j) {
    PlacedLead lead{places[j], m[j], placed.pieces[j]};
    for (PointMass& piece : lead.pieces) piece.mass_kg *= m[j];
    r.lead.push_back(std::move(lead));
    r.added_kg += m[j];
  }
  r.reached = specs_after(r.before, placed.cols, m);
  r.misses = explain_misses(r, placed.cols, places);
  r.exact = r.misses.empty();
  return r;
}

void check_targets(const io::DesignFile& design, const TuneTargets& targets,
                   const std::vector<LeadPlace>& places) {
  if (targets.empty()) throw std::invalid_argument("--target: give at least one target");
  if (places.empty()) throw std::invalid_argument("--places: give at least one place");
  if (targets.twistweight_kg_m2 && !polar_inertia_kg_m2(design.design)) {
    throw std::invalid_argument(
        fmt::format("--target: a twistweight needs the racquet's head or measured twistweight "
                    "(implement.headsize_sq_in or twistweight_kg_cm2 in {})",
                    io::one_line(design.source)));
  }
}

}  // namespace

TuneResult tune(const io::DesignFile& design, const TuneTargets& given,
                const std::vector<LeadPlace>& places) {
  TuneTargets targets = given;
  if (targets.balance_pts_hl) {
    // From the butt with this racquet's length (lead does not change it).
    const double L = design.design.implement.length_m();
    const double points = *std::exchange(targets.balance_pts_hl, std::nullopt);
    const double limit = io::points_head_light_limit(L);
    if (!(std::fabs(points) < limit)) {
      throw std::invalid_argument(fmt::format(
          "--target: balance_pts_hl must put the balance inside the length ({} cm), "
          "|points| < {}, got {}",
          io::significant(L * 100.0, 4), io::significant(limit, 4), io::significant(points, 6)));
    }
    targets.balance_from_butt_m = io::balance_from_points_head_light(L, points);
  }
  if (const double L = design.design.implement.length_m();
      targets.balance_from_butt_m && !(*targets.balance_from_butt_m <= L)) {
    throw std::invalid_argument(fmt::format(
        "--target: the balance must lie on the racquet, at most its length ({} cm) "
        "from the butt, got {} cm",
        io::significant(L * 100.0, 4), io::significant(*targets.balance_from_butt_m * 100.0, 6)));
  }
  check_targets(design, targets, places);
  const PlacedColumns placed = place_all(design, places);
  const RacquetSpecs before = specs_of(design.design);
  const TuneSystem system = tune_system(before, targets, placed.cols);
  const LeadSolution solution =
      solve_lead(system.A, system.b, system.scale, std::vector<double>(places.size(), 1.0));
  TuneResult result = result_of(design, targets, places, placed, solution.m);
  // A design holds at most kMaxMass_kg at a point: targets that would take
  // more lead are out of any racquet's reach, and said so by the option.
  for (const PlacedLead& lead : result.lead) {
    const double piece_kg = lead.mass_kg / static_cast<double>(lead.pieces.size());
    if (!(piece_kg <= kMaxMass_kg)) {
      throw std::invalid_argument(fmt::format(
          "--target: these specs would take {} g of lead at {}, more than the {} g a design may "
          "hold at a point",
          io::significant(lead.mass_kg * 1e3, 3), lead.place.label,
          io::significant(kMaxMass_kg * 1e3, 3)));
    }
  }
  return result;
}

io::Json tuned_document(const io::Json& document, const TuneResult& result) {
  io::Json out = document;
  io::Json& implement = out["implement"];
  io::Json list =
      implement.contains("point_masses") ? implement["point_masses"] : io::Json::array();
  for (const PlacedLead& lead : result.lead) {
    if (!(lead.mass_kg > 0.0)) continue;
    const double each_g = lead.mass_kg * 1e3 / static_cast<double>(lead.pieces.size());
    io::Json entry = {{"mass_g", each_g}};
    switch (lead.place.kind) {
      case LeadPlace::Kind::kThroat:
        entry["clock"] = "throat";
        break;
      case LeadPlace::Kind::kButtCap:
        entry["clock"] = "handle";
        break;
      case LeadPlace::Kind::kUnderGrip:
        entry["clock"] = "grip";
        break;
      case LeadPlace::Kind::kClock:
        if (lead.place.hours.size() == 1)
          entry["clock"] = lead.place.hours[0];
        else
          entry["clock"] = lead.place.hours;
        break;
    }
    list.push_back(std::move(entry));
  }
  implement["point_masses"] = std::move(list);
  const std::string name = document.contains("name") && document["name"].is_string()
                               ? document["name"].get<std::string>()
                               : std::string("Racquet");
  out["name"] = name + " (tuned)";
  return out;
}

MatchResult match(const std::vector<io::DesignFile>& designs,
                  const std::vector<LeadPlace>& places) {
  if (designs.size() < 2) throw std::invalid_argument("--match: give two racquets or more");
  if (places.empty()) throw std::invalid_argument("--places: give at least one place");
  // Unknowns: each racquet's lead, then the common mass, first moment and
  // swingweight (all >= 0). Three rows per racquet.
  std::vector<PlacedColumns> placed;
  std::vector<RacquetSpecs> before;
  for (const io::DesignFile& d : designs) {
    placed.push_back(place_all(d, places));
    before.push_back(specs_of(d.design));
  }
  const std::size_t n = places.size(), R = designs.size(), cols = n * R + 3;
  double mass_ref = 0.0;
  for (const RacquetSpecs& s : before) mass_ref = std::max(mass_ref, s.mass_kg);
  std::vector<std::vector<double>> A;
  std::vector<double> b, scale;
  for (std::size_t i = 0; i < R; ++i) {
    std::vector<double> mass(cols, 0.0), moment(cols, 0.0), sw(cols, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      mass[i * n + j] = 1.0;
      moment[i * n + j] = placed[i].cols[j].x;
      sw[i * n + j] = placed[i].cols[j].sw;
    }
    mass[n * R] = moment[n * R + 1] = sw[n * R + 2] = -1.0;
    A.push_back(mass);
    A.push_back(moment);
    A.push_back(sw);
    b.push_back(-before[i].mass_kg);
    b.push_back(-before[i].mass_kg * before[i].balance_from_butt_m);
    b.push_back(-before[i].swingweight_kg_m2);
    scale.push_back(1.0 / kMassUnit_kg);
    scale.push_back(1.0 / (mass_ref * kBalanceUnit_m));
    scale.push_back(1.0 / kInertiaUnit_kg_m2);
  }
  std::vector<double> cost(cols, 1.0);
  cost[n * R] = cost[n * R + 1] = cost[n * R + 2] = 0.0;
  const LeadSolution solution = solve_lead(A, b, scale, cost);
  MatchResult out;
  const double M = solution.m[n * R];
  out.common.mass_kg = M;
  out.common.balance_from_butt_m = solution.m[n * R + 1] / M;
  out.common.swingweight_kg_m2 = solution.m[n * R + 2];
  for (std::size_t i = 0; i < R; ++i) {
    // Each racquet tuned to the common specs on its own, the least lead
    // that reaches them (the same specs, exactly).
    out.tuned.push_back(tune(designs[i], out.common, places));
  }
  return out;
}

TuneEvaluations evaluate_tune(const io::DesignFile& original, const io::Json& tuned,
                              const std::string& tuned_name, double rel_tol) {
  return {compare_one(original, "", rel_tol),
          compare_one(io::read_design(tuned, tuned_name), "", rel_tol)};
}

}  // namespace sweetspot::studies

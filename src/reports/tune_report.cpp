#include "reports/tune_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "io/json_reader.hpp"
#include "reports/comparison.hpp"
#include "sweetspot/head_geometry.hpp"

namespace sweetspot::reports {
namespace {

using studies::LeadPlace;
using studies::RacquetSpecs;
using studies::TuneTargets;

// `round`: a bat's (an implement given by its profile), whose butt is its knob.
std::string where(const LeadPlace& place, bool round) {
  switch (place.kind) {
    case LeadPlace::Kind::kThroat:
      return "the throat (6 o'clock)";
    case LeadPlace::Kind::kUnderGrip:
      return fmt::format("under the grip ({:g} cm from the butt)",
                         studies::kUnderGripFromButt_m * 1e2);
    case LeadPlace::Kind::kButtCap:
      return fmt::format("{} ({:g} cm from the butt)", round ? "at the knob" : "under the butt cap",
                         kHandleWeightFromButt_m * 1e2);
    case LeadPlace::Kind::kClock:
      if (place.hours.size() == 2)
        return fmt::format("{:g} and {:g} o'clock", place.hours[0], place.hours[1]);
      return fmt::format("{:g} o'clock", place.hours[0]);
  }
  return place.label;
}

// A value rounded to `decimals`, never "-0.0".
double rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double r = std::round(value * scale) / scale;
  return r == 0.0 ? 0.0 : r;
}

std::string cell(std::optional<double> value, double factor, int decimals, const char* unit) {
  if (!value) return "–";
  const std::string number = fmt::format("{:.{}f}", rounded(*value * factor, decimals), decimals);
  return *unit ? number + " " + unit : number;
}

struct SpecRow {
  const char* label;
  const char* key;  // people's units in the suffix
  double factor;    // SI to the key's unit
  int decimals;
  const char* unit;
  std::optional<double> (*of_specs)(const RacquetSpecs&);
  std::optional<double> (*of_targets)(const TuneTargets&);
};

const SpecRow kSpecRows[] = {
    {"mass", "mass_g", 1e3, 1, "g",
     [](const RacquetSpecs& s) -> std::optional<double> { return s.mass_kg; },
     [](const TuneTargets& t) { return t.mass_kg; }},
    {"balance from the butt", "balance_cm", 1e2, 2, "cm",
     [](const RacquetSpecs& s) -> std::optional<double> { return s.balance_from_butt_m; },
     [](const TuneTargets& t) { return t.balance_from_butt_m; }},
    {"swingweight", "swingweight_kg_cm2", 1e4, 1, "kg·cm²",
     [](const RacquetSpecs& s) -> std::optional<double> { return s.swingweight_kg_m2; },
     [](const TuneTargets& t) { return t.swingweight_kg_m2; }},
    {"twistweight", "twistweight_kg_cm2", 1e4, 2, "kg·cm²",
     [](const RacquetSpecs& s) { return s.twistweight_kg_m2; },
     [](const TuneTargets& t) { return t.twistweight_kg_m2; }},
};

io::Json specs_json(const RacquetSpecs& s) {
  io::Json j = io::Json::object();
  for (const SpecRow& row : kSpecRows) {
    if (const auto v = row.of_specs(s)) j[row.key] = *v * row.factor;
  }
  return j;
}

// The numbers the change moves, for one evaluated design.
struct Effect {
  const char* label;
  const char* key;
  double factor;
  int decimals;
  const char* unit;
  std::optional<double> (*of)(const studies::ComparedDesign&);
};

const Effect kEffects[] = {
    {"centre of percussion (hand-held) from the tip", "cop_hand_from_tip_cm", 1e2, 1, "cm",
     [](const studies::ComparedDesign& c) { return c.spots.cop_from_tip_m; }},
    {"node of the fundamental (hand-held) from the tip", "node_from_tip_cm", 1e2, 1, "cm",
     [](const studies::ComparedDesign& c) { return c.spots.node_from_tip_m; }},
    {"peak wrist force at the impact", "peak_wrist_force_N", 1.0, 0, "N",
     [](const studies::ComparedDesign& c) -> std::optional<double> {
       return c.spots.asked.evaluation.peak_wrist_force_N;
     }},
    {"recoil weight (inertia about the balance point)", "recoil_weight_kg_cm2", 1e4, 1, "kg·cm²",
     [](const studies::ComparedDesign& c) -> std::optional<double> {
       return c.spots.asked.evaluation.I_cm_kg_m2;
     }},
    {"apparent COR at the impact", "apparent_cor", 1.0, 3, "",
     [](const studies::ComparedDesign& c) -> std::optional<double> {
       return c.spots.asked.evaluation.apparent_cor;
     }},
};

std::string markdown(const TunedRacquet& t, double strip_kg) {
  const studies::TuneResult& r = t.result;
  const bool round = is_round(t.before.design.design);
  std::string out = fmt::format("## {}\n\n", t.before.design.name);
  out += r.exact ? "The targets are reached with lead at the places given.\n\n"
                 : "**The targets cannot be reached** with lead at these places; the nearest "
                   "specs lead there can give are shown (nearest in 1 g, 1 mm of balance and "
                   "1 kg·cm² weighed alike).\n\n";
  out += "| spec | before | target | after |\n|---|---|---|---|\n";
  for (const SpecRow& row : kSpecRows) {
    const auto before = row.of_specs(r.before);
    if (!before && !row.of_targets(r.targets)) continue;
    out += fmt::format("| {} | {} | {} | {} |\n", row.label,
                       cell(before, row.factor, row.decimals, row.unit),
                       cell(row.of_targets(r.targets), row.factor, row.decimals, row.unit),
                       cell(row.of_specs(r.reached), row.factor, row.decimals, row.unit));
  }
  out += fmt::format("\n| lead at | grams | strips of {:g} g |\n|---|---|---|\n",
                     rounded(strip_kg * 1e3, 3));
  for (const studies::PlacedLead& lead : r.lead) {
    const double g = lead.mass_kg * 1e3;
    const std::size_t pieces = lead.pieces.size();
    const std::string each =
        pieces > 1 ? fmt::format(" ({:.1f} g at each)", rounded(g / static_cast<double>(pieces), 1))
                   : "";
    const std::string strips =
        pieces > 1 ? fmt::format("{:.1f} at each",
                                 rounded(lead.mass_kg / strip_kg / static_cast<double>(pieces), 1))
                   : fmt::format("{:.1f}", rounded(lead.mass_kg / strip_kg, 1));
    out += fmt::format("| {} | {:.1f} g{} | {} |\n", where(lead.place, round), rounded(g, 1), each,
                       strips);
  }
  out += fmt::format("\n{:.1f} g of lead in all.", rounded(r.added_kg * 1e3, 1));
  if (!t.written.empty()) out += " The tuned design is written to " + t.written + ".";
  out += "\n";
  if (!r.exact) {
    out += "\nWhy:\n\n";
    for (const studies::TargetMiss& miss : r.misses)
      out += "- " + (miss.spec == "together" ? "" : miss.spec + ": ") + miss.reason + ".\n";
  }
  out += "\n| what the lead changes | before | after |\n|---|---|---|\n";
  for (const Effect& e : kEffects) {
    out += fmt::format("| {} | {} | {} |\n", e.label,
                       cell(e.of(t.before), e.factor, e.decimals, e.unit),
                       cell(e.of(t.after), e.factor, e.decimals, e.unit));
  }
  const std::vector<std::string> changes = differences(t.before, t.after);
  if (!changes.empty()) {
    out += "\n";
    for (const std::string& sentence : changes) out += sentence + "\n";
  }
  return out;
}

io::Json json_of(const TunedRacquet& t, double strip_kg) {
  const studies::TuneResult& r = t.result;
  io::Json j;
  j["name"] = t.before.design.name;
  j["source"] = t.before.design.source;
  j["reachable"] = r.exact;
  j["before"] = specs_json(r.before);
  io::Json targets = io::Json::object();
  for (const SpecRow& row : kSpecRows) {
    if (const auto v = row.of_targets(r.targets)) targets[row.key] = *v * row.factor;
  }
  j["targets"] = targets;
  j["reached"] = specs_json(r.reached);
  io::Json lead = io::Json::array();
  for (const studies::PlacedLead& l : r.lead) {
    io::Json pieces = io::Json::array();
    for (const PointMass& p : l.pieces) {
      pieces.push_back({{"mass_g", p.mass_kg * 1e3},
                        {"from_butt_cm", p.from_butt_m * 1e2},
                        {"off_axis_cm", p.off_axis_m * 1e2}});
    }
    lead.push_back({{"place", l.place.label},
                    {"where", where(l.place, is_round(t.before.design.design))},
                    {"mass_g", l.mass_kg * 1e3},
                    {"strips", l.mass_kg / strip_kg},
                    {"pieces", pieces}});
  }
  j["lead"] = lead;
  j["added_g"] = r.added_kg * 1e3;
  j["strip_g"] = strip_kg * 1e3;
  io::Json why = io::Json::array();
  for (const studies::TargetMiss& miss : r.misses)
    why.push_back({{"spec", miss.spec}, {"reason", miss.reason}});
  j["why"] = why;
  io::Json effect = io::Json::object();
  for (const Effect& e : kEffects) {
    io::Json pair = io::Json::object();
    if (const auto v = e.of(t.before)) pair["before"] = *v * e.factor;
    if (const auto v = e.of(t.after)) pair["after"] = *v * e.factor;
    effect[e.key] = pair;
  }
  j["effect"] = effect;
  j["differences"] = differences(t.before, t.after);
  j["written"] = t.written.empty() ? io::Json(nullptr) : io::Json(t.written);
  return j;
}

}  // namespace

std::string tune_report(const std::vector<TunedRacquet>& racquets, double strip_kg,
                        io::Format format, const std::string& rule) {
  if (format == io::Format::kJson) {
    if (racquets.size() == 1 && rule.empty()) return json_of(racquets[0], strip_kg).dump(2) + "\n";
    io::Json all;
    all["rule"] = rule;
    all["racquets"] = io::Json::array();
    for (const TunedRacquet& t : racquets) all["racquets"].push_back(json_of(t, strip_kg));
    return all.dump(2) + "\n";
  }
  std::string out = "# Lead tape to target specs\n\n";
  if (!rule.empty()) out += rule + "\n\n";
  for (const TunedRacquet& t : racquets) out += markdown(t, strip_kg) + "\n";
  out.pop_back();
  return out;
}

}  // namespace sweetspot::reports

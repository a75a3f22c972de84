#include "reports/string_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/json_reader.hpp"

namespace sweetspot::reports {
namespace {

using io::kKilogramForce_N;
using io::kPoundForce_N;

// N/m in lbf per inch.
constexpr double kLbInPerNM = io::kInch_m / kPoundForce_N;

std::string num(double value, int digits = 3) { return io::significant(value, digits); }

// An answer below 0.6 or above 1.5 times the tension the design is strung at
// is said to be far from it: a stringer moves a frame by a few pounds, and the
// 40 to 70 lb that modern tennis racquets are strung at (Solihull Racket
// Services, "Tension gauge", solihullracketservices.co.uk/tension-gauge)
// spans these factors.
constexpr double kFarBelowStrung = 0.6;
constexpr double kFarAboveStrung = 1.5;

io::Json bed_json(const studies::BedReading& b) {
  return io::Json{{"pull_tension_lb", b.pull_tension_N / kPoundForce_N},
                  {"pull_tension_kg", b.pull_tension_N / kKilogramForce_N},
                  {"crosses_pull_tension_lb", b.cross_pull_tension_N / kPoundForce_N},
                  {"tension_loss", b.tension_loss},
                  {"string_bed_tension_N", b.bed_tension_N},
                  {"string_bed_stiffness_N_m", b.stiffness_N_m},
                  {"string_bed_stiffness_lb_in", b.stiffness_N_m * kLbInPerNM},
                  {"string_bed_ring_Hz", b.ring_Hz},
                  {"dwell_s", b.dwell_s},
                  {"strings_mass_g", b.strings_mass_kg * 1e3},
                  {"per_lb",
                   {{"string_bed_stiffness_N_m", b.stiffness_per_lb},
                    {"string_bed_ring_Hz", b.ring_per_lb},
                    {"dwell_s", b.dwell_per_lb}}}};
}

// A quantity in the units a stringer reads it in.
std::string in_words(studies::BedQuantity q, double value) {
  switch (q) {
    case studies::BedQuantity::kStiffness:
      return fmt::format("{} kN/m ({} lb/in)", num(value / 1e3), num(value * kLbInPerNM));
    case studies::BedQuantity::kRing:
      return fmt::format("{} Hz", num(value));
    case studies::BedQuantity::kDwell:
      return fmt::format("{} ms", num(value * 1e3));
  }
  return num(value);
}

std::string tensions(const studies::BedReading& b) {
  const double mains_lb = b.pull_tension_N / kPoundForce_N;
  const double crosses_lb = b.cross_pull_tension_N / kPoundForce_N;
  if (std::fabs(mains_lb - crosses_lb) < 1e-9)
    return fmt::format("{} lb ({} kg)", num(mains_lb, 4),
                       num(mains_lb * kPoundForce_N / kKilogramForce_N));
  return fmt::format("mains {} lb ({} kg), crosses {} lb ({} kg)", num(mains_lb, 4),
                     num(b.pull_tension_N / kKilogramForce_N), num(crosses_lb, 4),
                     num(b.cross_pull_tension_N / kKilogramForce_N));
}

std::string markdown(const StringAnswer& a) {
  const studies::BedReading& b = a.bed;
  std::string md = fmt::format("# The string bed of {}\n\n", a.name);
  if (a.tension) {
    const studies::TensionAnswer& t = *a.tension;
    const studies::BedReading& r = t.at_rounded;
    const double q_per_lb = r.per_lb(t.keep);
    if (t.reachable) {
      md += fmt::format(
          "**String it at {}** to keep the {} of {}, {}. At that setting the bed's {} is {} "
          "(exactly {} lb would match it); each pound more changes it by "
          "{}.\n\n",
          tensions(r), to_string(t.keep), a.target_from, in_words(t.keep, t.target),
          to_string(t.keep), in_words(t.keep, r.value(t.keep)),
          num(t.exact_pull_N / kPoundForce_N, 4),
          t.keep == studies::BedQuantity::kDwell ? fmt::format("{} ms", num(q_per_lb * 1e3, 2))
                                                 : in_words(t.keep, q_per_lb));
      // An answer far from the frame's own tension is said to be so: a target
      // typed from another instrument's scale (an RDC index as lb/in) lands here.
      const double ratio = t.rounded_pull_lb / (b.pull_tension_N / kPoundForce_N);
      if (ratio < kFarBelowStrung || ratio > kFarAboveStrung) {
        md += fmt::format(
            "That is {} times the tension this design is strung at ({} lb), for a bed {} than "
            "its own{}.\n\n",
            num(ratio, 3), num(b.pull_tension_N / kPoundForce_N, 3),
            ratio < 1.0 ? "far softer" : "far stiffer",
            t.keep == studies::BedQuantity::kStiffness && a.target_from == "the target"
                ? ". If the target is an RDC or an ERT reading, it is an index of that "
                  "instrument's own, not lb/in or kN/m"
                : "");
      }
    } else {
      md += fmt::format(
          "**No tension this frame takes gives the {} of {}, {}**: the nearest, {}, gives {}. "
          "The model is verified for tensions of {} to {} lb in the bed.\n\n",
          to_string(t.keep), a.target_from, in_words(t.keep, t.target), tensions(r),
          in_words(t.keep, r.value(t.keep)), num(kMinTension_N / kPoundForce_N),
          num(kMaxTension_N / kPoundForce_N));
    }
  }
  md += fmt::format(
      "| | as strung | per lb more |\n|---|---|---|\n"
      "| tension on the machine | {} | |\n"
      "| tension in the bed (mains) | {} lb ({} N) | |\n"
      "| string-bed stiffness | {} | {} |\n"
      "| ring (tap tone) | {} Hz | {} Hz |\n"
      "| dwell (time on the strings) | {} ms | {} ms |\n"
      "| strings in the head | {} g | |\n\n",
      tensions(b), num(b.bed_tension_N / kPoundForce_N, 4), num(b.bed_tension_N, 4),
      in_words(studies::BedQuantity::kStiffness, b.stiffness_N_m),
      in_words(studies::BedQuantity::kStiffness, b.stiffness_per_lb), num(b.ring_Hz),
      num(b.ring_per_lb, 2), num(b.dwell_s * 1e3), num(b.dwell_per_lb * 1e3, 2),
      num(b.strings_mass_kg * 1e3));
  md += fmt::format(
      "What this assumes: {}. The stiffness is the tensioned "
      "membrane's at the centre of the head, not a machine's reading: an RDC or an ERT prints "
      "its own index, and instruments disagree with one another by several points; compare a "
      "machine with itself. The ring is the membrane's fundamental over the head's area; the "
      "dwell is the contact time of the ball and the bed as two springs at the impact point. "
      "The string's own stiffness (the retailer's lb/in) does not enter: at the bed's small "
      "slopes its stiffness is its tension's.{}\n",
      b.tension_loss > 0.0
          ? fmt::format("the bed holds the pull less {} % (strings.tension_loss)",
                        num(b.tension_loss * 100.0))
          : std::string("the bed holds the whole pull (strings.tension_loss 0; Cross & Bower "
                        "2001 measured about 30 % lost right after stringing: set 0.3 to "
                        "compare with a reading of a freshly strung frame)"),
      a.solved_contact_time_s
          ? fmt::format(" With the frame's stiffness, ball, strings and frame are solved together, "
                        "as `sweetspot evaluate` does: there the ball stays on the strings {} ms "
                        "(the two springs' dwell above is the estimate the tension matching "
                        "uses).",
                        num(*a.solved_contact_time_s * 1e3))
          : std::string());
  return md;
}

io::Json json(const StringAnswer& a) {
  io::Json j{{"design", a.name}, {"bed", bed_json(a.bed)}};
  j["contact_time_s"] =
      a.solved_contact_time_s ? io::Json(*a.solved_contact_time_s) : io::Json(nullptr);
  if (a.tension) {
    const studies::TensionAnswer& t = *a.tension;
    const double kg = t.rounded_pull_lb * kPoundForce_N / kKilogramForce_N;
    j["keep"] = std::string(to_string(t.keep));
    j["target"] = t.target;
    j["target_unit"] = std::string(unit_of(t.keep));
    j["target_from"] = a.target_from;
    j["reachable"] = t.reachable;
    j["tension_to_as_strung"] = t.rounded_pull_lb / (a.bed.pull_tension_N / kPoundForce_N);
    j["tension_lb"] = t.rounded_pull_lb;
    j["tension_kg"] = std::round(kg * 10.0) / 10.0;
    j["crosses_tension_lb"] = t.rounded_cross_pull_lb;
    j["crosses_tension_kg"] =
        std::round(t.rounded_cross_pull_lb * kPoundForce_N / kKilogramForce_N * 10.0) / 10.0;
    j["exact_crosses_tension_lb"] = t.exact_cross_pull_N / kPoundForce_N;
    j["exact_tension_lb"] = t.exact_pull_N / kPoundForce_N;
    j["at_tension"] = bed_json(t.at_rounded);
  }
  return j;
}

}  // namespace

std::string string_beds_report(const std::vector<ShippedBed>& beds,
                               const std::vector<ShippedMatch>& matches, io::Format format) {
  if (format == io::Format::kCsv) {
    std::string csv =
        "design,mains_pull_lb,crosses_pull_lb,tension_loss,string_bed_tension_N,"
        "string_bed_stiffness_N_m,string_bed_stiffness_lb_in,string_bed_ring_Hz,dwell_s,"
        "strings_mass_g\n";
    for (const ShippedBed& b : beds) {
      const studies::BedReading& r = b.bed;
      csv += fmt::format(
          "{},{},{},{},{},{},{},{},{},{}\n", b.file, io::exact(r.pull_tension_N / kPoundForce_N),
          io::exact(r.cross_pull_tension_N / kPoundForce_N), io::exact(r.tension_loss),
          io::exact(r.bed_tension_N), io::exact(r.stiffness_N_m),
          io::exact(r.stiffness_N_m * kLbInPerNM), io::exact(r.ring_Hz), io::exact(r.dwell_s),
          io::exact(r.strings_mass_kg * 1e3));
    }
    return csv;
  }
  std::string md =
      "# The shipped designs' string beds\n\n"
      "Every shipped design with a string bed, as `sweetspot string` reads it: the pull on the "
      "machine, the bed's tension (the pull less `strings.tension_loss`), its stiffness (the "
      "tensioned membrane's, not an instrument's index), its ring (the membrane's fundamental) "
      "and the dwell (the ball and the bed as two springs at the design's impact point). The "
      "numbers to every digit are in [string-beds.csv](string-beds.csv).\n\n"
      "| design | pull (lb) | in the bed (N) | stiffness | ring (Hz) | dwell (ms) | strings (g) |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const ShippedBed& b : beds) {
    const studies::BedReading& r = b.bed;
    const double m = r.pull_tension_N / kPoundForce_N, c = r.cross_pull_tension_N / kPoundForce_N;
    md += fmt::format("| [{}](../designs/{}) | {} | {} | {} | {} | {} | {} |\n", b.file, b.file,
                      std::fabs(m - c) < 1e-9 ? num(m, 4) : num(m, 4) + " / " + num(c, 4),
                      num(r.bed_tension_N, 4),
                      in_words(studies::BedQuantity::kStiffness, r.stiffness_N_m), num(r.ring_Hz),
                      num(r.dwell_s * 1e3), num(r.strings_mass_kg * 1e3));
  }
  if (!matches.empty()) {
    md +=
        "\nThe stringer's question for each ticket of `designs/strings/`: the tension on it that "
        "keeps the other's string-bed stiffness (`sweetspot string A --like B`).\n\n"
        "| frame | keeps the bed of | string it at | per lb more |\n|---|---|---|---|\n";
    for (const ShippedMatch& m : matches) {
      const studies::TensionAnswer& t = m.answer;
      md += fmt::format("| {} | {} | {} | {} |\n", m.file, m.like_file, tensions(t.at_rounded),
                        in_words(t.keep, t.at_rounded.per_lb(t.keep)));
    }
  }
  return md;
}

std::string string_report(const StringAnswer& answer, io::Format format) {
  if (format == io::Format::kJson) return json(answer).dump(2) + "\n";
  return markdown(answer);
}

}  // namespace sweetspot::reports

#pragma once

// `sweetspot string`, rendered: a string bed as a stringer reads it (the
// tensions on the machine and in the bed, the bed's stiffness, ring and
// dwell, what a pound changes) and, when asked, the tension that gives it
// another bed's stiffness, ring or dwell, or a target's.

#include <optional>
#include <string>
#include <vector>

#include "io/format.hpp"
#include "studies/string_ticket.hpp"

namespace sweetspot::reports {

struct StringAnswer {
  std::string name;  // the design's
  studies::BedReading bed;
  // The inverse, when asked: the target's origin ("tour-100.json at 52 lb",
  // "the target") and the answer.
  std::optional<studies::TensionAnswer> tension;
  std::string target_from;
  // The solved collision's contact time at the design's impact, as `evaluate`
  // gives it, when the frame's stiffness lets it be solved (and it answers).
  std::optional<double> solved_contact_time_s = std::nullopt;
};

// Markdown (a sentence a stringer can act on, then the bed's numbers and
// what it assumes) or JSON ({"design", "bed": {...}, "tension_lb",
// "tension_kg", "crosses_tension_lb", "keep", "target", "reachable",
// "per_lb", "at_rounded"}, the tension keys present with an inverse only).
std::string string_report(const StringAnswer& answer, io::Format format);

// The shipped designs' beds side by side (reports/string-beds.md and .csv):
// one row per design (its file, its name, its bed), then each inverse asked.
struct ShippedBed {
  std::string file;  // relative to the designs folder
  std::string name;
  studies::BedReading bed;
};
struct ShippedMatch {
  std::string file, like_file;
  studies::TensionAnswer answer;
};
std::string string_beds_report(const std::vector<ShippedBed>& beds,
                               const std::vector<ShippedMatch>& matches, io::Format format);

}  // namespace sweetspot::reports

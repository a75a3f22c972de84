#pragma once

// A design as its file describes it, before anything is derived from it: each
// number in SI, in the form the file gave it (a balance in points head-light,
// an impact from the tip, the forearm's own mass). A study variable, a sweep
// axis or a batch column changes one of these numbers; derive() then rebuilds
// only what depends on it (the implement, the impact point from the tip, the
// equivalent forearm mass) with the reader's own arithmetic, so the design is
// bit for bit the one read_design() gives for the changed file.

#include <optional>
#include <vector>

#include "sweetspot/design.hpp"

namespace sweetspot::io {

// 1 point head-light = 1/8 inch from the middle of the length towards the butt.
inline constexpr double kPointHeadLight_m = 0.0254 / 8.0;

// The largest |points| head-light that keeps the balance inside (0, L).
double points_head_light_limit(double length_m);
// The balance point [m from the butt] of `points` head-light on a length L.
double balance_from_points_head_light(double length_m, double points);
// The string bed's radius [m] of a head of area `area_m2` (a circle).
double head_radius_from_area(double area_m2);

// How the implement was given, in SI, before the implement is built.
struct ImplementDescription {
  enum class Form { kHeadToHandleRatio, kSections, kSpecs };
  Form form = Form::kHeadToHandleRatio;
  double length_m = 0.0;                   // kHeadToHandleRatio, kSpecs
  double mass_kg = 0.0;                    // kHeadToHandleRatio, kSpecs
  double head_to_handle_mass_ratio = 0.0;  // kHeadToHandleRatio
  bool balance_in_points = false;          // kSpecs: balance_pts_hl, else metres from the butt
  double balance = 0.0;                    // kSpecs: [m] from the butt, or points head-light
  double swingweight_kg_m2 = 0.0;          // kSpecs
  std::vector<Section> sections;           // kSections
  std::vector<PointMass> point_masses;
};

struct DesignDescription {
  ImplementDescription implement;
  // The design as read. derive() overwrites its implement and the derived
  // numbers below; every other field is set directly.
  Design design;
  bool forearm_from_mass = false;  // forearm/mass_*: M_e = M_F / 3 (Eq. 7)
  double forearm_mass_kg = 0.0;
  bool impact_from_tip = true;         // impact/from_tip_* (or the default 5 cm), else from_butt_*
  double impact_m = 0.05;              // from the tip or from the butt
  std::optional<double> head_area_m2;  // strings/head_size_*: sets the string bed's radius
};

// The implement the description gives. Throws std::invalid_argument (the
// implement's factories) or std::domain_error (a balance outside the length)
// where read_design() refuses it.
Implement build_implement(const ImplementDescription& description);

// Recomputes description.design's derived numbers (the equivalent forearm
// mass, the impact point from the butt, the string bed's radius) from the
// description and its implement as it stands, then validate()s the design.
// Throws where read_design() would refuse the same numbers (the message is
// not the reader's: re-read the file for that).
void derive(DesignDescription& description);

}  // namespace sweetspot::io

#pragma once

// `sweetspot compare A.json B.json ...`, its numbers: each design evaluated
// at its own impact and at its sweet spots, and, for the web page, along its
// frame. reports/comparison.hpp says what changes in words and draws it.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/design_reader.hpp"
#include "studies/arm_load.hpp"
#include "studies/frame_curves.hpp"
#include "studies/sweet_spots.hpp"

namespace sweetspot::studies {

struct ComparedDesign {
  io::DesignFile design;  // as read (a default impact is the reader's, io::default_impact())
  SweetSpots spots;       // spots.asked.evaluation is the design's own evaluation
  // Along the frame every kFrameCurveStep_m at frame_curve_fidelity() of the
  // design's own evaluation; empty unless asked (compare_one's along_frame).
  std::vector<FramePoint> curve;
  // What the design does to the arm over a spread of hits (arm_load()).
  ArmLoad arm;
  // The vibration the asked impact leaves at the hand, or why it is not known.
  std::optional<HandVibration> asked_vibration;
  std::string asked_vibration_why;
  // Per point mass of the implement: the hour on the hoop it sits at (a whole
  // hour of head_geometry.hpp's clock_position()), std::nullopt elsewhere.
  std::vector<std::optional<int>> clock_hours;
  // Shot speed (a swinging racquet) is to join here when the evaluation gives it.
};

// Reads nothing: evaluates each design (at `fidelity`, "" for the file's own,
// the hand-held modes to `rel_tol`) and finds its sweet spots and its load on
// the arm, and with `along_frame` its curve along the frame. Throws like
// io::evaluate_design_file, naming the file and the JSON path.
ComparedDesign compare_one(io::DesignFile design, std::string_view fidelity, double rel_tol,
                           bool along_frame = false);

}  // namespace sweetspot::studies

#pragma once

// The answer first: where the sweet spots of a design held in the hand are,
// how far apart, and what the wrist and the ball feel at each, in a few plain
// sentences (centimetres from the tip, newtons rounded to what the model can
// claim), said from studies::find_sweet_spots()'s record. `evaluate`'s
// Markdown opens with them; the HTML report and `compare` reuse them.

#include <optional>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "studies/sweet_spots.hpp"

namespace sweetspot::reports {

// A few plain sentences answering "where are the sweet spots, how far apart,
// and what does the arm feel at each and at my impact": positions to 0.5 cm
// from the tip, forces to two significant figures, the apparent COR to two
// decimals (the model's inputs, a hand 7 cm from the butt and a forearm of
// 0.5 kg, are not known better).
std::vector<std::string> sweet_spot_sentences(const io::DesignFile& design,
                                              const studies::SweetSpots& spots);

// The sentences as one Markdown paragraph (no trailing newline).
std::string sweet_spot_paragraph(const io::DesignFile& design, const studies::SweetSpots& spots);

// A rig's answer in words (Evaluation::support): what comes back, how long
// the contact lasts, the peak force and the ball's squeeze; no sweet spots
// (they are the player's). No trailing newline.
std::string rig_paragraph(const io::DesignFile& design, const Evaluation& evaluation);

// Rounding shared by the sentences and `compare`: a position in cm to 0.5 cm
// ("30.5 cm"), a force to two significant figures ("470 N"), a ratio to two
// decimals ("0.42").
std::string cm_text(double metres);
std::string newton_text(double newtons);
std::string ratio_text(double ratio);

}  // namespace sweetspot::reports

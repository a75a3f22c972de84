#pragma once

// A frame's stiffness from the numbers on a retailer's spec sheet.
//
// RA is the stiffness rating printed on every tennis racquet's spec sheet:
// the racquet is supported at the handle and the throat and loaded at the tip,
// and the tip's static deflection is read on a 0-100 scale (Babolat's RDC;
// the procedure described by Tennis Warehouse University, "Racquet vibration",
// twu.tennis-warehouse.com/learning_center/vibration_explanation.php). It is
// a static number and says nothing by itself about the mass the frame must
// move, so the modes cannot take it directly. The retailer's lab also
// measures each racquet's vibration frequency, which grows with RA and falls
// with the mass, and the two are related here by a fit:
//
//   f1 = f_ref (RA / RA_ref)^p (m / m_ref)^q        [Hz]
//
// with m the strung frame's mass, RA_ref = 65, m_ref = 0.31 kg, fitted by
// least squares on ln f1 to the 263 strung racquets of the Tennis Warehouse
// University racquet table (columns flex = RA, weight = strung mass in g,
// vibration in Hz; RA 54-75, 242-349 g, 117-182 Hz; collected in a public
// MIT-licensed repository): f_ref = 146.9 Hz, p = 1.115, q = -0.276.
// Residuals over the 263: RMS 4.8 Hz (3.2 %), 95 % within 9.9 Hz, the
// largest 18.4 Hz (11 %); ten-fold cross-validation gives RMS 4.9 Hz, so the
// fit does not live on its own sample. RA alone (f1 = a + b RA) leaves RMS
// 5.6 Hz; adding the swingweight, length or head size gains < 0.2 Hz. A
// racquet's frequency from its RA is so good to about +-5 Hz, +-10 Hz for
// one racquet in twenty: enough to place the node (which moves by
// millimetres over that range), not to rank two frames 5 Hz apart. The same
// data answer the physical guess f ~ sqrt(k/m) with an exponent of mass of
// -0.28, not -0.5: RA is not proportional to the bending stiffness, and
// heavier frames are built stiffer.
//
// What the lab's frequency is: the Tennis Warehouse University page explains
// it as the frame's fundamental bending vibration, the mode with a node just
// below the centre of the head. Its values, 117-182 Hz, are those of free
// racquets (Cross 2004 and the literature: 100-180 Hz free). A racquet
// clamped rigidly at the handle vibrates as a cantilever several times
// slower (a uniform beam: (1.875 / 4.730)^2 = 0.16 of its free fundamental,
// ~25 Hz), so the column cannot be a clamped fundamental; a hand-held one
// would be some 10 % below the free one (Cross 2004: 193 -> 171 Hz). The fit
// is therefore taken as the free fundamental, `FrameStiffness::fundamental_free_Hz`,
// with that 10 % as the systematic doubt should the lab's support have been
// a hand-like grip.

namespace sweetspot {

// The fit's constants (above). Source: Tennis Warehouse University racquet
// table, 263 strung racquets.
inline constexpr double kRAFitReference_Hz = 146.9;
inline constexpr double kRAFitReferenceRA = 65.0;
inline constexpr double kRAFitReferenceMass_kg = 0.31;
inline constexpr double kRAFitRAExponent = 1.115;
inline constexpr double kRAFitMassExponent = -0.276;
// Its error over the sample: RMS and largest residual [Hz]; sample size.
inline constexpr double kRAFitRmsError_Hz = 4.8;
inline constexpr double kRAFitMaxError_Hz = 18.4;
inline constexpr int kRAFitSampleSize = 263;
// Where the relation is used: the sample's RA 54-75 and 242-349 g, widened a
// little (RA 50-80, 200-400 g); beyond, the racquet is not one the fit knows.
inline constexpr double kMinRA = 50.0;
inline constexpr double kMaxRA = 80.0;
inline constexpr double kMinRAFrameMass_kg = 0.20;
inline constexpr double kMaxRAFrameMass_kg = 0.40;
// Every racquet of the sample is 27-28 in long; the length adds nothing
// inside it, but a beam's frequency goes as 1/L^2 outside it, so the relation
// is used for 26-29 in only (a 25 in junior frame of RA 60 would get an adult
// frame's 149 Hz): give a junior's free fundamental or its EI instead.
inline constexpr double kMinRALength_m = 26.0 * 0.0254;
inline constexpr double kMaxRALength_m = 29.0 * 0.0254;

// The free fundamental [Hz] of a strung tennis racquet of stiffness rating
// `RA` (in [kMinRA, kMaxRA]) and strung frame mass `frame_mass_kg` (in
// [kMinRAFrameMass_kg, kMaxRAFrameMass_kg], without lead tape added after
// the rating) and length `length_m` (in [kMinRALength_m, kMaxRALength_m]):
// f1 = 146.9 (RA/65)^1.115 (m/0.31 kg)^-0.276 (above), within
// kRAFitRmsError_Hz RMS. Throws std::invalid_argument naming "frame/RA" for
// an RA outside its range or not finite, and naming "frame/RA" with the mass
// or the length for a frame the fit does not cover.
double fundamental_free_Hz_from_RA(double RA, double frame_mass_kg, double length_m);

}  // namespace sweetspot

#pragma once

// Rigid-body mass properties of a slender implement about a transverse axis.
// Positions are measured along the long axis from the butt (handle end, x = 0).

namespace sweetspot {

// The axis of the industry swingweight: 10 cm from the butt.
inline constexpr double kSwingweightAxisFromButt_m = 0.10;

// A mass at a point of the implement: lead tape, a hand on a handle. The
// transverse mass properties below use from_butt_m only (a mass off the axis
// turns the implement about a transverse axis exactly as one on it); the
// off-axis distance counts in the polar inertia (head_geometry.hpp).
struct PointMass {
  double from_butt_m = 0.0;  // [m], in [0, L]
  double mass_kg = 0.0;      // [kg], >= 0
  double off_axis_m = 0.0;   // y [m], across the face, positive towards 3 o'clock; 0: on the axis
};

// Total mass, centre of mass and moment of inertia about the centre of mass
// (transverse axis) of a rigid body lying along the long axis.
struct MassProperties {
  double mass_kg = 0.0;          // [kg], > 0
  double com_from_butt_m = 0.0;  // [m]
  double I_cm_kg_m2 = 0.0;       // [kg m^2], >= 0
};

// Moment of inertia about a transverse axis at `axis_from_butt_m`
// (parallel-axis theorem): I = I_cm + M (x_axis - x_cm)^2  [kg m^2].
double inertia_about(const MassProperties& body, double axis_from_butt_m);

// Swingweight: inertia about the axis 10 cm from the butt [kg m^2].
double swingweight_kg_m2(const MassProperties& body);

// The body with a point mass rigidly attached. The shift of the centre of mass
// is Cross (2004) Eq. (14) with the hand as the point mass:
//   x = m (c - x_m) / (M + m),  new centre c - x;
// the inertia follows from the parallel-axis theorem for both parts.
// Throws std::invalid_argument if the point mass is negative or not finite.
MassProperties with_point_mass(const MassProperties& body, const PointMass& point);

// Inverse of swingweight_kg_m2(): the mass properties of a body of mass M with
// its balance point at `balance_from_butt_m` and swingweight `swingweight_kg_m2`.
// Throws std::invalid_argument unless the swingweight is at least
// M (balance - 0.10 m)^2 (that is, I_cm >= 0).
MassProperties from_swingweight(double mass_kg, double balance_from_butt_m,
                                double swingweight_kg_m2);

}  // namespace sweetspot

// The flexible frame of a design: fitted mass distributions and the
// fundamental free and hand-held, against the paper (Sections III and IV).
#include "sweetspot/frame_modes.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "sweetspot/evaluate.hpp"

namespace sweetspot {
namespace {

constexpr double kRoundOff = 1e-12;
// The paper reads nodes off impact traces every 2 cm: "15.8 cm", "16 cm".
constexpr double kMeasuredNodeTolerance_m = 0.005;

Design paper_beam(double hand_kg = 0.5) {
  Design d{Implement::from_sections({Section{0.72, 0.328, {}}})};
  d.hand.mass_kg = hand_kg;
  d.stiffness.fundamental_free_Hz = 193.0;
  return d;
}

TEST_CASE("A fitted distribution reproduces mass, balance and swingweight exactly") {
  const MassProperties specs = from_swingweight(0.305, 0.325, 0.0320);
  const std::vector<Section> sections = fitted_sections(0.6858, specs);
  REQUIRE(sections.size() == static_cast<std::size_t>(kFittedSections));
  const MassProperties back = section_mass_properties(sections);
  CHECK(back.mass_kg == Approx(specs.mass_kg).epsilon(kRoundOff));
  CHECK(back.com_from_butt_m == Approx(specs.com_from_butt_m).epsilon(kRoundOff));
  CHECK(back.I_cm_kg_m2 == Approx(specs.I_cm_kg_m2).epsilon(kRoundOff));
  // A uniform body is fitted by a uniform distribution.
  const MassProperties uniform{0.3, 0.35, 0.3 * 0.7 * 0.7 / 12};
  for (const Section& s : fitted_sections(0.7, uniform))
    CHECK(s.mass_kg == Approx(0.3 / kFittedSections).epsilon(1e-9));
}

TEST_CASE("Specs that no positive smooth distribution gives are refused") {
  // Nearly all the mass at the two ends: I_cm near its maximum M B (L - B).
  const MassProperties extreme{0.3, 0.35, 0.3 * 0.35 * 0.35 * 0.99};
  CHECK_THROWS_WITH(fitted_sections(0.7, extreme), Catch::Contains("no smooth"));
}

TEST_CASE("The paper's beam at 193 Hz has its free node 15.8 cm from the end") {
  const ModalOutputs m = evaluate_modes(paper_beam());
  CHECK(m.fundamental_free_Hz == Approx(193.0).epsilon(1e-9));
  REQUIRE(m.node_free_from_butt_m);
  CHECK(0.72 - *m.node_free_from_butt_m == Approx(0.158).margin(kMeasuredNodeTolerance_m));
}

TEST_CASE("Held in the hand the beam rings at about 171 Hz, damped, its free-end node kept") {
  const ModalOutputs m = evaluate_modes(paper_beam());
  // Section IV(a): 193 -> 171 Hz; the calibration fixes this to the solver's tolerance.
  CHECK(m.fundamental_hand_Hz == Approx(171.0).epsilon(1e-3));
  CHECK(m.hand_damping_ratio > 0.05);
  REQUIRE(m.node_hand_from_butt_m);
  // Section IV(b): "a vibration node 16 cm from the free end, as for the freely supported beam".
  CHECK(std::abs(*m.node_hand_from_butt_m - *m.node_free_from_butt_m) < 0.01);
}

// The paper's beam made round (wood, G 1 GPa, 6.4 cm across, Poisson's ratio 0.35) and a
// rectangle with the same kappa G A and the same radius of gyration are one
// Timoshenko beam: the design's section reaches the modes through its shape
// alone. The tube of the same outer diameter spreads its area outwards: more
// rotary inertia and a softer shear at the same EI and mass, so every mode falls.
namespace {

// A round implement of the paper beam's length by its profile: a wood rod,
// uniform or tapered from a handle to a barrel, solid or a shell.
Design round_rod(const std::vector<ProfileStation>& stations, double wall_m = 0.0) {
  const RoundProfile profile{
      .stations = stations, .density_kg_m3 = 650.0, .youngs_modulus_Pa = 1.2e10, .wall_m = wall_m};
  Design d{Implement::from_profile(profile)};
  d.stiffness.shear_modulus_Pa = 9e8;
  d.stiffness.cross_section =
      CrossSection{.shape = CrossSection::Shape::kProfile, .poisson_ratio = 0.35};
  return d;
}

std::vector<double> free_frequencies(const Design& d) {
  FlexibleFrame frame = flexible_frame(d);
  frame.options.rel_tol = kMinRelTol;
  std::vector<double> f;
  for (const Mode& m : free_modes(frame.sections, frame.point_masses, frame.options).modes)
    f.push_back(m.frequency_Hz);
  return f;
}

}  // namespace

// shape "profile": each slice of a round implement is the circle or tube of
// its own diameter. On a uniform rod or tube every slice is the same section,
// so the modes are those of that one circle or tube given by its sizes; on a
// taper they are below Euler-Bernoulli's, and reach them as G grows.
TEST_CASE("A fundamental is refused where the EI it takes passes the range a given EI has") {
  // The highest fundamental is the one a frame of the largest EI allowed has:
  // EI grows as f^2 when every section is scaled alike.
  Design stiffest{Implement::paper_racquet(0.70, 0.25, 0.8)};
  stiffest.stiffness.EI_N_m2 = kMaxEI_N_m2;
  const double highest = evaluate(stiffest, Fidelity::kModal).modal->fundamental_free_Hz;
  Design d{Implement::paper_racquet(0.70, 0.25, 0.8)};
  d.stiffness.fundamental_free_Hz = highest * (1.0 - 1e-6);
  CHECK_NOTHROW(evaluate(d, Fidelity::kModal));
  d.stiffness.fundamental_free_Hz = highest * (1.0 + 1e-6);
  CHECK_THROWS_WITH(evaluate(d, Fidelity::kModal),
                    Catch::StartsWith("frame/fundamental_free_Hz: must be in (0, ") &&
                        Catch::Contains("for the frame's EI to stay at most 1e+12 N m^2"));
}

TEST_CASE("A profile's sections are each its own circle or tube") {
  using Shape = CrossSection::Shape;
  const std::vector<ProfileStation> uniform{{0.0, 0.05}, {0.72, 0.05}};
  for (const double wall : {0.0, 0.004}) {
    INFO("wall " << wall);
    const Design profile = round_rod(uniform, wall);
    Design sized = profile;
    sized.stiffness.cross_section =
        wall == 0.0
            ? CrossSection{.shape = Shape::kCircle, .diameter_m = 0.05, .poisson_ratio = 0.35}
            : CrossSection{.shape = Shape::kHollowCircle,
                           .diameter_m = 0.05,
                           .wall_m = wall,
                           .poisson_ratio = 0.35};
    const std::vector<double> a = free_frequencies(profile), b = free_frequencies(sized);
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) CHECK(a[k] == Approx(b[k]).epsilon(kRoundOff));
  }
  const std::vector<ProfileStation> bat{{0.0, 0.025}, {0.3, 0.026}, {0.55, 0.05}, {0.72, 0.064}};
  const Design timoshenko = round_rod(bat);
  Design euler = timoshenko;
  euler.stiffness.shear_modulus_Pa.reset();
  Design stiff = timoshenko;
  stiff.stiffness.shear_modulus_Pa = 1e20;
  const std::vector<double> t = free_frequencies(timoshenko), e = free_frequencies(euler),
                            s = free_frequencies(stiff);
  REQUIRE(t.size() == e.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    CHECK(t[k] < e[k]);
    CHECK(s[k] > t[k]);
  }
  // A design not given by its profile has no slices to take the shape from.
  Design beam = paper_beam();
  beam.stiffness.shear_modulus_Pa = 1e9;
  beam.stiffness.cross_section = CrossSection{.shape = Shape::kProfile};
  CHECK_THROWS_WITH(validate(beam), Catch::Contains("frame/cross_section/shape"));
}

TEST_CASE("A round cross-section gives the modes of the rectangle with its shear and inertia") {
  using Shape = CrossSection::Shape;
  const CrossSection round{.shape = Shape::kCircle, .diameter_m = 0.064, .poisson_ratio = 0.35};
  Design circle = paper_beam();
  // EI given, not solved for a fundamental: the two beams' matrices then
  // differ only by the round-off of kappa G A and r.
  circle.stiffness.fundamental_free_Hz.reset();
  circle.stiffness.EI_N_m2 = 300.0;
  circle.stiffness.shear_modulus_Pa = 1e9;
  circle.stiffness.cross_section = round;
  const TimoshenkoSection t = timoshenko_section(1e9, round);
  // The rectangle of thickness sqrt(12) r, width chosen for the same kappa G A.
  Design rectangle = circle;
  const double thickness = std::sqrt(12.0) * t.radius_of_gyration_m;
  rectangle.stiffness.cross_section = CrossSection{
      .width_m = t.shear_stiffness_N / (kRectangularShearCoefficient * 1e9 * thickness),
      .thickness_m = thickness};
  const auto modes = [](const Design& d) {
    FlexibleFrame frame = flexible_frame(d);
    frame.options.rel_tol = kMinRelTol;
    return free_modes(frame.sections, frame.point_masses, frame.options).modes;
  };
  const std::vector<Mode> a = modes(circle), b = modes(rectangle);
  REQUIRE(a.size() == 3);
  REQUIRE(b.size() == 3);
  for (std::size_t k = 0; k < a.size(); ++k)
    CHECK(a[k].frequency_Hz == Approx(b[k].frequency_Hz).epsilon(1e-12));
  // An ellipse with equal axes is that circle: its area, inertia and Cowper's
  // coefficient (here through the ellipse's expression) are the circle's.
  Design ellipse = circle;
  ellipse.stiffness.cross_section = CrossSection{
      .shape = Shape::kEllipse, .width_m = 0.064, .thickness_m = 0.064, .poisson_ratio = 0.35};
  const std::vector<Mode> e = modes(ellipse);
  REQUIRE(e.size() == 3);
  for (std::size_t k = 0; k < e.size(); ++k)
    CHECK(e[k].frequency_Hz == Approx(a[k].frequency_Hz).epsilon(1e-12));
  Design tube = circle;
  tube.stiffness.cross_section.shape = Shape::kHollowCircle;
  tube.stiffness.cross_section.wall_m = 0.004;
  const std::vector<Mode> c = modes(tube);
  REQUIRE(c.size() == 3);
  for (std::size_t k = 0; k < c.size(); ++k) CHECK(c[k].frequency_Hz < a[k].frequency_Hz);
}

TEST_CASE("With no hand the hand-held modes are the free ones") {
  const ModalOutputs m = evaluate_modes(paper_beam(0.0));
  CHECK(m.fundamental_hand_Hz == m.fundamental_free_Hz);
  CHECK(m.hand_damping_ratio == 0.0);
}

TEST_CASE("The modes need a stiffness and a grip on the implement") {
  Design d = paper_beam();
  d.stiffness.fundamental_free_Hz.reset();
  // Every way of giving it is offered, the spec sheet's RA too.
  CHECK_THROWS_WITH(evaluate_modes(d), Catch::StartsWith("frame/EI_N_m2") &&
                                           Catch::Contains("frame RA") &&
                                           Catch::Contains("fundamental_free_Hz") &&
                                           Catch::Contains("EI_N_m2 for every section"));
  d = paper_beam();
  d.hand.center_from_butt_m = 0.02;  // a 10 cm grip would start 3 cm beyond the butt
  CHECK_THROWS_WITH(evaluate_modes(d), Catch::StartsWith("hand/center_from_butt_m: must be in "
                                                         "[0.05, 0.67] m for the modes"));
}

TEST_CASE("A modal evaluation carries the rigid one unchanged") {
  const Design d = paper_beam();
  const Evaluation rigid = evaluate(d);
  const Evaluation modal = evaluate(d, Fidelity::kModal);
  CHECK_FALSE(rigid.modal.has_value());
  REQUIRE(modal.modal.has_value());
  CHECK(modal.peak_wrist_force_N == rigid.peak_wrist_force_N);
}

TEST_CASE(
    "An evaluation at collision fidelity has evaluate_modes' numbers, bit for bit, its hand-held "
    "mesh the one a coarse estimate sizes") {
  // The collision's free response model lends the modal outputs its exact
  // fundamental (the first root of the same scan a one-mode solve makes), and
  // the hand-held mesh is sized from it: the oracles are a one-mode solve and
  // hand_held_beam_fundamental() sizing its own mesh.
  Design racquet{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  racquet.stiffness.fundamental_free_Hz = 155.0;
  Design taped = racquet;
  taped.implement =
      Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320}, {PointMass{0.6, 0.01}});
  Design stiff = racquet;
  stiff.stiffness.fundamental_free_Hz.reset();
  stiff.stiffness.EI_N_m2 = 300.0;
  Design beam = paper_beam();
  for (Design* d : {&racquet, &taped, &stiff, &beam}) {
    d->impact_from_butt_m = d->implement.length_m() - 0.16;
    d->strings = StringBed{};
    d->cor_given = false;
    const Evaluation e = evaluate(*d, Fidelity::kCollision);
    const ModalOutputs alone = evaluate_modes(*d);
    REQUIRE(e.modal);
    CHECK(e.modal->fundamental_free_Hz == alone.fundamental_free_Hz);
    CHECK(e.modal->node_free_from_butt_m == alone.node_free_from_butt_m);
    CHECK(e.modal->fundamental_hand_Hz == alone.fundamental_hand_Hz);
    CHECK(e.modal->hand_damping_ratio == alone.hand_damping_ratio);
    CHECK(e.modal->node_hand_from_butt_m == alone.node_hand_from_butt_m);
    CHECK(e.modal->hand_elements == alone.hand_elements);

    const FlexibleFrame frame = flexible_frame(*d);
    ModeOptions options = frame.options;
    options.method = ModeOptions::Method::kFiniteElement;
    options.modes = 3;
    const ModalResult held =
        hand_held_beam_fundamental(frame.sections, frame.point_masses, hand_coupling(*d), options);
    REQUIRE(held.modes.size() == 1);
    CHECK(held.elements_used == alone.hand_elements);
    CHECK(held.modes[0].frequency_Hz == alone.fundamental_hand_Hz);
    CHECK(held.modes[0].damping_ratio == alone.hand_damping_ratio);
    CHECK(held.modes[0].nodes_from_butt_m.back() == *alone.node_hand_from_butt_m);
  }
}

}  // namespace
}  // namespace sweetspot

#include "core/beam_modes/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/check.hpp"
#include "sweetspot/errors.hpp"
#include "sweetspot/roots.hpp"

namespace sweetspot::beam_detail {

// Nodes of a mode shape are located to this absolute tolerance [m].
constexpr double kNodeTol_m = 1e-13;

Krylov krylov(double z) {
  if (z < 1.5) {
    // Taylor series in q = z^4; the terms after q^6 are below 1e-19 here.
    const double q = z * z * z * z;
    auto series = [q](const double* c) {
      double sum = c[6];
      for (int k = 5; k >= 0; --k) sum = sum * q + c[k];
      return sum;
    };
    static const auto kCoefficients = [] {
      // kCoefficients[j][k] = 1/(4k + j)!, j = 0..3 for S, T1, U2, V3.
      std::array<std::array<double, 7>, 4> c{};
      for (int j = 0; j < 4; ++j) {
        for (int k = 0; k < 7; ++k) {
          double factorial = 1.0;
          for (int n = 2; n <= 4 * k + j; ++n) factorial *= n;
          c[j][k] = 1.0 / factorial;
        }
      }
      return c;
    }();
    const double* kS = kCoefficients[0].data();
    const double* kT = kCoefficients[1].data();
    const double* kU = kCoefficients[2].data();
    const double* kV = kCoefficients[3].data();
    return {series(kS), series(kT), series(kU), series(kV)};
  }
  const double e = std::exp(z);
  const double ch = 0.5 * (e + 1.0 / e);
  const double sh = 0.5 * (e - 1.0 / e);
  const double c = std::cos(z);
  const double s = std::sin(z);
  const double z2 = z * z;
  return {0.5 * (ch + c), 0.5 * (sh + s) / z, 0.5 * (ch - c) / z2, 0.5 * (sh - s) / (z2 * z)};
}

// w at xi from a piece's start values (see ShapePiece).
double evaluate_piece(const ShapePiece& p, double xi) {
  const Krylov k = krylov(p.wavenumber_per_m * xi);
  const auto& d = p.derivatives;
  return d[0] * k.s + xi * (d[1] * k.t1 + xi * (d[2] * k.u2 + xi * d[3] * k.v3));
}

double normalise_and_find_nodes(Mode& mode) {
  struct Sample {
    std::size_t piece;
    double xi, w;
  };
  std::vector<Sample> samples;
  double w_max = 0.0;
  for (std::size_t i = 0; i < mode.shape.size(); ++i) {
    const ShapePiece& p = mode.shape[i];
    const double length = p.end_m - p.start_m;
    const int intervals =
        std::max(2, static_cast<int>(std::ceil(p.wavenumber_per_m * length / (kPi / 8.0))));
    for (int j = 0; j <= intervals; ++j) {
      const double xi = length * j / intervals;
      const double w = evaluate_piece(p, xi);
      samples.push_back({i, xi, w});
      w_max = std::max(w_max, std::abs(w));
    }
  }
  const double w_tip = samples.back().w;
  double scale = 1.0 / w_max;
  if (w_tip < 0.0) scale = -scale;
  for (ShapePiece& p : mode.shape) {
    for (double& d : p.derivatives) d *= scale;
  }
  mode.nodes_from_butt_m.clear();
  const double x_end = mode.shape.back().end_m;
  auto add_node = [&](double x) {
    if (x <= 0.0 || x >= x_end) return;
    if (!mode.nodes_from_butt_m.empty() && x - mode.nodes_from_butt_m.back() < 1e-9) return;
    mode.nodes_from_butt_m.push_back(x);
  };
  for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
    const Sample& a = samples[k];
    const Sample& b = samples[k + 1];
    const ShapePiece& p = mode.shape[a.piece];
    if (a.w == 0.0) add_node(p.start_m + a.xi);
    if (a.piece != b.piece) continue;  // the same point, end of one piece and start of next
    if ((a.w < 0.0 && b.w > 0.0) || (a.w > 0.0 && b.w < 0.0)) {
      const double xi = brent_root([&](double t) { return evaluate_piece(p, t); }, a.xi, b.xi,
                                   a.w * scale, b.w * scale, kNodeTol_m);
      add_node(p.start_m + xi);
    }
  }
  return scale;
}

namespace {

// A beam mode slower than this (a period of 12 days) is no implement's: its
// stiffness has been given so small against its mass that the arithmetic
// no longer holds the mode (E = 1e-300 Pa gives 0 Hz and a shape of NaN).
constexpr double kMinBeamFrequency_Hz = 1e-6;

[[noreturn]] void refuse_unresolved(double frequency_Hz) {
  throw FieldError(
      "sections/0/EI_N_m2",
      "the bending stiffness is too small for the mass: the beam's modes come out " +
          (std::isfinite(frequency_Hz) ? "at " + detail::format_significant(frequency_Hz) + " Hz"
                                       : std::string("at no finite frequency")) +
          ", below " + detail::format_number(kMinBeamFrequency_Hz) +
          " Hz, where no implement vibrates and the arithmetic does not hold the "
          "mode; give a stiffness of a real frame");
}

}  // namespace

void fill_shape_table(ModalResult& result, double length_m, int samples) {
  const auto beam = [](const Mode& m) { return m.hand_energy_fraction < kHandModeEnergyShare; };
  for (const Mode& m : result.modes) {
    if (beam(m) && !(m.frequency_Hz >= kMinBeamFrequency_Hz && std::isfinite(m.frequency_Hz)))
      refuse_unresolved(m.frequency_Hz);
  }
  if (samples <= 0) return;
  result.shape_x_m.resize(samples);
  for (int i = 0; i < samples; ++i) result.shape_x_m[i] = length_m * i / (samples - 1);
  for (const Mode& m : result.modes) {
    std::vector<double> w(samples);
    for (int i = 0; i < samples; ++i) {
      w[i] = mode_shape_at(m, result.shape_x_m[i]);
      if (beam(m) && !std::isfinite(w[i])) refuse_unresolved(m.frequency_Hz);
    }
    result.shape_w.push_back(std::move(w));
  }
}

}  // namespace sweetspot::beam_detail

#include "reports/modes_report.hpp"

#include <fmt/format.h>

namespace sweetspot::reports {
namespace {

std::string nodes_text(const Mode& mode, double length_m) {
  std::string text;
  for (const double x : mode.nodes_from_butt_m) {
    text += fmt::format("{}{:.4f}", text.empty() ? "" : ", ", length_m - x);
  }
  return text.empty() ? "—" : text;
}

io::Json mode_json(const Mode& mode, double length_m, bool held) {
  io::Json nodes = io::Json::array();
  for (const double x : mode.nodes_from_butt_m)
    nodes.push_back({{"from_butt_m", x}, {"from_tip_m", length_m - x}});
  io::Json j{{"frequency_Hz", mode.frequency_Hz}, {"nodes", nodes}};
  if (held) {
    j["undamped_frequency_Hz"] = mode.undamped_frequency_Hz;
    j["damping_ratio"] = mode.damping_ratio;
    j["hand_energy_fraction"] = mode.hand_energy_fraction;
  }
  return j;
}

// "handle clamped (2-12 cm from the butt)", "on a pivot 15.24 cm from the butt".
std::string rig_words(const studies::ModesData& data) {
  const Support& support = data.design.design.support;
  if (support.kind == Support::Kind::kPivot)
    return fmt::format("on a pivot {:.2f} cm from the butt", 100 * support.pivot_from_butt_m);
  const Hand& hand = data.design.design.hand;
  return fmt::format("handle clamped ({:.1f}-{:.1f} cm from the butt)",
                     100 * (hand.center_from_butt_m - 0.5 * hand.grip_length_m),
                     100 * (hand.center_from_butt_m + 0.5 * hand.grip_length_m));
}

std::string capitalised(std::string text) {
  if (!text.empty() && text[0] >= 'a' && text[0] <= 'z') text[0] = static_cast<char>(text[0] - 32);
  return text;
}

// The centres of percussion are a player's: shown unless on a rig.
bool shows_cops(const studies::ModesData& data) { return !is_rig(data.design.design.support); }

}  // namespace

std::string modes_report(const studies::ModesData& data, io::Format format) {
  const double L = data.design.design.implement.length_m();
  if (format == io::Format::kCsv) {
    std::string csv = "x_from_butt_m";
    for (std::size_t k = 0; k < data.free.shape_w.size(); ++k)
      csv += fmt::format(",free_mode_{}", k + 1);
    for (std::size_t k = 0; k < data.held.shape_w.size(); ++k)
      csv += fmt::format(",hand_mode_{}", k + 1);
    for (std::size_t k = 0; k < data.rig.shape_w.size(); ++k)
      csv += fmt::format(",rig_mode_{}", k + 1);
    csv += "\n";
    for (std::size_t i = 0; i < data.free.shape_x_m.size(); ++i) {
      csv += io::exact(data.free.shape_x_m[i]);
      for (const auto& w : data.free.shape_w) csv += "," + io::exact(w[i]);
      for (const auto& w : data.held.shape_w) csv += "," + io::exact(i < w.size() ? w[i] : 0.0);
      for (const auto& w : data.rig.shape_w) csv += "," + io::exact(i < w.size() ? w[i] : 0.0);
      csv += "\n";
    }
    return csv;
  }
  if (format == io::Format::kJson) {
    io::Json j{
        {"name", data.design.name},
        {"mass_distribution", data.mass_distribution_fitted ? "fitted to the specs" : "given"}};
    j["free"] = io::Json::array();
    for (const Mode& m : data.free.modes) j["free"].push_back(mode_json(m, L, false));
    j["hand_held"] = io::Json::array();
    for (const Mode& m : data.held.modes) j["hand_held"].push_back(mode_json(m, L, true));
    j["free_method"] =
        data.free.method == ModeOptions::Method::kExact ? "exact" : "finite elements";
    j["hand_held_elements"] = data.held.elements_used;
    if (is_rig(data.design.design.support)) {
      j["support"] = to_string(data.design.design.support.kind);
      j["on_rig"] = io::Json::array();
      for (const Mode& m : data.rig.modes) j["on_rig"].push_back(mode_json(m, L, false));
      j["on_rig_elements"] = data.rig.elements_used;
    }
    return j.dump(2, ' ', false, io::Json::error_handler_t::replace) + "\n";
  }
  std::string md = fmt::format("# Vibration modes: {}\n\n", io::md_cell(data.design.name));
  if (data.mass_distribution_fitted) {
    md +=
        "The mass distribution was fitted to the specs (a quadratic density reproducing mass, "
        "balance "
        "and swingweight exactly).\n\n";
  }
  md += fmt::format(
      "## Free ({})\n\n| mode | frequency (Hz) | nodes from the tip (m) |\n|---:|---:|---|\n",
      data.free.method == ModeOptions::Method::kExact
          ? "exact transfer-matrix solution"
          : fmt::format("finite elements, {} elements", data.free.elements_used));
  for (std::size_t k = 0; k < data.free.modes.size(); ++k) {
    md += fmt::format("| {} | {:.2f} | {} |\n", k + 1, data.free.modes[k].frequency_Hz,
                      nodes_text(data.free.modes[k], L));
  }
  if (!data.held.modes.empty()) {
    md += fmt::format(
        "\n## Held in the hand (finite elements, {} elements; damped complex modes)\n\n"
        "| mode | frequency (Hz) | damping ratio | hand's share of the energy | nodes from the tip "
        "(m) |\n"
        "|---:|---:|---:|---:|---|\n",
        data.held.elements_used);
    for (std::size_t k = 0; k < data.held.modes.size(); ++k) {
      const Mode& m = data.held.modes[k];
      md += fmt::format("| {} | {:.2f} | {:.4f} | {:.3f} | {} |\n", k + 1, m.frequency_Hz,
                        m.damping_ratio, m.hand_energy_fraction, nodes_text(m, L));
    }
    md +=
        "\nModes in which the hand carries most of the energy are the hand rocking on the grip; "
        "the "
        "first mode with a small share is the frame's fundamental.\n";
  }
  if (!data.rig.modes.empty()) {
    md += fmt::format(
        "\n## {} (finite elements, {} elements)\n\n| mode | frequency (Hz) | nodes from the tip "
        "(m) |\n|---:|---:|---|\n",
        capitalised(rig_words(data)), data.rig.elements_used);
    for (std::size_t k = 0; k < data.rig.modes.size(); ++k) {
      md += fmt::format("| {} | {:.2f} | {} |\n", k + 1, data.rig.modes[k].frequency_Hz,
                        nodes_text(data.rig.modes[k], L));
    }
    md += data.design.design.support.kind == Support::Kind::kPivot
              ? "\nThe pivot is a node of every mode (w = 0 there, free to turn).\n"
              : "\nThe clamp holds w = w' = 0 over its length; no node is reported inside it.\n";
  }
  if (shows_cops(data) && data.rigid.cop_free_from_butt_m && data.rigid.cop_hand_from_butt_m) {
    md += fmt::format(
        "\nCentres of percussion from the tip: free (axis at the butt) {:.4f} m, hand-held {:.4f} "
        "m.\n",
        L - *data.rigid.cop_free_from_butt_m, L - *data.rigid.cop_hand_from_butt_m);
  }
  return md;
}

io::Plot modes_plot(const studies::ModesData& data) {
  const double L = data.design.design.implement.length_m();
  io::Plot plot{fmt::format("Mode shapes: {}", data.design.name),
                "position from the tip (cm)",
                "displacement w (normalised, max |w| = 1)",
                std::pair{0.0, 100 * L},
                std::pair{-1.1, 1.1},
                {},
                {},
                {}};
  plot.key_position = "outside right";
  const std::size_t wanted = data.free.modes.size();
  const auto add = [&](const ModalResult& result, const char* label, const char* dash,
                       bool skip_hand_modes) {
    std::size_t shown = 0;
    for (std::size_t k = 0; k < result.shape_w.size() && shown < wanted; ++k) {
      if (skip_hand_modes && result.modes[k].hand_energy_fraction >= 0.5) continue;
      ++shown;
      io::PlotSeries s{fmt::format("{} {:.0f} Hz", label, result.modes[k].frequency_Hz),
                       {},
                       {},
                       fmt::format("lines lw 2 {}", dash)};
      for (std::size_t i = 0; i < result.shape_x_m.size(); ++i) {
        s.x.push_back(100 * (L - result.shape_x_m[i]));
        s.y.push_back(result.shape_w[k][i]);
      }
      plot.series.push_back(std::move(s));
    }
  };
  add(data.free, "free", "dt 1", false);
  add(data.held, "hand-held", "dt 2", true);
  add(data.rig, data.design.design.support.kind == Support::Kind::kPivot ? "pivoted" : "clamped",
      "dt 2", false);
  if (shows_cops(data) && data.rigid.cop_free_from_butt_m)
    plot.vertical_lines.push_back({100 * (L - *data.rigid.cop_free_from_butt_m), "COP free"});
  if (shows_cops(data) && data.rigid.cop_hand_from_butt_m)
    plot.vertical_lines.push_back({100 * (L - *data.rigid.cop_hand_from_butt_m), "COP hand-held"});
  if (!data.free.modes.empty() && !data.free.modes[0].nodes_from_butt_m.empty()) {
    plot.vertical_lines.push_back(
        {100 * (L - data.free.modes[0].nodes_from_butt_m.back()), "node (free f1)"});
  }
  return plot;
}

}  // namespace sweetspot::reports

#include "io/format.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <cmath>

#include "io/outputs.hpp"

namespace sweetspot::io {

std::optional<Format> parse_format(std::string_view text) {
  if (text == "md") return Format::kMarkdown;
  if (text == "json") return Format::kJson;
  if (text == "csv") return Format::kCsv;
  return std::nullopt;
}

std::string significant(double value, int digits) {
  if (value == 0.0) return "0";  // no "-0"
  return fmt::format("{:.{}g}", value, digits);
}

std::string exact(double value) { return value == 0.0 ? "0" : fmt::format("{}", value); }

void append_exact(std::string& out, double value) {
  if (value == 0.0) {
    out += '0';
    return;
  }
  // The longest shortest round-trip text of a double is 24 characters
  // ("-2.2250738585072014e-308"); the format is compiled, not parsed per call.
  char buffer[32];
  const char* end = fmt::format_to(buffer, FMT_COMPILE("{}"), value);
  out.append(buffer, static_cast<std::size_t>(end - buffer));
}

std::string md_cell(std::string_view text) {
  std::string cell;
  for (const char c : text) cell += c == '|' ? std::string("\\|") : std::string(1, c);
  return cell;
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

namespace {

Json inputs_json(const DesignFile& file, const Evaluation& e) {
  const Design& d = file.design;
  const auto input = [&](const char* name, double value, const char* unit) {
    const auto it = file.provenance.find(name);
    return Json{{"value", value},
                {"unit", unit},
                {"provenance", it == file.provenance.end() ? "given" : it->second}};
  };
  Json inputs;
  inputs["implement/form"] = file.implement_form;
  inputs["frame/cor"] = input("frame/cor", e.cor, "");
  inputs["strings/impact_duration_s"] =
      input("strings/impact_duration_s", e.impact_duration_s, "s");
  if (d.cor_rigid) inputs["frame/cor_rigid"] = input("frame/cor_rigid", *d.cor_rigid, "");
  if (d.strings)
    inputs["strings/tension_N"] = input("strings/tension_N", d.strings->tension_N, "N");
  inputs["hand/mass_kg"] = input("hand/mass_kg", d.hand.mass_kg, "kg");
  inputs["hand/center_from_butt_m"] =
      input("hand/center_from_butt_m", d.hand.center_from_butt_m, "m");
  inputs["forearm/equivalent_mass_kg"] =
      input("forearm/equivalent_mass_kg", d.forearm_equivalent_mass_kg, "kg");
  inputs["ball/mass_kg"] = input("ball/mass_kg", d.ball.mass_kg, "kg");
  inputs["ball/speed_m_s"] = input("ball/speed_m_s", d.ball.speed_m_s, "m/s");
  inputs["impact/from_butt_m"] = input("impact/from_butt_m", d.impact_from_butt_m, "m");
  return inputs;
}

}  // namespace

Json evaluation_json(const DesignFile& file, const Evaluation& e) {
  Json j;
  j["name"] = file.name;
  j["fidelity"] = to_string(fidelity_of(e));
  if (e.modal)
    j["mass_distribution"] =
        e.modal->mass_distribution_fitted ? "fitted to the specs (quadratic density)" : "given";
  j["inputs"] = inputs_json(file, e);
  Json& outputs = j["outputs"];
  Json notes = Json::object();
  for (const OutputSpec& output : output_specs()) {
    const auto value = output.value(e);
    outputs[std::string(output.name)] = value ? Json(*value) : Json(nullptr);
    if (!value) notes[std::string(output.name)] = output.when_absent;
  }
  const Evaluation::Details details = e.details.value_or(Evaluation::Details{});
  if (!details.fidelity_note.empty()) notes["fidelity"] = details.fidelity_note;
  j["notes"] = notes;
  if (!details.vibration_modes.empty()) {
    j["vibration_modes"] = Json::array();
    for (const auto& [frequency, energy] : details.vibration_modes) {
      j["vibration_modes"].push_back({{"frequency_Hz", frequency}, {"energy_J", energy}});
    }
  }
  return j;
}

std::string evaluation_report(const DesignFile& file, const Evaluation& e, Format format,
                              std::string_view answer) {
  if (format == Format::kJson)
    return evaluation_json(file, e).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
  if (format == Format::kCsv) {
    std::string header = "name";
    std::string row = csv_field(file.name);
    for (const OutputSpec& output : output_specs()) {
      header += "," + std::string(output.name);
      const auto value = output.value(e);
      row += "," + (value ? exact(*value) : std::string());
    }
    return header + "\n" + row + "\n";
  }
  std::string md = fmt::format("# {}\n\n", md_cell(file.name));
  if (!answer.empty()) md += std::string(answer) + "\n\n";
  md += fmt::format(
      "{} of Cross (2004); source `{}`.{}\n\n",
      e.vibration_energy_J ? "Rigid-body model, vibration modes and impact response"
      : e.modal            ? "Rigid-body model and vibration modes"
                           : "Rigid-body model",
      file.source,
      e.modal && e.modal->mass_distribution_fitted
          ? " The mass distribution for the modes was fitted to the specs (quadratic density)."
          : "");
  md += "| output | value | unit | meaning |\n|---|---:|---|---|\n";
  for (const OutputSpec& output : output_specs()) {
    if (output.needs_modes && !output.value(e)) continue;
    const auto value = output.value(e);
    md += fmt::format(
        "| `{}` | {} | {} | {} |\n", output.name, value ? significant(*value) : std::string("—"),
        output.unit,
        md_cell(value ? std::string(output.description)
                      : std::string(output.description) + "; " + std::string(output.when_absent)));
  }
  if (!e.modal) {
    md += "\nVibration modes: not evaluated (rigid fidelity; they need the frame's stiffness).\n";
  }
  const Evaluation::Details details = e.details.value_or(Evaluation::Details{});
  if (!details.vibration_modes.empty()) {
    md +=
        "\nEnergy each mode of the free frame keeps after the impact:\n\n| mode | frequency (Hz) | "
        "energy (J) |\n|---:|---:|---:|\n";
    for (std::size_t k = 0; k < details.vibration_modes.size(); ++k) {
      md += fmt::format("| {} | {:.1f} | {} |\n", k + 1, details.vibration_modes[k].first,
                        significant(details.vibration_modes[k].second, 4));
    }
  }
  if (!details.fidelity_note.empty()) md += "\nNote: " + details.fidelity_note + ".\n";
  md += "\nInputs (SI; *default* values are Cross (2004) Table I, top row):\n\n";
  const Json inputs = inputs_json(file, e);
  for (const auto& [name, input] : inputs.items()) {
    if (!input.is_object()) continue;
    md += fmt::format("- `{}` = {} {} ({})\n", name, significant(input["value"].get<double>()),
                      input["unit"].get<std::string>(), input["provenance"].get<std::string>());
  }
  return md;
}

}  // namespace sweetspot::io

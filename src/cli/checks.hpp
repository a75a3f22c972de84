#pragma once

// Checks of numeric command-line values, shared by every subcommand: a value
// given on the command line is refused there, named as the option it is
// ("--tol: expected a number in [1e-08, 0.1], got nan"), never passed on for
// a design file to be blamed.

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_error.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::cli {

// `text` as a finite double, or why it is not one ("" when it is).
inline std::string parse_finite(std::string_view text, double& value) {
  const auto first = text.find_first_not_of(" \t");
  const auto last = text.find_last_not_of(" \t");
  const std::string_view number =
      first == std::string_view::npos ? std::string_view() : text.substr(first, last - first + 1);
  const char* end = number.data() + number.size();
  const auto [stop, error] = std::from_chars(number.data(), end, value);
  if (number.empty() || error == std::errc::invalid_argument || stop != end) return "not a number";
  if (error == std::errc::result_out_of_range || !std::isfinite(value))
    return "not a finite number";
  return "";
}

// A CLI11 check that a value names a fidelity (kFidelityNames: every level
// and "auto"), so that a new level is accepted wherever a level is asked.
inline CLI::Validator fidelity_name() {
  return CLI::IsMember(std::vector<std::string>(kFidelityNames.begin(), kFidelityNames.end()));
}

// A CLI11 check that a value is a finite number in [min, max], the bounds
// in their shortest form ("1e-08", not "0.000000").
inline CLI::Validator finite_in(double min, double max) {
  const std::string range = fmt::format("[{}, {}]", min, max);
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        double value = 0.0;
        if (!parse_finite(text, value).empty() || value < min || value > max) {
          return fmt::format("expected a number in {}, got {}", range,
                             text.empty() ? "nothing" : io::one_line(text));
        }
        return "";
      },
      "NUMBER in " + range);
}

// The same for a whole number in [min, max].
inline CLI::Validator whole_in(long min, long max) {
  const std::string range = fmt::format("[{}, {}]", min, max);
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        long value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc() || stop != end || value < min || value > max) {
          return fmt::format("expected a whole number in {}, got {}", range,
                             text.empty() ? "nothing" : io::one_line(text));
        }
        return "";
      },
      "INTEGER in " + range);
}

// A comma-separated list of finite numbers given to `option` ("0.1,0.2");
// an empty item or one that is not a finite number is a ValidationError
// naming the option and the item.
inline std::vector<double> number_list(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::size_t item = 1;
  for (std::size_t start = 0;; ++item) {
    const std::size_t comma = text.find(',', start);
    const std::string_view piece = std::string_view(text).substr(
        start, comma == std::string::npos ? std::string::npos : comma - start);
    double value = 0.0;
    if (piece.find_first_not_of(" \t") == std::string_view::npos) {
      throw CLI::ValidationError(option,
                                 fmt::format("an empty point (item {} of \"{}\"; expected numbers "
                                             "separated by commas)",
                                             item, io::one_line(text)));
    }
    if (const std::string why = parse_finite(piece, value); !why.empty()) {
      throw CLI::ValidationError(
          option, fmt::format("item {} \"{}\" is {}", item, io::one_line(piece), why));
    }
    values.push_back(value);
    if (comma == std::string::npos) return values;
    start = comma + 1;
  }
}

// `--set FIELD=VALUE`, repeatable, one item per occurrence: a field of the
// design set as a catalogue's column would (studies/design_settings.hpp).
inline CLI::Option* add_set_option(CLI::App* command, std::vector<std::string>& settings) {
  return command
      ->add_option("--set", settings,
                   "Set a design field for this run, as a catalogue's column names it, in any "
                   "unit the design file accepts (repeatable): --set impact.off_axis_cm=3 "
                   "--set strings.tension_lb=48")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace sweetspot::cli

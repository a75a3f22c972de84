#pragma once

// The model against the published numbers its shipped designs set up: each
// design file with a "reference" block (published values of named outputs and
// their source) evaluated as it stands, output by output. The numbers of
// reports/fidelity.md (reports/fidelity_report.hpp writes them).

#include <optional>
#include <string>
#include <vector>

namespace sweetspot::studies {

struct FidelityRow {
  std::string design;           // the file, relative to the designs folder
  std::string title;            // the design's name
  std::string output;           // an output of evaluate (outputs.hpp)
  std::string unit;             // the output's
  double published = 0.0;       // the reference's value, in the output's unit
  std::optional<double> model;  // evaluate()'s at the design's own fidelity; none: not given
  std::string fidelity;         // the fidelity it was evaluated at
  std::string source;           // the reference's "source"
};

// Every shipped design under `designs_dir` (its folders table1/, lab/,
// racquets/ and the files at its top) with a reference, each referenced
// output a row, sorted by file. A reference key that is not an output is
// not a row.
std::vector<FidelityRow> fidelity_rows(const std::string& designs_dir);

}  // namespace sweetspot::studies

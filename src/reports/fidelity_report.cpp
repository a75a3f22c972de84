#include "reports/fidelity_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "io/format.hpp"

namespace sweetspot::reports {

namespace {

// The model's error over the published value, in per cent ("" without a model value).
std::string error_percent(const studies::FidelityRow& row) {
  if (!row.model || row.published == 0.0) return "";
  const double percent = 100.0 * (*row.model - row.published) / row.published;
  return std::abs(percent) < 0.05 ? "0.0" : fmt::format("{:+.1f}", percent);
}

}  // namespace

std::vector<ReportEntry> write_fidelity_report(const std::vector<studies::FidelityRow>& rows,
                                               const ReportWriter& write) {
  std::string md =
      "# Fidelity: the model against the published numbers\n\n"
      "Each row is a published number that a shipped design file sets up (its `reference` "
      "block), the model's value for that design as `sweetspot evaluate` gives it, and the "
      "error. The same quantity on both sides: a rig's number for a rig, a racquet at rest "
      "for a racquet at rest. The ball's own measurements against both contact laws (the "
      "slow ITF test, the pulse's rise, the squeeze on strings) are tabled in "
      "[docs/model.md](../docs/model.md#the-ball).\n\n"
      "| design | quantity | unit | published | model | error (%) | fidelity | source |\n"
      "|---|---|---|---:|---:|---:|---|---|\n";
  std::string csv = "design,output,unit,published,model,error_percent,fidelity,source\n";
  int worst_row = -1;
  double worst = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const studies::FidelityRow& r = rows[i];
    // People's units in the table (ms, mm, cm), SI in the CSV.
    const io::PeopleUnit unit = io::people_unit(r.unit, r.output);
    const std::string model = r.model ? io::significant(*r.model * unit.factor, 4) : "—";
    const std::string error = error_percent(r);
    md += fmt::format("| [{}](../designs/{}) | `{}` | {} | {} | {} | {} | {} | {} |\n", r.design,
                      r.design, r.output, unit.unit, io::significant(r.published * unit.factor, 4),
                      model, error, r.fidelity, io::md_cell(r.source));
    csv += io::csv_field(r.design) + "," + r.output + "," + io::csv_field(r.unit) + "," +
           io::significant(r.published) + "," + (r.model ? io::significant(*r.model) : "") + "," +
           error + "," + r.fidelity + "," + io::csv_field(r.source) + "\n";
    if (r.model && r.published != 0.0) {
      const double relative = std::abs(*r.model / r.published - 1.0);
      if (relative > worst) worst = relative, worst_row = static_cast<int>(i);
    }
  }
  std::string says = fmt::format(
      "{} published numbers set up by the shipped designs against the "
      "model's",
      rows.size());
  if (worst_row >= 0) {
    const studies::FidelityRow& r = rows[worst_row];
    says += fmt::format("; the furthest, {} of {}, {:+.0f} %", r.output, r.design,
                        100.0 * (*r.model / r.published - 1.0));
  }
  write.text("fidelity.md", md);
  write.text("fidelity.csv", csv);
  return {{"[fidelity.md](fidelity.md), [.csv](fidelity.csv)", says}};
}

}  // namespace sweetspot::reports

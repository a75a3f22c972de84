#include "studies/fidelity.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "io/design_reader.hpp"
#include "io/outputs.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {

namespace fs = std::filesystem;

std::vector<FidelityRow> fidelity_rows(const std::string& designs_dir) {
  std::vector<fs::path> files;
  const fs::path top(designs_dir);
  for (const auto& entry : fs::directory_iterator(top))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  for (const char* folder : {"table1", "lab", "racquets"}) {
    const fs::path dir = top / folder;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<FidelityRow> rows;
  for (const fs::path& path : files) {
    const io::DesignFile file = io::load_design(path.string());
    if (!file.reference.is_object()) continue;
    const Fidelity fidelity = resolve_fidelity(file.fidelity, file.design);
    const Evaluation e = io::evaluate_design_file(file, "", 1e-6);
    const std::string source =
        file.reference.contains("source") && file.reference["source"].is_string()
            ? file.reference["source"].get<std::string>()
            : "";
    for (const auto& [key, value] : file.reference.items()) {
      const io::OutputSpec* spec = io::find_output(key);
      if (!spec || !value.is_number()) continue;
      FidelityRow row;
      row.design = fs::relative(path, top).generic_string();
      row.title = file.name;
      row.output = key;
      row.unit = std::string(spec->unit);
      row.published = value.get<double>();
      row.model = spec->value(e);
      row.fidelity = std::string(to_string(fidelity));
      row.source = source;
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace sweetspot::studies

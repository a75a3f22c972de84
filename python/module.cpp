// `import sweetspot`: the library in Python (docs/python.md). Every function
// reads its design as `sweetspot` reads a design file and answers with the
// numbers the command line prints, as Python values and NumPy arrays; the
// physics runs without the GIL.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "convert.hpp"
#include "errors.hpp"
#include "evaluate_many.hpp"
#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "io/parallel.hpp"
#include "reports/modes_report.hpp"
#include "reports/optimization_report.hpp"
#include "reports/tune_report.hpp"
#include "studies/catalogue_header.hpp"
#include "studies/modes.hpp"
#include "studies/optimization.hpp"
#include "studies/string_bed_map.hpp"
#include "studies/study.hpp"
#include "studies/sweet_spots.hpp"
#include "studies/tune.hpp"
#include "sweetspot/beam_modes.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif
#include "sweetspot/evaluate.hpp"

namespace py = pybind11;

namespace sweetspot::python {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The checks the command line's options make, with their words.
std::string checked_fidelity(const std::optional<std::string>& fidelity) {
  if (!fidelity) return "";
  if (*fidelity == "auto" || parse_fidelity(*fidelity)) return *fidelity;
  throw py::value_error(
      "fidelity: expected rigid, modal, response, collision or auto (or None: the design's "
      "own), got " +
      io::one_line(*fidelity));
}

double checked_tolerance(double tol) {
  if (!(tol >= kMinRelTol && tol <= kMaxRelTol)) {
    throw py::value_error("tol: must be in [" + io::exact(kMinRelTol) + ", " +
                          io::exact(kMaxRelTol) + "], got " + io::exact(tol));
  }
  return tol;
}

int checked_threads(const std::optional<int>& threads) {
  if (!threads) return io::all_cores();
  if (*threads < 1 || *threads > 1024)
    throw py::value_error("threads: must be in [1, 1024], got " + std::to_string(*threads));
  return *threads;
}

py::array_t<double> array_of(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

#if defined(__linux__)
// The memory of evaluate_many()'s fresh outputs of a megabyte and more (131 072
// rows; a million rows is 8 MB an output): each a mapping of its own, aligned to and
// advised into 2 MB pages (madvise(MADV_HUGEPAGE), honoured where the kernel
// offers transparent huge pages on request), and, when its array is freed,
// kept for the next call's outputs rather than given back. A fresh page costs
// a fault and its zeroing, which for five million-row outputs on a virtual
// machine took longer than the rows' arithmetic (35 ms against 9 ms); a
// notebook that evaluates catalogues of one size again and again pays it once.
// At most kMaxKept mappings and kMaxKeptBytes are kept; the rest are unmapped.
// Used under the GIL only (arrays are made and freed with it held).
class OutputMemory {
 public:
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  static constexpr std::size_t kMaxKept = 16;
  static constexpr std::size_t kMaxKeptBytes = std::size_t{256} << 20;

  // n doubles' worth, 2 MB aligned, or nullptr (then an ordinary array).
  static double* take(std::size_t n, py::capsule& owner) {
    const std::size_t length = (n * sizeof(double) + 2 * kHugePage - 1) / kHugePage * kHugePage;
    std::vector<Mapping>& kept = kept_mappings();
    Mapping* mapping = nullptr;
    const auto same = std::find_if(kept.begin(), kept.end(),
                                   [&](const Mapping& m) { return m.length == length; });
    if (same != kept.end()) {
      mapping = new Mapping(*same);
      kept.erase(same);
    } else {
      void* start =
          mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (start == MAP_FAILED) return nullptr;
      mapping = new Mapping{start, length};
#if defined(MADV_HUGEPAGE)
      madvise(mapping->aligned(), length - kHugePage, MADV_HUGEPAGE);  // a hint: may fail
#endif
    }
    owner = py::capsule(mapping, [](void* p) { give_back(static_cast<Mapping*>(p)); });
    return static_cast<double*>(mapping->aligned());
  }

 private:
  struct Mapping {
    void* start;
    std::size_t length;  // a whole number of huge pages, one more than the data needs
    void* aligned() const {
      const auto base = reinterpret_cast<std::uintptr_t>(start);
      return reinterpret_cast<void*>((base + kHugePage - 1) & ~std::uintptr_t{kHugePage - 1});
    }
  };
  static std::vector<Mapping>& kept_mappings() {
    static auto* kept = new std::vector<Mapping>();  // never destroyed: freed at exit
    return *kept;
  }
  static void give_back(Mapping* mapping) {
    std::vector<Mapping>& kept = kept_mappings();
    std::size_t bytes = mapping->length;
    for (const Mapping& m : kept) bytes += m.length;
    if (kept.size() < kMaxKept && bytes <= kMaxKeptBytes) {
      kept.push_back(*mapping);
    } else {
      munmap(mapping->start, mapping->length);
    }
    delete mapping;
  }
};
#endif

// A new, uninitialised float64 array of n elements for evaluate_many()'s
// outputs: from OutputMemory from 1 MB up, else (or where it has none) NumPy's.
// From 1 MB, not 2: an output of 1 to 2 MB (a catalogue of 200 000 rows) had
// from NumPy a fresh mapping of 4 kB pages on every call until glibc's
// threshold for them grew, each page a fault; in one huge page it costs one,
// for at most twice its memory.
py::array_t<double> fresh_array(std::size_t n) {
#if defined(__linux__)
  if (n * sizeof(double) >= OutputMemory::kHugePage / 2) {
    py::capsule owner;
    if (double* data = OutputMemory::take(n, owner)) {
      return py::array_t<double>({static_cast<py::ssize_t>(n)}, {py::ssize_t{sizeof(double)}}, data,
                                 owner);
    }
  }
#endif
  return py::array_t<double>(static_cast<py::ssize_t>(n));
}

py::object optional_float(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

io::DesignFile read_design_of(py::handle design) {
  const Document document = read_document(design);
  return io::read_design(document.json, document.source);
}

// ------------------------------------------------------------ evaluate

py::object evaluate_py(py::handle design, const std::optional<std::string>& fidelity, double tol) {
  const std::string name = checked_fidelity(fidelity);
  checked_tolerance(tol);
  const Document document = read_document(design);
  std::optional<io::DesignFile> file;
  std::optional<Evaluation> evaluation;
  {
    py::gil_scoped_release release;
    file.emplace(io::read_design(document.json, document.source));
    evaluation.emplace(
        studies::with_power_point(*file, io::evaluate_design_file(*file, name, tol), tol));
  }
  return evaluation_dict(*file, *evaluation);
}

// ------------------------------------------------------------ evaluate_many

// The caller's array for output `name` of n rows, if `out` holds one: a
// writable, contiguous float64 array of n elements, or InputError naming it.
std::optional<py::array_t<double>> out_array(const std::optional<py::dict>& out,
                                             std::string_view name, std::size_t n) {
  if (!out) return std::nullopt;
  const py::str key{std::string(name)};
  if (!out->contains(key)) return std::nullopt;
  const py::handle given = (*out)[key];
  const std::string where = "out[" + studies::shown(name) + "]";
  if (!py::isinstance<py::array>(given))
    throw io::InputError("out", "", where + ": expected a NumPy array of float64");
  const auto array = py::reinterpret_borrow<py::array>(given);
  if (!array.dtype().is(py::dtype::of<double>()) || array.ndim() != 1 ||
      !(array.flags() & py::array::c_style) || !array.writeable()) {
    throw io::InputError("out", "",
                         where + ": expected a writable, contiguous 1-D array of float64, got " +
                             py::str(array.dtype()).cast<std::string>() + " of " +
                             std::to_string(array.ndim()) + " dimension(s)");
  }
  if (static_cast<std::size_t>(array.shape(0)) != n) {
    throw io::InputError("out", "",
                         where + ": " + std::to_string(array.shape(0)) + " elements, expected " +
                             std::to_string(n) + " as the columns' rows");
  }
  return py::reinterpret_borrow<py::array_t<double>>(array);
}

// The rows' error column, read-only: each failed row's message, '' for the
// others. Without a failed row it is one '' seen by every row (no memory per row).
py::array error_column(std::size_t n, const RowErrors& errors) {
  const py::str empty("");
  if (errors.empty()) {
    py::array one(py::dtype("O"), std::vector<py::ssize_t>{1});
    PyObject** slot = static_cast<PyObject**>(one.mutable_data());
    Py_XDECREF(slot[0]);
    slot[0] = empty.inc_ref().ptr();
    py::array every(py::dtype("O"), std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)},
                    std::vector<py::ssize_t>{0}, one.data(), one);
    every.attr("setflags")(py::arg("write") = false);
    return every;
  }
  py::array error(py::dtype("O"), std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)});
  PyObject** slots = static_cast<PyObject**>(error.mutable_data());
  for (std::size_t i = 0; i < n; ++i) {
    Py_XDECREF(slots[i]);
    slots[i] = empty.inc_ref().ptr();
  }
  for (const auto& [row, message] : errors) {
    PyObject* text =
        PyUnicode_DecodeUTF8(message.data(), static_cast<Py_ssize_t>(message.size()), "replace");
    if (!text) throw py::error_already_set();
    Py_XDECREF(slots[row]);
    slots[row] = text;
  }
  error.attr("setflags")(py::arg("write") = false);
  return error;
}

py::dict evaluate_many_py(py::handle base, py::handle columns,
                          const std::optional<std::string>& fidelity,
                          const std::optional<int>& threads, double tol,
                          const std::optional<std::vector<std::string>>& wanted,
                          const std::optional<py::dict>& out) {
  ManyOptions options;
  options.fidelity = checked_fidelity(fidelity);
  options.modal_tolerance = checked_tolerance(tol);
  options.threads = checked_threads(threads);
  const std::span<const io::OutputSpec> specs = io::output_specs();
  if (wanted) {
    if (wanted->empty()) throw io::InputError("outputs", "", "expected at least one output name");
    for (const std::string& name : *wanted) {
      const auto at = std::find_if(specs.begin(), specs.end(),
                                   [&](const io::OutputSpec& s) { return s.name == name; });
      if (at == specs.end()) {
        throw io::InputError(
            "outputs", "",
            "unknown output " + studies::shown(name) + ": expected a name of sweetspot.outputs()");
      }
      const auto k = static_cast<std::size_t>(at - specs.begin());
      if (std::find(options.outputs.begin(), options.outputs.end(), k) != options.outputs.end())
        throw io::InputError("outputs", "", "output " + studies::shown(name) + " given twice");
      options.outputs.push_back(k);
    }
  } else {
    for (std::size_t k = 0; k < specs.size(); ++k) options.outputs.push_back(k);
  }
  const Document document = read_document(base);
  // The base is checked once, as `--base` is: a design on its own.
  if (!document.json.is_object() || !document.json.contains("implement")) {
    throw io::InputError(document.source, "/implement",
                         "missing: the base design needs an implement");
  }
  {
    py::gil_scoped_release release;
    io::evaluate_design_file(io::read_design(document.json, document.source), "", tol);
  }
  // The columns: a dict or anything with items() (a pandas DataFrame), each
  // value an array of numbers, read in place when it is float64.
  if (!py::hasattr(columns, "items"))
    throw py::type_error("columns: expected a dict (or a DataFrame) of dotted names to arrays");
  std::vector<py::array_t<double>> arrays;
  std::vector<Column> cols;
  std::optional<std::size_t> rows;
  for (const py::handle item : columns.attr("items")()) {
    const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
    if (!PyUnicode_Check(pair[0].ptr()))
      throw py::type_error("columns: expected str keys, the dotted names of design fields");
    const std::string field = pair[0].cast<std::string>();
    // Numbers only, as a design file's: NumPy would take a bool as 1, a
    // complex number's real part, a masked array's hidden values and an
    // object column's None as nan.
    {
      const py::module_ numpy = py::module_::import("numpy");
      if (py::isinstance(pair[1], numpy.attr("ma").attr("MaskedArray"))) {
        throw io::InputError("columns", "",
                             "column " + studies::shown(field) +
                                 ": expected an array of numbers, got a masked array (fill or "
                                 "drop its masked rows first)");
      }
      py::object as_array;
      try {
        as_array = numpy.attr("asarray")(pair[1]);
      } catch (const py::error_already_set&) {
        // Not an array at all (ragged, say): refused below as before.
      }
      const char kind = as_array ? as_array.attr("dtype").attr("kind").cast<char>() : 'f';
      if (kind != 'f' && kind != 'i' && kind != 'u') {
        throw io::InputError("columns", "",
                             "column " + studies::shown(field) +
                                 ": expected an array of numbers (float or int), got " +
                                 py::str(as_array.attr("dtype")).cast<std::string>() + " values");
      }
    }
    py::array_t<double> array;
    try {
      array = py::array_t<double, py::array::forcecast>::ensure(pair[1]);
    } catch (const py::error_already_set&) {
      array = {};
    }
    if (!array) {
      PyErr_Clear();
      throw io::InputError(
          "columns", "",
          "column " + studies::shown(field) + ": expected an array of numbers, got a " +
              py::str(py::type::handle_of(pair[1]).attr("__name__")).cast<std::string>());
    }
    if (array.ndim() > 1) {
      throw io::InputError("columns", "",
                           "column " + studies::shown(field) + ": expected one dimension, got " +
                               std::to_string(array.ndim()));
    }
    Column column{field, array.data(), 0};
    if (array.ndim() == 1) {
      if (array.strides(0) % static_cast<py::ssize_t>(sizeof(double)) != 0)
        array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
      column.data = array.data();
      column.stride = array.strides(0) / static_cast<py::ssize_t>(sizeof(double));
      const auto n = static_cast<std::size_t>(array.shape(0));
      if (rows && *rows != n) {
        throw io::InputError("columns", "",
                             "column " + studies::shown(field) + ": " + std::to_string(n) +
                                 " rows, expected " + std::to_string(*rows) +
                                 " as the columns before it");
      }
      rows = n;
    }
    arrays.push_back(std::move(array));
    cols.push_back(std::move(column));
  }
  const std::size_t n = rows.value_or(1);
  std::vector<py::array_t<double>> outputs;
  std::vector<double*> pointers;
  for (std::size_t k = 0; k < options.outputs.size(); ++k) {
    auto given = out_array(out, specs[options.outputs[k]].name, n);
    outputs.push_back(given ? std::move(*given) : fresh_array(n));
    pointers.push_back(outputs.back().mutable_data());
  }
  if (out) {
    for (const auto& [key, value] : *out) {
      const std::string name = py::str(key).cast<std::string>();
      const bool asked = std::any_of(options.outputs.begin(), options.outputs.end(),
                                     [&](std::size_t k) { return specs[k].name == name; });
      if (!asked) {
        throw io::InputError(
            "out", "",
            "out[" + studies::shown(name) + "]: not an output asked for (outputs= or outputs())");
      }
    }
    // An output written over another, or over a column still to be read, is refused.
    const auto bytes = [](const double* data, std::ptrdiff_t stride, std::size_t count) {
      const double* last = data + static_cast<std::ptrdiff_t>(count ? count - 1 : 0) * stride;
      return std::pair{std::min(data, last), std::max(data, last) + 1};
    };
    const auto overlap = [](std::pair<const double*, const double*> a,
                            std::pair<const double*, const double*> b) {
      return std::less<>()(a.first, b.second) && std::less<>()(b.first, a.second);
    };
    for (std::size_t a = 0; a < pointers.size(); ++a) {
      const auto range = bytes(pointers[a], 1, n);
      const std::string name = "out[" + studies::shown(specs[options.outputs[a]].name) + "]";
      for (std::size_t b = a + 1; b < pointers.size(); ++b) {
        if (overlap(range, bytes(pointers[b], 1, n)))
          throw io::InputError("out", "", name + ": shares memory with another output");
      }
      for (const Column& column : cols) {
        if (overlap(range, bytes(column.data, column.stride, n))) {
          throw io::InputError(
              "out", "", name + ": shares memory with the column " + studies::shown(column.field));
        }
      }
    }
  }
  RowErrors errors;
  {
    py::gil_scoped_release release;
    evaluate_columns(document.json, cols, n, options, pointers, errors);
  }
  py::dict result;
  for (std::size_t k = 0; k < options.outputs.size(); ++k)
    result[py::str(std::string(specs[options.outputs[k]].name))] = outputs[k];
  py::array_t<bool> ok(static_cast<py::ssize_t>(n));
  std::fill_n(ok.mutable_data(), n, true);
  for (const auto& error : errors) ok.mutable_data()[error.first] = false;
  result["ok"] = ok;
  result["error"] = error_column(n, errors);
  return result;
}

// ------------------------------------------------------------ modes, collide, map

py::array_t<double> shapes_of(const ModalResult& result) {
  const auto modes = static_cast<py::ssize_t>(result.shape_w.size());
  const auto points = static_cast<py::ssize_t>(result.shape_x_m.size());
  py::array_t<double> out({modes, points});
  for (py::ssize_t k = 0; k < modes; ++k) {
    for (py::ssize_t i = 0; i < points; ++i) {
      const auto& row = result.shape_w[static_cast<std::size_t>(k)];
      out.mutable_at(k, i) =
          static_cast<std::size_t>(i) < row.size() ? row[static_cast<std::size_t>(i)] : kNaN;
    }
  }
  return out;
}

py::object modes_py(py::handle design, int count, double tol, const std::string& method) {
  if (count < 1 || count > kMaxExactModes) {
    throw py::value_error("count: must be in [1, " + std::to_string(kMaxExactModes) + "], got " +
                          std::to_string(count));
  }
  checked_tolerance(tol);
  if (method != "exact" && method != "fe")
    throw py::value_error("method: expected exact or fe, got " + io::one_line(method));
  const io::DesignFile file = read_design_of(design);
  std::optional<studies::ModesData> data;
  std::string text;
  {
    py::gil_scoped_release release;
    data.emplace(studies::compute_modes(
        file, count, tol,
        method == "fe" ? ModeOptions::Method::kFiniteElement : ModeOptions::Method::kExact));
    text = reports::modes_report(*data, io::Format::kJson);
  }
  py::dict result(to_python(io::parse_json(text, "modes")));
  result["free_x_m"] = array_of(data->free.shape_x_m);
  result["free_shapes"] = shapes_of(data->free);
  result["hand_held_x_m"] = array_of(data->held.shape_x_m);
  result["hand_held_shapes"] = shapes_of(data->held);
  if (!data->rig.modes.empty()) {
    result["on_rig_x_m"] = array_of(data->rig.shape_x_m);
    result["on_rig_shapes"] = shapes_of(data->rig);
  }
  return result;
}

py::dict collide_py(py::handle design, double tol) {
  checked_tolerance(tol);
  const io::DesignFile file = read_design_of(design);
  std::optional<Evaluation> e;
  {
    py::gil_scoped_release release;
    e = studies::with_power_point(file, io::evaluate_design_file(file, "collision", tol), tol);
  }
  const CollisionResult& r = e->details.value().collision.value();
  py::dict out;
  out["separated"] = r.separated;
  out["contacts"] = r.contacts;
  out["contact_time_s"] = r.contact_time_s;
  out["in_contact_s"] = r.in_contact_s;
  out["peak_force_N"] = r.peak_force_N;
  out["peak_ball_compression_m"] = r.peak_ball_compression_m;
  out["peak_string_deflection_m"] = r.peak_string_deflection_m;
  out["impulse_N_s"] = r.impulse_N_s;
  out["ball_velocity_after_m_s"] = r.ball_velocity_after_m_s;
  out["frame_velocity_after_m_s"] = r.frame_velocity_after_m_s;
  out["implement_momentum_N_s"] = r.implement_momentum_N_s;
  out["apparent_cor"] = r.apparent_cor;
  out["mode_energy_J"] = array_of(r.mode_energy_J);
  out["string_bed_energy_J"] = r.string_bed_energy_J;
  out["ball_in_J"] = r.ball_in_J;
  out["ball_out_J"] = r.ball_out_J;
  out["implement_rigid_J"] = r.implement_rigid_J;
  out["vibration_J"] = r.vibration_J;
  out["modal_damping_loss_J"] = r.modal_damping_loss_J;
  out["ball_loss_J"] = r.ball_loss_J;
  out["strings_loss_J"] = r.strings_loss_J;
  out["step_s"] = r.step_s;
  out["steps"] = r.steps;
  out["step_error"] = r.step_error;
  out["time_s"] = array_of(r.time_s);
  out["force_N"] = array_of(r.force_N);
  out["evaluation"] = evaluation_dict(file, *e);
  return out;
}

py::dict string_bed_map_py(py::handle design, int columns, int rows,
                           const std::optional<std::string>& fidelity,
                           const std::optional<int>& threads) {
  const std::string name = checked_fidelity(fidelity);
  const io::DesignFile file = read_design_of(design);
  studies::StringBedMapOptions options;
  options.columns = columns;
  options.rows = rows;
  options.threads = checked_threads(threads);
  studies::StringBedMap map;
  {
    py::gil_scoped_release release;
    try {
      // As `sweetspot map` takes it: the response model's feel is the modal one.
      const std::string wanted = name.empty() ? file.fidelity : name;
      options.fidelity = resolve_fidelity(wanted == "response" ? "modal" : wanted, file.design);
      if (options.fidelity == Fidelity::kResponse) options.fidelity = Fidelity::kModal;
      map = studies::string_bed_map(file.design, options);
    } catch (const std::invalid_argument& e) {
      io::rethrow_in(file, e);
    }
  }
  const std::vector<py::ssize_t> shape{map.rows, map.columns};
  py::array_t<double> x(shape), y(shape), mass(shape), cor(shape), wrist(shape), twist(shape),
      feel(shape);
  py::array_t<bool> on_bed(shape);
  for (std::size_t k = 0; k < map.points.size(); ++k) {
    const studies::StringBedMapPoint& p = map.points[k];
    x.mutable_data()[k] = p.from_butt_m;
    y.mutable_data()[k] = p.off_axis_m;
    on_bed.mutable_data()[k] = p.on_bed;
    mass.mutable_data()[k] = p.on_bed ? p.effective_mass_kg : kNaN;
    cor.mutable_data()[k] = p.on_bed ? p.apparent_cor : kNaN;
    wrist.mutable_data()[k] = p.on_bed ? p.peak_wrist_force_N : kNaN;
    twist.mutable_data()[k] = p.on_bed ? p.peak_twist_torque_N_m : kNaN;
    feel.mutable_data()[k] = p.on_bed ? p.vibration_energy_J.value_or(kNaN) : kNaN;
  }
  py::dict out;
  out["from_butt_m"] = x;
  out["off_axis_m"] = y;
  out["on_bed"] = on_bed;
  out["effective_mass_kg"] = mass;
  out["apparent_cor"] = cor;
  out["peak_wrist_force_N"] = wrist;
  out["peak_twist_torque_N_m"] = twist;
  out["vibration_energy_J"] = feel;
  py::dict bed;
  bed["center_from_butt_m"] = map.bed.center_from_butt_m;
  bed["semi_length_m"] = map.bed.semi_length_m;
  bed["semi_width_m"] = map.bed.semi_width_m;
  out["bed"] = bed;
  out["polar_inertia_kg_m2"] = map.polar_inertia_kg_m2;
  out["polar_inertia_estimated"] = map.polar_inertia_estimated;
  out["cop_hand_from_butt_m"] = optional_float(map.cop_hand_from_butt_m);
  out["node_free_from_butt_m"] = optional_float(map.node_free_from_butt_m);
  out["fidelity"] = std::string(to_string(map.fidelity));
  return out;
}

// ------------------------------------------------------------ optimize

py::dict optimize_py(py::handle study_value, const std::optional<int>& threads) {
  const Document document = read_document(study_value);
  studies::Study study = studies::read_study(document.json, document.source, document.folder);
  study.options.threads = checked_threads(threads);
  std::optional<studies::OptimizationResult> result;
  std::string report;
  {
    py::gil_scoped_release release;
    result.emplace(studies::run_optimization(study));
    report = reports::optimization_report(study, *result, io::Format::kJson, false);
  }
  const studies::OptimizationResult& r = *result;
  py::dict out;
  out["name"] = study.name;
  out["outcome"] = r.outcome == studies::Outcome::kOptimum      ? "optimum"
                   : r.outcome == studies::Outcome::kInfeasible ? "infeasible"
                                                                : "no_value";
  py::list variables;
  for (const studies::StudyVariable& v : study.variables) variables.append(v.pointer);
  out["variables"] = variables;
  out["start_x"] = array_of(r.start_x);
  out["x"] = array_of(r.summary.x);
  out["objective"] = r.summary.objective;
  out["start_objective"] = optional_float(r.start_objective);
  py::list constraints;
  for (const studies::ConstraintReport& c : r.constraints) {
    py::dict d;
    d["name"] = c.name;
    d["unit"] = c.unit;
    d["value"] = optional_float(c.value);
    d["limit"] = c.limit;
    d["tolerance"] = c.tolerance;
    d["violation"] = c.violation;
    d["satisfied"] = c.satisfied;
    d["active"] = c.active;
    constraints.append(d);
  }
  out["constraints"] = constraints;
  out["feasible"] = r.summary.feasible;
  out["evaluations"] = r.summary.evaluations;
  out["seconds"] = r.summary.seconds;
  out["algorithm"] = r.summary.algorithm;
  out["termination"] = r.summary.termination_text();
  out["history"] = array_of(r.summary.history);
  out["violation_history"] = array_of(r.summary.violation_history);
  out["best_design"] = to_python(r.best_document);
  out["best"] = r.best_outputs ? py::object(evaluation_dict(r.best, *r.best_outputs))
                               : py::object(py::none());
  out["start"] = r.start_outputs ? py::object(evaluation_dict(r.start, *r.start_outputs))
                                 : py::object(py::none());
  out["inconsistency"] = r.inconsistency;
  out["report"] = to_python(io::parse_json(report, "report"));
  return out;
}

py::list outputs_py() {
  py::list list;
  for (const io::OutputSpec& o : io::output_specs()) {
    py::dict d;
    d["name"] = std::string(o.name);
    d["unit"] = std::string(o.unit);
    d["description"] = std::string(o.description);
    d["when_absent"] = std::string(o.when_absent);
    d["needs_modes"] = o.needs_modes;
    d["needs_response"] = o.needs_response;
    list.append(d);
  }
  return list;
}

// ------------------------------------------------------------ tune

// A str argument's UTF-8, refused as `name` when it holds what UTF-8 cannot
// (a lone surrogate) or is not a str.
std::string utf8_argument(py::handle value, const char* name, const char* expected) {
  Py_ssize_t size = 0;
  const char* text =
      PyUnicode_Check(value.ptr()) ? PyUnicode_AsUTF8AndSize(value.ptr(), &size) : nullptr;
  if (!text) {
    PyErr_Clear();
    throw io::InputError(name, "",
                         std::string("expected ") + expected + ", got " +
                             io::brief(io::valid_utf8(py::repr(value).cast<std::string>())));
  }
  return std::string(text, static_cast<std::size_t>(size));
}

// A list given as a str ("12,3/9,handle") or as a sequence of str, each one
// item, as the command line's comma-separated text.
std::string comma_text(py::handle value, const char* name) {
  if (PyUnicode_Check(value.ptr())) return utf8_argument(value, name, "a str or a list of str");
  if (!py::isinstance<py::sequence>(value))
    throw io::InputError(
        name, "",
        "expected a str or a list of str, got a " +
            py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
  std::string text;
  for (const py::handle item : value) {
    const std::string one = utf8_argument(item, name, "a str or a list of str");
    if (one.find(',') != std::string::npos)
      throw io::InputError(name, "", "a list's item holds a comma, got " + io::brief(one));
    if (!text.empty()) text += ',';
    text += one;
  }
  return text;
}

// The targets given as a dict ({"mass_g": 330}) or the command line's text.
std::string target_text(py::handle value) {
  if (!PyDict_Check(value.ptr())) return comma_text(value, "target");
  std::string text;
  for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
    const std::string name = utf8_argument(key, "target", "a dict of a spec's name and a number");
    if (name.find_first_of(",=") != std::string::npos)
      throw io::InputError("target", "", "a spec's name holds ',' or '=', got " + io::brief(name));
    // Any real number (NumPy's too), not a bool or a str.
    PyObject* number = PyNumber_Check(item.ptr()) && !PyBool_Check(item.ptr())
                           ? PyNumber_Float(item.ptr())
                           : nullptr;
    if (!number) {
      PyErr_Clear();
      throw io::InputError("target", "",
                           "expected a dict of a spec's name and a number, got " + name + ": " +
                               io::brief(io::valid_utf8(py::repr(item).cast<std::string>())));
    }
    const double x = PyFloat_AsDouble(number);
    Py_DECREF(number);
    if (!text.empty()) text += ',';
    text += name + "=" + fmt::format("{}", x);
  }
  return text;
}

// A study's complaint about an argument, as the command line words it for its option.
template <typename F>
auto as_input_error(const char* name, F f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    std::string detail = e.what();
    for (const std::string prefix : {"--target: ", "--places: "}) {
      if (detail.starts_with(prefix)) {
        const std::string option = prefix.substr(2, prefix.size() - 4);
        throw io::InputError(option, "", detail.substr(prefix.size()));
      }
    }
    throw io::InputError(name, "", detail);
  }
}

py::dict specs_dict(const studies::RacquetSpecs& specs) {
  py::dict d;
  d["mass_kg"] = specs.mass_kg;
  d["balance_from_butt_m"] = specs.balance_from_butt_m;
  d["swingweight_kg_m2"] = specs.swingweight_kg_m2;
  d["twistweight_kg_m2"] = optional_float(specs.twistweight_kg_m2);
  return d;
}

py::dict tune_py(py::handle design, py::handle target, py::handle places, py::handle like,
                 double strip_g, double tol) {
  checked_tolerance(tol);
  if (!(strip_g >= 0.01 && strip_g <= 100.0))
    throw io::InputError("strip_g", "",
                         "must be in [0.01, 100] g, got " + fmt::format("{}", strip_g));
  const Document document = read_document(design);
  const io::DesignFile file = io::read_design(document.json, document.source);
  const std::vector<studies::LeadPlace> lead_places = as_input_error(
      "places", [&] { return studies::parse_lead_places(comma_text(places, "places")); });
  studies::TuneTargets targets;
  // An empty dict asks for nothing beyond `like`'s specs.
  const bool no_target = target.is_none() || (PyDict_Check(target.ptr()) && py::len(target) == 0);
  if (!no_target)
    targets =
        as_input_error("target", [&] { return studies::parse_tune_targets(target_text(target)); });
  if (!like.is_none()) {
    std::optional<io::DesignFile> other_file;
    try {
      other_file.emplace(read_design_of(like));
    } catch (const io::InputError& e) {
      throw io::InputError("like " + e.source(), e.pointer(), e.detail());  // not the design's
    }
    const studies::TuneTargets other =
        studies::targets_from(studies::specs_of(other_file->design), false);
    if (!targets.mass_kg) targets.mass_kg = other.mass_kg;
    if (!targets.has_balance()) targets.balance_from_butt_m = other.balance_from_butt_m;
    if (!targets.swingweight_kg_m2) targets.swingweight_kg_m2 = other.swingweight_kg_m2;
  }
  if (targets.empty())
    throw io::InputError("target", "", "give the specs to reach (or like=another design)");
  std::optional<studies::TuneResult> result;
  io::Json tuned;
  std::string report;
  {
    py::gil_scoped_release release;
    result.emplace(
        as_input_error("target", [&] { return studies::tune(file, targets, lead_places); }));
    tuned = studies::tuned_document(document.json, *result);
    studies::TuneEvaluations evaluations =
        studies::evaluate_tune(file, tuned, file.source + " (tuned)", tol);
    const reports::TunedRacquet racquet{*result, std::move(evaluations.before),
                                        std::move(evaluations.after), ""};
    report = reports::tune_report({racquet}, strip_g * 1e-3, io::Format::kJson);
  }
  const studies::TuneResult& r = *result;
  py::dict out;
  out["exact"] = r.exact;
  out["added_kg"] = r.added_kg;
  out["before"] = specs_dict(r.before);
  out["reached"] = specs_dict(r.reached);
  py::dict wanted;
  wanted["mass_kg"] = optional_float(r.targets.mass_kg);
  wanted["balance_from_butt_m"] = optional_float(r.targets.balance_from_butt_m);
  wanted["swingweight_kg_m2"] = optional_float(r.targets.swingweight_kg_m2);
  wanted["twistweight_kg_m2"] = optional_float(r.targets.twistweight_kg_m2);
  out["targets"] = wanted;
  py::list lead;
  for (const studies::PlacedLead& placed : r.lead) {
    py::dict d;
    d["place"] = placed.place.label;
    d["mass_kg"] = placed.mass_kg;
    py::list pieces;
    for (const PointMass& piece : placed.pieces) {
      py::dict p;
      p["from_butt_m"] = piece.from_butt_m;
      p["off_axis_m"] = piece.off_axis_m;
      p["mass_kg"] = piece.mass_kg;
      pieces.append(p);
    }
    d["pieces"] = pieces;
    lead.append(d);
  }
  out["lead"] = lead;
  py::list misses;
  for (const studies::TargetMiss& miss : r.misses) {
    py::dict d;
    d["spec"] = miss.spec;
    d["reason"] = miss.reason;
    misses.append(d);
  }
  out["misses"] = misses;
  out["tuned_design"] = r.exact ? to_python(tuned) : py::object(py::none());
  out["report"] = to_python(io::parse_json(report, "report"));
  return out;
}

}  // namespace
}  // namespace sweetspot::python

PYBIND11_MODULE(sweetspot, m) {
  using namespace sweetspot::python;
  m.doc() =
      "sweetspot: where a ball should hit a racquet, bat or any hand-held implement, and what\n"
      "the hand feels when it does not (R. Cross, Am. J. Phys. 72, 622 (2004)).\n\n"
      "A design is a dict, a JSON text or the path of a design file, in the units its keys\n"
      "name (docs/design-files.md); every function reads it as `sweetspot evaluate` reads a\n"
      "file and answers in SI units, the unit at the end of each name (peak_wrist_force_N).\n"
      "Bad input raises InputError (a ValueError) with the command line's words; a design the\n"
      "model refuses raises ModelRefusal. See docs/python.md.";
  m.attr("__version__") = SWEETSPOT_VERSION;
  register_errors(m);

  m.def("evaluate", &evaluate_py, py::arg("design"), py::arg("fidelity") = py::none(),
        py::arg("tol") = 1e-6,
        R"(Every output of one design: the dict `sweetspot evaluate --format json` prints.

design: a dict, a JSON text (a str starting with '{') or the path of a design file.
fidelity: 'rigid', 'modal', 'response', 'collision' or 'auto' (the cheapest that answers
    the design); None (default): the design's own "fidelity", as the command line without
    --fidelity.
tol: the hand-held modes' relative frequency error, in [1e-8, 0.1] (--tol).

Returns {'name', 'inputs', 'outputs', 'notes', ...}: outputs in SI units named by their
unit (peak_wrist_force_N in N, cop_hand_from_tip_m in m, swingweight_kg_m2 in kg m^2),
None where the design's fidelity gives no value (notes say why); the same keys and the
same doubles, bit for bit, as the command line.

Raises InputError at the JSON path of a bad value, ModelRefusal (exit status 3 on the
command line) when the model cannot answer.)");

  m.def("evaluate_many", &evaluate_many_py, py::arg("base"), py::arg("columns"),
        py::arg("fidelity") = py::none(), py::arg("threads") = py::none(), py::arg("tol") = 1e-6,
        py::arg("outputs") = py::none(), py::arg("out") = py::none(),
        R"(Many designs at once: a base design and columns of numbers, as `sweetspot evaluate
--batch CATALOGUE.csv --base BASE.json` evaluates a catalogue.

base: a design (dict, JSON text or path) giving every row's defaults; it must be a design
    on its own (an implement, every value valid), as --base.
columns: a dict (or a pandas DataFrame) whose keys are the dotted names of a catalogue's
    header ('implement.mass_kg', 'impact.from_tip_m', 'strings.tension_lb': the suffix is
    the unit of the values) and whose values are 1-D arrays of numbers of one length (a
    scalar stands for every row). float64 arrays are read in place, any stride; others
    are converted once.
fidelity: as evaluate(); None: the base's own.
threads: threads the rows are shared among (--threads); None (default): every core. The
    GIL is released while the rows are evaluated.
tol: as evaluate().
outputs: the names of the outputs wanted (of outputs()); None (default): every one. Rigid
    rows of a design in the paper's parametrisation (length, mass, head-to-handle ratio)
    asking only for effective_mass_kg, apparent_cor, rebound_speed_m_s, impulse_N_s,
    peak_impact_force_N, wrist_force_ratio, peak_wrist_force_N, cor or impact_duration_s
    are evaluated column-wise, a block of rows at a time (the same numbers, bit for bit).
out: a dict of output names to arrays the outputs are written into (writable, contiguous
    float64, one element per row, sharing no memory with a column or each other), as
    NumPy's out=: a loop over many calls reuses its arrays instead of fresh memory.

Returns a dict: for each output wanted (every output of evaluate(), outputs(), by default)
a float64 array, one value per row, in its SI unit (NaN where the output is None or the
row failed), the array of `out` where given; 'ok', a bool array; 'error', a read-only object
array holding each failed row's message ('row 7: /implement/mass_kg: must be in ..., got
...', the command line's words) and '' for the others. A bad row never
raises. Raises InputError naming 'columns' for a name that is no design field (or is given
twice or in two units), arrays of different lengths, and for the base.)");

  m.def("modes", &modes_py, py::arg("design"), py::arg("count") = 3, py::arg("tol") = 1e-6,
        py::arg("method") = "exact",
        R"(The frame's vibration modes, free and held in the hand: `sweetspot modes --format json`.

design: a design with the frame's stiffness (frame.EI_N_m2, frame.RA, ...).
count: flexible modes, in [1, 6] (--modes).
tol: the finite elements' relative frequency error, in [1e-8, 0.1] (--tol).
method: 'exact' (transfer matrices) or 'fe' for the free modes (--method).

Returns the command line's dict ('free' and 'hand_held': lists of modes with frequency_Hz,
nodes from the butt and the tip in m, ...) and the mode shapes: 'free_x_m' (points along
the implement from the butt, m), 'free_shapes' (modes x points, max |w| = 1), and
'hand_held_x_m', 'hand_held_shapes'. On a rig that lets the frame vibrate (support
'handle_clamped' or a pivot) also 'support', 'on_rig' (its modes), 'on_rig_x_m' and
'on_rig_shapes', and no hand-held modes.)");

  m.def("collide", &collide_py, py::arg("design"), py::arg("tol") = 1e-6,
        R"(The solved collision of ball, strings and frame (fidelity 'collision').

design: a design with a string tension and the frame's stiffness, and no COR.
tol: the modes' relative frequency error, in [1e-8, 0.1].

Returns a dict: contact_time_s (s), peak_force_N (N), apparent_cor, impulse_N_s (N s),
ball_velocity_after_m_s (m/s, < 0 rebounding), the energy ledger in J (ball_in_J,
ball_out_J, implement_rigid_J, vibration_J, ball_loss_J, strings_loss_J, ...),
mode_energy_J (J, one per mode), the force history 'time_s' and 'force_N' (arrays), and
'evaluation', evaluate(design, 'collision').)");

  m.def("string_bed_map", &string_bed_map_py, py::arg("design"), py::arg("columns") = 50,
        py::arg("rows") = 50, py::arg("fidelity") = py::none(), py::arg("threads") = 1,
        R"(Power, shock and feel over the string bed: `sweetspot map`.

design: a design whose polar inertia is known (a twistweight or a head).
columns, rows: grid points along the long axis and across it, each in [2, 1000].
fidelity: 'rigid' (power and shock), 'modal' (also the vibration energy), 'collision', or
    None: the design's own (as `sweetspot map` without --fidelity).
threads: threads the grid is shared among (the map is the same whatever their number).

Returns 2-D arrays (rows x columns, x fastest): from_butt_m and off_axis_m (m, > 0 towards
3 o'clock), on_bed (bool), effective_mass_kg (kg), apparent_cor, peak_wrist_force_N (N),
peak_twist_torque_N_m (N m), vibration_energy_J (J; NaN off the bed or where the model gives
none); the ellipse 'bed' (m), polar_inertia_kg_m2, cop_hand_from_butt_m and
node_free_from_butt_m (m, or None), and the fidelity used.)");

  m.def("optimize", &optimize_py, py::arg("study"), py::arg("threads") = py::none(),
        R"(Runs a study's optimisation: `sweetspot optimize STUDY.json`.

study: a study as a dict, JSON text or path (docs/studies.md); a relative "design" path
    is resolved from the study file's folder (from the working folder for a dict).
threads: threads for independent evaluations (--threads); None: every core. The answer is
    the same whatever their number.

Returns a dict: 'outcome' ('optimum', 'infeasible' or 'no_value'), 'variables' (their JSON
pointers), 'x' and 'start_x' (arrays, in each variable's unit), 'objective' and
'start_objective', 'constraints' (a dict each: name, unit, value, limit, tolerance,
violation, satisfied, active), 'history' and 'violation_history' (the best objective and
its violation after each evaluation, arrays), 'evaluations', 'seconds', 'termination',
'best_design' (the design file of the answer, as a dict evaluate() takes), 'best' and
'start' (their evaluate() dicts), and 'report' (`sweetspot optimize --format json`).)");

  m.def("tune", &tune_py, py::arg("design"), py::arg("target") = py::none(), py::kw_only(),
        py::arg("places"), py::arg("like") = py::none(), py::arg("strip_g") = 1.0,
        py::arg("tol") = 1e-6,
        R"(The least lead tape, and where, that brings a racquet to target specs: `sweetspot tune
DESIGN --target ... --places ...`.

design: a design as a dict, JSON text or path.
target: the specs to reach, a dict of a design file's spelling and a number
    ({"mass_g": 330, "balance_cm": 32, "swingweight_kg_cm2": 330}; twistweight_kg_cm2 too,
    the balance in cm or m from the butt, or balance_pts_hl) or the command line's text
    ("mass_g=330,balance_cm=32"); None: only those of `like`.
places: where lead may go, a str ("12,3/9,grip") or a list of str: clock hours on the
    hoop (a pair 3/9 takes half at each; the design needs its head size), throat, grip
    (under the grip, 9 cm from the butt), handle or butt (under the butt cap, 2 cm from it).
like: another design whose mass, balance and swingweight to reach (target wins for the
    specs it names).
strip_g: the strip of tape the report counts the lead in, in [0.01, 100] g (1 g: about
    10 cm of 1/4-inch tape).
tol: as evaluate(), for the report's hand-held frequency.

Returns a dict: 'exact' (every target reached), 'added_kg', 'before', 'reached' and
'targets' (mass_kg, balance_from_butt_m, swingweight_kg_m2, twistweight_kg_m2; None where
not known or not asked), 'lead' (one dict per place: place, mass_kg, pieces with
from_butt_m, off_axis_m and mass_kg), 'misses' (spec and reason, when not exact),
'tuned_design' (the design file with the lead as point masses, a dict evaluate() takes;
None when not exact) and 'report' (`sweetspot tune --format json`). Lead only adds mass:
a target below the racquet's own is reported as a miss, not an error.)");

  m.def("outputs", &outputs_py,
        R"(Every output of evaluate(), in report order: a dict each with its name, SI unit
('' when dimensionless), a one-line description, why it can be None, and whether it needs
the modes or the response model.)");
}

#include "convert.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string_view>
#include <unordered_map>

#include "io/evaluation_tree.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"

namespace py = pybind11;

namespace sweetspot::python {
namespace {

std::string type_name(py::handle value) {
  return py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
}

// Where a value sits in the document: its parent's place and its key (or
// index). Written out as a JSON pointer only for an error message.
struct Place {
  const Place* parent = nullptr;
  std::string_view key;   // a dict's key, or
  std::size_t index = 0;  // a list's index when key is empty and is_index
  bool is_index = false;
};

std::string pointer_of(const Place* place) {
  if (!place || !place->parent) return "";
  std::string pointer = pointer_of(place->parent);
  pointer += '/';
  pointer += place->is_index ? std::to_string(place->index) : io::escape_pointer_token(place->key);
  return pointer;
}

// A str's text as UTF-8, without a copy where Python keeps it.
std::string_view utf8_of(py::handle text) {
  Py_ssize_t size = 0;
  const char* data = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
  if (!data) throw py::error_already_set();
  return {data, static_cast<std::size_t>(size)};
}

io::Json to_json(py::handle value, const std::string& source, const Place& place, int depth) {
  if (depth > io::kMaxJsonDepth) {
    throw io::InputError(source, pointer_of(&place),
                         fmt::format("nested deeper than {} levels", io::kMaxJsonDepth));
  }
  if (value.is_none()) return nullptr;
  if (PyBool_Check(value.ptr())) return value.ptr() == Py_True;
  if (PyLong_Check(value.ptr())) {
    int overflow = 0;
    const long long n = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
    if (overflow == 0) return static_cast<std::int64_t>(n);
    const unsigned long long u = PyLong_AsUnsignedLongLong(value.ptr());
    if (PyErr_Occurred()) {
      PyErr_Clear();
      throw io::InputError(source, pointer_of(&place),
                           "expected a number a JSON document can hold, got an integer of " +
                               std::to_string(py::int_(value.attr("bit_length")()).cast<long>()) +
                               " bits");
    }
    return static_cast<std::uint64_t>(u);
  }
  if (PyFloat_Check(value.ptr())) {
    const double x = PyFloat_AsDouble(value.ptr());
    if (!std::isfinite(x)) {
      throw io::InputError(source, pointer_of(&place),
                           "expected a finite number, got " + py::repr(value).cast<std::string>());
    }
    return x;
  }
  if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
  if (PyDict_Check(value.ptr())) {
    io::Json object = io::Json::object();
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!PyUnicode_Check(key.ptr())) {
        throw io::InputError(source, pointer_of(&place),
                             "expected keys that are str, got the " + type_name(key) + " " +
                                 py::repr(key).cast<std::string>());
      }
      const std::string_view name = utf8_of(key);
      const Place child{&place, name};
      object.emplace(std::string(name), to_json(item, source, child, depth + 1));
    }
    return object;
  }
  if (PyList_Check(value.ptr()) || PyTuple_Check(value.ptr())) {
    io::Json array = io::Json::array();
    std::size_t i = 0;
    for (const py::handle item : value) {
      const Place child{&place, {}, i++, true};
      array.push_back(to_json(item, source, child, depth + 1));
    }
    return array;
  }
  // A NumPy array or scalar is the Python value it holds (item(): a 0-d array's
  // or a scalar's bool, int, float or complex; tolist(): an array's list), so
  // np.bool_ stays a bool and np.array(0.3) a float, read as the rest.
  if (py::isinstance<py::array>(value)) {
    const py::object held = py::reinterpret_borrow<py::object>(value).attr(
        py::reinterpret_borrow<py::array>(value).ndim() == 0 ? "item" : "tolist")();
    return to_json(held, source, place, depth);
  }
  if (py::hasattr(value, "dtype") && py::hasattr(value, "item") && !py::hasattr(value, "__len__"))
    return to_json(py::reinterpret_borrow<py::object>(value).attr("item")(), source, place, depth);
  // Other integer types have __index__, other floating ones __float__.
  if (py::hasattr(value, "__index__"))
    return to_json(py::reinterpret_borrow<py::object>(value).attr("__index__")(), source, place,
                   depth);
  if (py::hasattr(value, "__float__") && !py::hasattr(value, "__len__")) {
    PyObject* number = PyNumber_Float(value.ptr());
    if (!number) throw py::error_already_set();
    return to_json(py::reinterpret_steal<py::object>(number), source, place, depth);
  }
  throw io::InputError(source, pointer_of(&place),
                       "expected a JSON value (dict, list, str, int, float, bool or None), got a " +
                           type_name(value));
}

py::str text_of(std::string_view text) {
  PyObject* decoded =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace");
  if (!decoded) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(decoded);
}

// The str of a text an evaluation's dict repeats from call to call (its keys,
// units, provenances, notes), made once and shared: most of evaluate()'s
// dict is these. Used with the GIL held, which guards the table (one per
// process: the module runs in the main interpreter). A design's own texts
// (its name) take entries too; past kSharedTexts entries, and for texts past
// kSharedTextLength, each str is made anew: a cost, never another str.
constexpr std::size_t kSharedTextLength = 256;
constexpr std::size_t kSharedTexts = 4096;
py::str shared_text(std::string_view text) {
  if (text.size() > kSharedTextLength) return text_of(text);
  // Never freed: the module's strs live as long as the interpreter.
  struct Hash {
    using is_transparent = void;
    std::size_t operator()(std::string_view t) const { return std::hash<std::string_view>{}(t); }
  };
  static auto* table = new std::unordered_map<std::string, py::str, Hash, std::equal_to<>>();
  // In front of the table, a cache by the text's address and length: most
  // texts are the same literals and tables' strings call after call, so a hit
  // costs a comparison of the text with the entry's, not a hash of it. A text
  // at an address another held before compares unequal and takes the table.
  struct Recent {
    const char* data = nullptr;
    std::size_t size = 0;
    const std::string* text = nullptr;  // the table's key (never freed)
    PyObject* str = nullptr;            // the table's str (never freed)
  };
  constexpr std::size_t kRecent = 1024;  // a power of two
  static auto* recent = new std::array<Recent, kRecent>();
  const auto address = reinterpret_cast<std::uintptr_t>(text.data());
  Recent& slot = (*recent)[((address >> 3) ^ (address >> 13) ^ text.size()) & (kRecent - 1)];
  if (slot.data == text.data() && slot.size == text.size() && *slot.text == text)
    return py::reinterpret_borrow<py::str>(slot.str);
  auto it = table->find(text);
  if (it == table->end()) {
    py::str made = text_of(text);
    if (table->size() >= kSharedTexts) return made;
    it = table->emplace(std::string(text), std::move(made)).first;
  }
  slot = Recent{text.data(), text.size(), &it->first, it->second.ptr()};
  return it->second;
}

// io::write_evaluation()'s node for a Python dict.
class DictNode {
 public:
  explicit DictNode(py::dict dict) : dict_(std::move(dict)) {}
  void number(std::string_view key, double value) { set(key, py::float_(value)); }
  void integer(std::string_view key, std::int64_t value) { set(key, py::int_(value)); }
  void text(std::string_view key, std::string_view value) { set(key, shared_text(value)); }
  void null(std::string_view key) { set(key, py::none()); }
  void numbers(std::string_view key, const std::vector<double>& values) {
    py::list list(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) list[i] = py::float_(values[i]);
    set(key, list);
  }
  void json_number(std::string_view key, const io::Json& value) { set(key, to_python(value)); }
  DictNode object(std::string_view key) {
    py::dict child;
    set(key, child);
    return DictNode(std::move(child));
  }
  class List {
   public:
    explicit List(py::list list) : list_(std::move(list)) {}
    DictNode object() {
      py::dict child;
      list_.append(child);
      return DictNode(std::move(child));
    }

   private:
    py::list list_;
  };
  List list(std::string_view key) {
    py::list child;
    set(key, child);
    return List(std::move(child));
  }

 private:
  void set(std::string_view key, const py::handle value) {
    if (PyDict_SetItem(dict_.ptr(), shared_text(key).ptr(), value.ptr()) != 0)
      throw py::error_already_set();
  }
  py::dict dict_;
};

}  // namespace

py::dict evaluation_dict(const io::DesignFile& file, const Evaluation& evaluation) {
  py::dict root;
  DictNode node(root);
  io::write_evaluation(node, file, evaluation);
  return root;
}

Document read_document(py::handle value) {
  Document document;
  if (PyDict_Check(value.ptr())) {
    document.source = "<dict>";
    document.json = to_json(value, document.source, Place{}, 1);
    return document;
  }
  if (PyUnicode_Check(value.ptr())) {
    const std::string text = value.cast<std::string>();
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '{') {
      document.source = "<JSON text>";
      document.json = io::parse_json(text, document.source);
      return document;
    }
  }
  if (PyUnicode_Check(value.ptr()) || py::hasattr(value, "__fspath__")) {
    const std::string path = py::module_::import("os").attr("fspath")(value).cast<std::string>();
    document.source = io::input_name(path);
    document.json = io::read_json_file(path);
    document.folder = std::filesystem::path(path).parent_path().string();
    return document;
  }
  throw py::type_error("expected a design as a dict, a JSON text or a path, got a " +
                       type_name(value));
}

py::object to_python(const io::Json& value) {
  switch (value.type()) {
    case io::Json::value_t::null:
      return py::none();
    case io::Json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case io::Json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case io::Json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case io::Json::value_t::number_float:
      return py::float_(value.get<double>());
    case io::Json::value_t::string: {
      const std::string& text = value.get_ref<const std::string&>();
      PyObject* decoded =
          PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace");
      if (!decoded) throw py::error_already_set();
      return py::reinterpret_steal<py::object>(decoded);
    }
    case io::Json::value_t::array: {
      py::list list(value.size());
      std::size_t i = 0;
      for (const io::Json& item : value) list[i++] = to_python(item);
      return list;
    }
    case io::Json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = to_python(item);
      return dict;
    }
    default:
      return py::none();  // binary and discarded values: never in an evaluation's JSON
  }
}

}  // namespace sweetspot::python

#include "errors.hpp"

#include <stdexcept>
#include <string>

#include "io/input_error.hpp"
#include "sweetspot/invariants.hpp"

namespace py = pybind11;

namespace sweetspot::python {
namespace {

PyObject* input_error = nullptr;
PyObject* model_refusal = nullptr;

// A message's detail split where the value is named: "must be in [0, 1e+06]
// kg, got -0.5 kg" is expected "must be in [0, 1e+06] kg", value "-0.5 kg".
// A detail that names no value is all `expected`, and the value None.
void raise(PyObject* type, const std::string& message, const std::string& source,
           const std::string& pointer, const std::string& detail) {
  py::object error = py::reinterpret_borrow<py::object>(type)(io::one_line(message));
  error.attr("source") = py::str(source);
  error.attr("path") = py::str(pointer);
  error.attr("detail") = py::str(detail);
  const std::size_t got = detail.rfind(", got ");
  if (got != std::string::npos) {
    error.attr("expected") = py::str(detail.substr(0, got));
    error.attr("value") = py::str(detail.substr(got + 6));
  } else {
    error.attr("expected") = py::str(detail);
    error.attr("value") = py::none();
  }
  PyErr_SetObject(type, error.ptr());
}

PyObject* new_type(py::module_& module, const char* name, PyObject* base, const char* doc) {
  const std::string qualified = std::string("sweetspot.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (!type) throw py::error_already_set();
  module.add_object(name, py::reinterpret_borrow<py::object>(type));
  return type;
}

}  // namespace

void register_errors(py::module_& module) {
  input_error =
      new_type(module, "InputError", PyExc_ValueError,
               "Bad input: a design, study or column that is not what it should be (exit status\n"
               "2 on the command line). str() is the command line's message, 'SOURCE: PATH:\n"
               "DETAIL'.\n\n"
               "Attributes: source (the file, '<dict>' or '<JSON text>'), path (the JSON\n"
               "pointer, '' for the whole document), detail (the words after the path),\n"
               "expected (what was expected) and value (the value as the message shows it, or\n"
               "None when the detail names none).");
  model_refusal =
      new_type(module, "ModelRefusal", PyExc_RuntimeError,
               "Every input is in range, but the evaluation broke an invariant of its fidelity:\n"
               "the model refuses to answer rather than give a wrong number (exit status 3 on the\n"
               "command line). The same attributes as InputError, naming the input that took the\n"
               "design outside the model's valid range.");
  py::register_exception_translator([](std::exception_ptr pointer) {
    if (!pointer) return;
    try {
      std::rethrow_exception(pointer);
    } catch (const io::InputError& e) {
      raise(e.model_refused() ? model_refusal : input_error, e.what(), e.source(), e.pointer(),
            e.detail());
    } catch (const ModelRefusal& e) {
      raise(model_refusal, e.what(), "", "/" + e.field(), e.detail());
    } catch (const io::ReadError& e) {
      PyErr_SetString(PyExc_OSError, io::one_line(e.what()).c_str());
    } catch (const std::invalid_argument& e) {
      raise(input_error, e.what(), "", "", e.what());
    }
  });
}

}  // namespace sweetspot::python

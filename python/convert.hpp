#pragma once

// Python values to and from the JSON documents the io layer reads and writes:
// a design or a study given as a dict, a path or a JSON text; an evaluation's
// JSON object as the dict `sweetspot evaluate --format json` prints.

#include <pybind11/pybind11.h>

#include <string>

#include "io/design_reader.hpp"
#include "io/json_reader.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::python {

// A document named `source` in messages, read from a Python value: a dict
// (its values str, int, float, bool, None, lists and dicts), a JSON text (a
// str starting with '{' after blanks) or a path (str or os.PathLike), read
// as `sweetspot` reads the file (io::read_json_file). Throws io::InputError
// at the value's JSON path for what a JSON document cannot hold (a key that
// is not a str, a NaN, an object of another type).
struct Document {
  io::Json json;
  std::string source;  // "<dict>", "<JSON text>" or the file, as messages name it
  std::string folder;  // where a path's relative references are resolved ("" for the others)
};
Document read_document(pybind11::handle value);

// A JSON value as Python: objects as dict, arrays as list, numbers as int or
// float (the same double), strings decoded as UTF-8 (an invalid byte as
// U+FFFD, as the JSON writer replaces it), null as None.
pybind11::object to_python(const io::Json& value);

// The dict `sweetspot evaluate --format json` prints for an evaluation
// (io::write_evaluation() into Python objects directly: the same keys and the
// same doubles, with no JSON document between). Needs the GIL.
pybind11::dict evaluation_dict(const io::DesignFile& file, const Evaluation& evaluation);

}  // namespace sweetspot::python

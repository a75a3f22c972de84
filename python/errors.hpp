#pragma once

// The errors of `sweetspot` in Python, with the words of the command line:
// sweetspot.InputError (a ValueError) for bad input, exit status 2 on the
// command line; sweetspot.ModelRefusal (a RuntimeError) for a design the
// model refuses to answer, exit status 3. Both carry `source`, `path` (the
// JSON pointer), `value` and `expected`, and `detail` (the words after the
// path); str() is the line `sweetspot` prints after "sweetspot: ".

#include <pybind11/pybind11.h>

namespace sweetspot::python {

// Makes the exception types in `module` and registers the translation of
// io::InputError, io::ReadError, ModelRefusal and std::invalid_argument.
void register_errors(pybind11::module_& module);

}  // namespace sweetspot::python

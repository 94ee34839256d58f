// Python exceptions pybind11 has no C++ type for.
#pragma once
#include <pybind11/pybind11.h>

#include <string>

namespace spinhash::python {

[[noreturn]] inline void raise_file_not_found(const std::string& message) {
  PyErr_SetString(PyExc_FileNotFoundError, message.c_str());
  throw pybind11::error_already_set();
}

}  // namespace spinhash::python

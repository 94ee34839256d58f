#include "config_kinds.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "config/mode_name.hpp"

namespace py = pybind11;

namespace spinhash::python {

std::string type_name(py::handle v) { return py::str(py::type::handle_of(v).attr("__name__")); }

// Range bounds as written in messages (U64's top bound is 2^64 - 1).
std::string bound_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}
std::string bound_text(unsigned long long v) { return std::to_string(v); }

[[noreturn]] void out_of_range(const char* name, const std::string& lo, const std::string& hi, py::handle v) {
  throw py::value_error(std::string(name) + " must be in [" + lo + ", " + hi + "], got " +
                        std::string(py::repr(v)));
}

double shortest(float v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf - 1, v).ptr;
  *end = '\0';
  return std::strtod(buf, nullptr);
}

// One getter and one setter per kind of SPINHASH_CONFIG_FIELDS.
py::object get_MODE(Mode v) { return py::str(host::mode_name(v)); }
py::object get_BOOL(bool v) { return py::bool_(v); }
py::object get_U32(uint32_t v) { return py::int_(v); }
py::object get_U64(uint64_t v) { return py::int_(v); }
py::object get_F32(float v) { return py::float_(shortest(v)); }
py::object get_VEC3D(const double (&v)[3]) { return py::make_tuple(v[0], v[1], v[2]); }

// By name, as the CLI's --mode: "bran", "sran" or "sind", any case.
void set_MODE(RecognizerConfig*, Mode* v, int lo, int hi, const char* name, py::handle value) {
  std::string choices;
  for (int m = lo; m <= hi; ++m) choices += std::string(m > lo ? ", " : "") + host::mode_name(Mode(m));
  if (!py::isinstance<py::str>(value))
    throw py::type_error(std::string(name) + " must be a str (" + choices + "), got " + type_name(value));
  std::string word = value.cast<std::string>();
  for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (int m = lo; m <= hi; ++m) {
    if (word == host::mode_name(Mode(m))) {
      *v = Mode(m);
      return;
    }
  }
  throw py::value_error(std::string(name) + " must be one of " + choices + ", got " +
                        std::string(py::repr(value)));
}

void set_BOOL(RecognizerConfig*, bool* v, int, int, const char* name, py::handle value) {
  if (!PyBool_Check(value.ptr()))
    throw py::type_error(std::string(name) + " must be True or False, got " + type_name(value));
  *v = value.ptr() == Py_True;
}

// Any real number (not bool), checked as the float the core stores (NaN is out of range).
void set_F32(RecognizerConfig*, float* v, float lo, float hi, const char* name, py::handle value) {
  if (PyBool_Check(value.ptr()) || py::isinstance<py::str>(value) || !PyNumber_Check(value.ptr()))
    throw py::type_error(std::string(name) + " must be a number, got " + type_name(value));
  const double d = PyFloat_AsDouble(value.ptr());
  if (PyErr_Occurred()) throw py::error_already_set();
  const float f = static_cast<float>(d);
  if (!(f >= lo && f <= hi)) out_of_range(name, bound_text(double{lo}), bound_text(double{hi}), value);
  *v = f;
}

// The viewpoint (the one VEC3D field): 3 finite numbers turn it on, as the
// CLI's --viewpoint X Y Z does; None turns it off.
void set_VEC3D(RecognizerConfig* c, double (*v)[3], int, int, const char* name, py::handle value) {
  if (value.is_none()) {
    c->has_viewpoint = false;
    return;
  }
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 3)
    throw py::type_error(std::string(name) + " must be 3 numbers (x, y, z) or None, got " + type_name(value));
  double xyz[3];
  for (int a = 0; a < 3; ++a) {
    xyz[a] = PyFloat_AsDouble(py::sequence(py::reinterpret_borrow<py::object>(value))[a].ptr());
    if (PyErr_Occurred()) throw py::error_already_set();
    if (!std::isfinite(xyz[a]))
      throw py::value_error(std::string(name) + " must be finite, got " + std::string(py::repr(value)));
  }
  for (int a = 0; a < 3; ++a) (*v)[a] = xyz[a];
  c->has_viewpoint = true;
}

}  // namespace spinhash::python

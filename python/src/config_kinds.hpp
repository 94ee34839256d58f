// Conversions between Python values and the kinds of SPINHASH_CONFIG_FIELDS
// (MODE, BOOL, U32, U64, F32, VEC3D): one getter and one setter per kind,
// named get_KIND / set_KIND so the X-macro can pick them. Setters check the
// field's range as the core does and name the field in every error.
#pragma once
#include <pybind11/pybind11.h>

#include <string>

#include "spinhash/config.hpp"

namespace spinhash::python {

std::string type_name(pybind11::handle v);
std::string bound_text(double v);
std::string bound_text(unsigned long long v);
[[noreturn]] void out_of_range(const char* name, const std::string& lo, const std::string& hi,
                               pybind11::handle v);
double shortest(float v);  // the shortest decimal that reads back as v (0.15, not 0.15000000596)

pybind11::object get_MODE(Mode v);
pybind11::object get_BOOL(bool v);
pybind11::object get_U32(uint32_t v);
pybind11::object get_U64(uint64_t v);
pybind11::object get_F32(float v);
pybind11::object get_VEC3D(const double (&v)[3]);

void set_MODE(RecognizerConfig*, Mode* v, int lo, int hi, const char* name, pybind11::handle value);
void set_BOOL(RecognizerConfig*, bool* v, int, int, const char* name, pybind11::handle value);
void set_F32(RecognizerConfig*, float* v, float lo, float hi, const char* name, pybind11::handle value);
void set_VEC3D(RecognizerConfig* c, double (*v)[3], int, int, const char* name, pybind11::handle value);

// Any integer (int, numpy integers; not bool), within [lo, hi].
template <typename T, typename L, typename H>
void set_unsigned(T* v, L lo, H hi, const char* name, pybind11::handle value) {
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw pybind11::type_error(std::string(name) + " must be an int, got " + type_name(value));
  const auto as_int = pybind11::reinterpret_steal<pybind11::int_>(PyNumber_Index(value.ptr()));
  if (!as_int) throw pybind11::error_already_set();
  const unsigned long long low = static_cast<unsigned long long>(lo);
  const unsigned long long high = static_cast<unsigned long long>(hi);
  const unsigned long long u = PyLong_AsUnsignedLongLong(as_int.ptr());  // fails for < 0 and >= 2^64
  if (PyErr_Occurred()) {
    PyErr_Clear();
    out_of_range(name, bound_text(low), bound_text(high), value);
  }
  if (u < low || u > high) out_of_range(name, bound_text(low), bound_text(high), value);
  *v = static_cast<T>(u);
}
template <typename L, typename H>
void set_U32(RecognizerConfig*, uint32_t* v, L lo, H hi, const char* name, pybind11::handle value) {
  set_unsigned(v, lo, hi, name, value);
}
template <typename L, typename H>
void set_U64(RecognizerConfig*, uint64_t* v, L lo, H hi, const char* name, pybind11::handle value) {
  set_unsigned(v, lo, hi, name, value);
}

}  // namespace spinhash::python

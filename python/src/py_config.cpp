#include "py_config.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "bindings.hpp"
#include "pipeline/recognizer_flags.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

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

// The float as Python shows the shortest decimal that reads back as it (0.15, not 0.15000000596).
double shortest(float v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf - 1, v).ptr;
  *end = '\0';
  return std::strtod(buf, nullptr);
}

// One getter and one setter per kind of SPINHASH_CONFIG_FIELDS.
py::object get_MODE(Mode v) { return py::str(pipeline::mode_name(v)); }
py::object get_BOOL(bool v) { return py::bool_(v); }
py::object get_U32(uint32_t v) { return py::int_(v); }
py::object get_U64(uint64_t v) { return py::int_(v); }
py::object get_F32(float v) { return py::float_(shortest(v)); }
py::object get_VEC3D(const double (&v)[3]) { return py::make_tuple(v[0], v[1], v[2]); }

// By name, as the CLI's --mode: "bran", "sran" or "sind", any case.
void set_MODE(RecognizerConfig*, Mode* v, int lo, int hi, const char* name, py::handle value) {
  std::string choices;
  for (int m = lo; m <= hi; ++m) choices += std::string(m > lo ? ", " : "") + pipeline::mode_name(Mode(m));
  if (!py::isinstance<py::str>(value))
    throw py::type_error(std::string(name) + " must be a str (" + choices + "), got " + type_name(value));
  std::string word = value.cast<std::string>();
  for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (int m = lo; m <= hi; ++m) {
    if (word == pipeline::mode_name(Mode(m))) {
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

// Any integer (int, numpy integers; not bool), within [lo, hi].
template <typename T, typename L, typename H>
void set_unsigned(T* v, L lo, H hi, const char* name, py::handle value) {
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw py::type_error(std::string(name) + " must be an int, got " + type_name(value));
  const auto as_int = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  if (!as_int) throw py::error_already_set();
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
void set_U32(RecognizerConfig*, uint32_t* v, L lo, H hi, const char* name, py::handle value) {
  set_unsigned(v, lo, hi, name, value);
}
template <typename L, typename H>
void set_U64(RecognizerConfig*, uint64_t* v, L lo, H hi, const char* name, py::handle value) {
  set_unsigned(v, lo, hi, name, value);
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

// Field names in SPINHASH_CONFIG_FIELDS order.
py::tuple field_names() {
  py::list names;
#define SPINHASH_PY_NAME(kind, name, lo, hi, flag, help) names.append(#name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_NAME)
#undef SPINHASH_PY_NAME
  return py::tuple(names);
}

// The valid range of each numeric setting, (lo, hi) inclusive, as the core checks it.
py::object range_of(float lo, float hi) { return py::make_tuple(shortest(lo), shortest(hi)); }
template <typename L, typename H>
py::object range_of(L lo, H hi) {
  return py::make_tuple(static_cast<unsigned long long>(lo), static_cast<unsigned long long>(hi));
}
py::dict field_ranges() {
  py::dict ranges;
#define SPINHASH_PY_RANGE_MODE(name, lo, hi)
#define SPINHASH_PY_RANGE_BOOL(name, lo, hi)
#define SPINHASH_PY_RANGE_VEC3D(name, lo, hi)
#define SPINHASH_PY_RANGE_U32(name, lo, hi) ranges[#name] = range_of(lo, hi);
#define SPINHASH_PY_RANGE_U64(name, lo, hi) ranges[#name] = range_of(lo, hi);
#define SPINHASH_PY_RANGE_F32(name, lo, hi) ranges[#name] = range_of(lo, hi);
#define SPINHASH_PY_RANGE(kind, name, lo, hi, flag, help) SPINHASH_PY_RANGE_##kind(name, lo, hi)
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_RANGE)
#undef SPINHASH_PY_RANGE
  return ranges;
}

// The mode words, in the MODE field's range ("bran", "sran", "sind").
py::tuple mode_names() {
  py::list names;
#define SPINHASH_PY_MODES_MODE(lo, hi) \
  for (int m = lo; m <= hi; ++m) names.append(pipeline::mode_name(Mode(m)));
#define SPINHASH_PY_MODES_BOOL(lo, hi)
#define SPINHASH_PY_MODES_U32(lo, hi)
#define SPINHASH_PY_MODES_U64(lo, hi)
#define SPINHASH_PY_MODES_F32(lo, hi)
#define SPINHASH_PY_MODES_VEC3D(lo, hi)
#define SPINHASH_PY_MODES(kind, name, lo, hi, flag, help) SPINHASH_PY_MODES_##kind(lo, hi)
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_MODES)
#undef SPINHASH_PY_MODES
  return py::tuple(names);
}

py::dict as_dict(const RecognizerConfig& c) {
  py::dict d;
#define SPINHASH_PY_GET(kind, name, lo, hi, flag, help) d[#name] = get_##kind(c.name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_GET)
#undef SPINHASH_PY_GET
  return d;
}

std::string config_repr(const RecognizerConfig& c) {
  std::string s = "spinhash.Config(";
  bool first = true;
  for (auto item : as_dict(c)) {
    s += std::string(first ? "" : ", ") + std::string(py::str(item.first)) + "=" +
         std::string(py::repr(item.second));
    first = false;
  }
  return s + ")";
}

RecognizerConfig from_kwargs(const py::kwargs& kwargs) {
  RecognizerConfig c;
  for (auto item : kwargs) set_config_field(&c, py::cast<std::string>(item.first), item.second);
  return c;
}

}  // namespace

void set_config_field(RecognizerConfig* c, const std::string& key, py::handle value) {
#define SPINHASH_PY_SET(kind, name, lo, hi, flag, help) \
  if (key == #name) return set_##kind(c, &c->name, lo, hi, #name, value);
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_SET)
#undef SPINHASH_PY_SET
  throw py::type_error("unknown recognizer setting '" + key + "' (spinhash.Config.fields lists them)");
}

RecognizerConfig recognizer_config(const RecognizerConfig& base, py::handle config,
                                   const py::kwargs& kwargs) {
  RecognizerConfig c = base;
  if (!config.is_none()) {
    if (!py::isinstance<RecognizerConfig>(config))
      throw py::type_error("config must be a spinhash.Config or None, got " + type_name(config));
    c = config.cast<RecognizerConfig>();
  }
  for (auto item : kwargs) set_config_field(&c, py::cast<std::string>(item.first), item.second);
  if (c.delta_max < c.delta)
    throw py::value_error("delta_max (" + bound_text(double{c.delta_max}) + ") must be at least delta (" +
                          bound_text(double{c.delta}) + ")");
  if (required_workspace_bytes(c) == 0) throw py::value_error("invalid recognizer configuration");
  return c;
}

void bind_config(py::module_& m) {
  py::class_<RecognizerConfig> cls(m, "Config",
                                   "Recognition settings: one attribute and keyword argument per setting of "
                                   "the core's RecognizerConfig (Config.fields; docs/api.md).");
  cls.def(py::init(&from_kwargs), "Config(**settings): defaults, with the settings given");
  cls.attr("fields") = field_names();
  cls.attr("ranges") = field_ranges();
  cls.attr("modes") = mode_names();
// A BOOL field's help describes its CLI flag, which sets it to false.
#define SPINHASH_PY_DOC_MODE(help) help
#define SPINHASH_PY_DOC_BOOL(help) "False: " help
#define SPINHASH_PY_DOC_U32(help) help
#define SPINHASH_PY_DOC_U64(help) help
#define SPINHASH_PY_DOC_F32(help) help
#define SPINHASH_PY_DOC_VEC3D(help) help
#define SPINHASH_PY_PROPERTY(kind, name, lo, hi, flag, help)                                \
  cls.def_property(                                                                         \
      #name, [](const RecognizerConfig& c) { return get_##kind(c.name); },                  \
      [](RecognizerConfig& c, py::handle v) { set_##kind(&c, &c.name, lo, hi, #name, v); }, \
      SPINHASH_PY_DOC_##kind(help));
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_PROPERTY)
#undef SPINHASH_PY_PROPERTY
  cls.def("to_dict", &as_dict, "every setting by name");
  cls.def("copy", [](const RecognizerConfig& c) { return c; });
  cls.def("__eq__",
          [](const RecognizerConfig& a, const RecognizerConfig& b) { return as_dict(a).equal(as_dict(b)); });
  cls.def("__repr__", &config_repr);
}

}  // namespace spinhash::python

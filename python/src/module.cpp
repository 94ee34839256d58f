// The `spinhash` Python module: recognition of numpy point clouds against a
// spinhash database, through the same host pipeline as the spinhash command.
#include "bindings.hpp"
#include "pipeline/version.hpp"
#include "spinhash/vehicle_classes.h"

PYBIND11_MODULE(spinhash, m) {
  m.doc() =
      "spinhash: 3D object recognition in airborne lidar point clouds (spin images, LSH, batch RANSAC). "
      "See docs/python.md.";
  m.attr("__version__") = spinhash::pipeline::version();
  // Every class a model can carry, in id order (spinhash/vehicle_classes.h).
  m.attr("CLASS_NAMES") = pybind11::make_tuple(
#define SPINHASH_PY_CLASS_NAME(id, Name, name, help) name,
      SPINHASH_VEHICLE_CLASSES(SPINHASH_PY_CLASS_NAME) nullptr);
#undef SPINHASH_PY_CLASS_NAME
  spinhash::python::bind_database(m);
  spinhash::python::bind_config(m);
  spinhash::python::bind_result(m);
  spinhash::python::bind_recognizer(m);
  spinhash::python::bind_scene(m);
  spinhash::python::bind_cloud(m);
}

// spinhash._spinhash, the compiled half of the `spinhash` package
// (python/spinhash/__init__.py re-exports it): recognition of numpy point clouds against a
// spinhash database, through the same host pipeline as the spinhash command.
#include "bindings.hpp"
#include "pipeline/version.hpp"
#include "spinhash/status_list.h"
#include "spinhash/vehicle_class.hpp"

PYBIND11_MODULE(_spinhash, m) {
  m.doc() =
      "spinhash: 3D object recognition in airborne lidar point clouds (spin images, LSH, batch RANSAC). "
      "See docs/python.md.";
  m.attr("__version__") = spinhash::pipeline::version();
  // Every class a model can carry, in id order (spinhash/vehicle_classes.h).
  pybind11::list classes;
  for (uint32_t id = 0; id < spinhash::kVehicleClassCount; ++id)
    classes.append(spinhash::vehicle_class_name(id));
  m.attr("CLASS_NAMES") = pybind11::tuple(classes);
  // Every group, in id order, and each class's group (CLASS_GROUPS[i] is the
  // group of CLASS_NAMES[i]): the group column of vehicle_classes.h.
  pybind11::list groups;
  for (uint32_t id = 0; id < spinhash::kVehicleGroupCount; ++id)
    groups.append(spinhash::vehicle_group_name(id));
  m.attr("GROUP_NAMES") = pybind11::tuple(groups);
  pybind11::list class_groups;
  for (uint32_t id = 0; id < spinhash::kVehicleClassCount; ++id)
    class_groups.append(spinhash::vehicle_group_name(spinhash::vehicle_group_of(id)));
  m.attr("CLASS_GROUPS") = pybind11::tuple(class_groups);
  // Every status (spinhash/status_list.h): its word (the `status` of results
  // and objects) -> (code, message).
  pybind11::dict statuses;
#define SPINHASH_PY_STATUS(cxx, value, c, word, message) \
  statuses[word] = pybind11::make_tuple(value, message);
  SPINHASH_STATUS_LIST(SPINHASH_PY_STATUS)
#undef SPINHASH_PY_STATUS
  m.attr("STATUSES") = statuses;
  spinhash::python::bind_database(m);
  spinhash::python::bind_config(m);
  spinhash::python::bind_result(m);
  spinhash::python::bind_recognizer(m);
  spinhash::python::bind_scene(m);
  spinhash::python::bind_scene_stream(m);
  spinhash::python::bind_cloud(m);
  spinhash::python::bind_survey(m);
}

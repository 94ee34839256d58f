// The parts of the `spinhash` Python module, each bound by its own file.
#pragma once
#include <pybind11/pybind11.h>

namespace spinhash::python {

void bind_database(pybind11::module_& m);      // py_database.cpp
void bind_config(pybind11::module_& m);        // py_config.cpp
void bind_result(pybind11::module_& m);        // py_result.cpp
void bind_recognizer(pybind11::module_& m);    // py_recognizer.cpp
void bind_scene(pybind11::module_& m);         // py_scene.cpp
void bind_scene_stream(pybind11::module_& m);  // py_scene_stream.cpp
void bind_cloud(pybind11::module_& m);         // py_cloud.cpp
void bind_survey(pybind11::module_& m);        // py_survey.cpp

}  // namespace spinhash::python

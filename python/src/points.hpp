// numpy (N, 3) float64 arrays <-> the pipeline's x0 y0 z0 x1 ... vectors.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "spinhash/recognizer.hpp"

namespace spinhash::python {

// The rows of an (N, 3) float64 or float32 array, any strides (float32
// widened, with a UserWarning when its coordinates are too large for
// float32 to hold to a centimetre). TypeError for anything that is not such
// a numpy array, ValueError for another shape; NaN rows pass through (the
// core drops and counts them).
std::vector<double> points_from_array(pybind11::handle points);

// An (N, 3) float64 array of xyz (3 per point).
pybind11::array_t<double> array_from_points(const std::vector<double>& xyz);

// x_query = R x_model + t as a 4x4 float64 array (R widened from float, as
// the CLI's JSON prints it).
pybind11::array_t<double> pose_matrix(const Pose& p);

}  // namespace spinhash::python

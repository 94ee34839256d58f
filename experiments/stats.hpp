// Small summary statistics for experiment tables.
#pragma once
#include <vector>

namespace spinhash::experiment {

double mean_of(const std::vector<double>& v);  // 0 for an empty list
double median_of(std::vector<double> v);       // 0 for an empty list
// Least-squares line y = slope * x + intercept and its R^2.
struct LineFit {
  double slope = 0.0, intercept = 0.0, r2 = 0.0;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace spinhash::experiment

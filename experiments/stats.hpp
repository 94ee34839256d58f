// Small summary statistics for experiment tables.
#pragma once
#include <cstdint>
#include <vector>

namespace spinhash::experiment {

double mean_of(const std::vector<double>& v);  // 0 for an empty list
double median_of(std::vector<double> v);       // 0 for an empty list
// Least-squares line y = slope * x + intercept and its R^2.
struct LineFit {
  double slope = 0.0, intercept = 0.0, r2 = 0.0;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

// Wilson score interval of a binomial share k / n at 95 % confidence
// (z = 1.96): an interval that stays inside [0, 1] and is honest at 0 of n
// and n of n. {0, 1} for n = 0.
struct ShareInterval {
  double lo = 0.0, hi = 1.0;
};
ShareInterval wilson_interval(uint64_t k, uint64_t n);

}  // namespace spinhash::experiment

#pragma once
// Pearson's chi-square goodness-of-fit test for binned samples, as Nori's and Mitsuba's warp tests
// use it: bins expected to hold fewer than a handful of samples are pooled into one, so that the
// statistic keeps its chi-square distribution.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace ptview::testing {

struct ChiSquareResult {
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 1.0;      // P(a true fit gives a statistic at least this large)
    int pooledBins = 0;       // bins merged into the pool (0: no pool)
    std::string impossible;   // non-empty when a bin with nothing expected was hit: pValue is 0
};

// observed[i] samples fell into bin i where expected[i] were expected. The expected counts are
// not rescaled to the observed total: a density that integrates to 1.1 must fail.
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected = 5.0);

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularized upper incomplete gamma function; the p-value
// of a chi-square statistic s with k degrees of freedom is Q(k / 2, s / 2).
double regularizedGammaQ(double a, double x);

// Per-test significance that keeps the chance of any false rejection among `tests` independent
// tests at `significance` (Sidak correction).
double sidakSignificance(double significance, int tests);

// One line: statistic, degrees of freedom, p-value, pooling.
std::string describe(const ChiSquareResult& result);

// A table of the `rows` bins that contribute most to the statistic, for a failure message.
// `label` names a bin (e.g. its coordinate range); by default its index.
std::string worstBinsTable(const std::vector<double>& observed, const std::vector<double>& expected,
                           const std::function<std::string(std::size_t)>& label = {}, int rows = 8);

} // namespace ptview::testing

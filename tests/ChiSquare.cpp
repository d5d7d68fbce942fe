#include "ChiSquare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ptview::testing {
namespace {

constexpr double kRelativeEpsilon = 1e-15;
constexpr int kMaxIterations = 100000;

// P(a, x) by its power series: converges quickly for x < a + 1.
double lowerGammaSeries(double a, double x, double logPrefactor) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < kMaxIterations; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * kRelativeEpsilon) break;
    }
    return sum * std::exp(logPrefactor);
}

// Q(a, x) by its continued fraction, evaluated with the modified Lentz method: converges quickly
// for x >= a + 1, and keeps full relative precision in the far tail where 1 - P would be 0.
double upperGammaContinuedFraction(double a, double x, double logPrefactor) {
    const double tiny = std::numeric_limits<double>::min() / kRelativeEpsilon;
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double fraction = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double delta = d * c;
        fraction *= delta;
        if (std::abs(delta - 1.0) < kRelativeEpsilon) break;
    }
    return std::exp(logPrefactor) * fraction;
}

} // namespace

double regularizedGammaQ(double a, double x) {
    if (!(a > 0.0)) throw std::invalid_argument("regularizedGammaQ: a must be positive");
    if (x <= 0.0) return 1.0;
    // Both expansions share the factor x^a e^-x / Gamma(a).
    const double logPrefactor = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) return std::max(0.0, 1.0 - lowerGammaSeries(a, x, logPrefactor));
    return upperGammaContinuedFraction(a, x, logPrefactor);
}

double sidakSignificance(double significance, int tests) {
    return 1.0 - std::pow(1.0 - significance, 1.0 / std::max(tests, 1));
}

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected) {
    if (observed.size() != expected.size()) throw std::invalid_argument("chiSquareTest: bin counts differ");
    std::vector<std::size_t> order(expected.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return expected[i] < expected[j]; });

    // Smallest expectations first: they go into the pool until it alone expects minExpected.
    ChiSquareResult result;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int bins = 0;
    for (std::size_t i : order) {
        if (expected[i] <= 0.0) {
            if (observed[i] > 0.0 && result.impossible.empty())
                result.impossible = "bin " + std::to_string(i) + " holds " + std::to_string(observed[i]) +
                                    " samples where none were expected";
            continue;
        }
        if (expected[i] < minExpected || (pooledExpected > 0.0 && pooledExpected < minExpected)) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            ++result.pooledBins;
            continue;
        }
        double difference = observed[i] - expected[i];
        result.statistic += difference * difference / expected[i];
        ++bins;
    }
    if (pooledExpected > 0.0) {
        double difference = pooledObserved - pooledExpected;
        result.statistic += difference * difference / pooledExpected;
        ++bins;
    }
    result.degreesOfFreedom = bins - 1;
    if (!result.impossible.empty())
        result.pValue = 0.0;
    else if (result.degreesOfFreedom > 0)
        result.pValue = regularizedGammaQ(0.5 * result.degreesOfFreedom, 0.5 * result.statistic);
    return result;
}

std::string describe(const ChiSquareResult& result) {
    char line[256];
    std::snprintf(line, sizeof line, "chi2 = %.2f, dof = %d, p-value = %.3g (%d low bins pooled)",
                  result.statistic, result.degreesOfFreedom, result.pValue, result.pooledBins);
    return result.impossible.empty() ? std::string(line) : std::string(line) + "; " + result.impossible;
}

std::string worstBinsTable(const std::vector<double>& observed, const std::vector<double>& expected,
                           const std::function<std::string(std::size_t)>& label, int rows) {
    auto contribution = [&](std::size_t i) {
        double difference = observed[i] - expected[i];
        if (expected[i] > 0.0) return difference * difference / expected[i];
        return observed[i] > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    };
    std::vector<std::size_t> order(std::min(observed.size(), expected.size()));
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return contribution(i) > contribution(j); });

    std::string table = "worst bins:\n";
    char line[256];
    std::snprintf(line, sizeof line, "  %-36s %10s %12s %12s\n", "bin", "observed", "expected", "(o-e)^2/e");
    table += line;
    for (std::size_t k = 0; k < order.size() && k < static_cast<std::size_t>(rows); ++k) {
        std::size_t i = order[k];
        std::string name = label ? label(i) : "#" + std::to_string(i);
        std::snprintf(line, sizeof line, "  %-36s %10.0f %12.2f %12.2f\n", name.c_str(), observed[i], expected[i],
                      contribution(i));
        table += line;
    }
    return table;
}

} // namespace ptview::testing

// ∫ f(r) 2πr dr over [a, b] by composite Simpson in s = ln r: a profile's
// peak near 0 and its exponential tail both get evenly spaced nodes.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>

namespace tsis::test {

inline double planeIntegral(const std::function<double(double)>& f, double a, double b,
                            int n = 20000) {
    const double la = std::log(a), lb = std::log(b), h = (lb - la) / n;
    auto g = [&](double s) {
        const double r = std::exp(s);
        return f(r) * 2.0 * std::numbers::pi * r * r;
    };
    double sum = g(la) + g(lb);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * g(la + k * h);
    return sum * h / 3.0;
}

}  // namespace tsis::test

// What the volumetric tests share: a medium from coefficients and the mean of
// RGB samples with its standard error.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>

#include "volumetric/medium.h"

namespace tsis {

inline Medium testMedium(glm::dvec3 sigmaS, glm::dvec3 sigmaA, double eta) {
    Material mat;
    mat.sigmaSPrime = sigmaS;
    mat.sigmaA = sigmaA;
    mat.eta = eta;
    return Medium(mat);
}

class MeanEstimate {
  public:
    void add(const glm::dvec3& v) {
        sum_ += v;
        sumSq_ += v * v;
        ++n_;
    }
    glm::dvec3 mean() const { return sum_ / static_cast<double>(n_); }
    double error(int c) const {
        const double m = sum_[c] / n_;
        return std::sqrt(std::max(0.0, sumSq_[c] / n_ - m * m) / n_);
    }

  private:
    glm::dvec3 sum_{0.0}, sumSq_{0.0};
    long long n_ = 0;
};

}  // namespace tsis

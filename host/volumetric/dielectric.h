// A smooth dielectric interface: Snell refraction and mirror reflection (the
// exact Fresnel reflectance is physics/fresnel.h's).
#pragma once

#include <glm/vec3.hpp>

namespace tsis {

// Reflection of travel direction d at a surface of unit normal n.
glm::dvec3 reflect(const glm::dvec3& d, const glm::dvec3& n);

// Refraction of travel direction d (unit) through a surface of unit normal n
// facing against d (n·d < 0), from index 1 into index `eta` relative to it
// (eta = n_t / n_i). False on total internal reflection.
bool refract(const glm::dvec3& d, const glm::dvec3& n, double eta, glm::dvec3& out);

// Uniform direction on the unit sphere (the isotropic phase function).
glm::dvec3 uniformSphere(double u1, double u2);

}  // namespace tsis

// Validity of a mesh's UVs as an atlas: every coordinate in [0,1]², no
// degenerate UV triangle, no two triangles overlapping in UV space.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace tsis {

struct UVCheck {
    bool ok = true;
    std::string problem;  // one line, empty when ok
    size_t outOfRange = 0, degenerate = 0, overlapping = 0;
};

UVCheck checkUVs(const Mesh& mesh);

}  // namespace tsis

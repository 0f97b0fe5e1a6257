// Procedural meshes with analytic, valid, non-overlapping UVs.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tsis {

Mesh builtinSphere();   // 28,560 triangles (the thesis' Sphere(28K)); equal-area UVs
Mesh builtinPlane();    // square in the xz-plane facing +y
Mesh builtinDefault();  // the default scene: thick body and thin parts

// Throws Error listing the names for an unknown one.
Mesh builtinMesh(const std::string& name);
std::vector<std::string> builtinNames();

}  // namespace tsis

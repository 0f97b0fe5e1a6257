// An order to draw a mesh's triangles in that llvmpipe (and any tiled
// rasteriser) sets up fastest: nearby triangles one after another (Morton
// order of their centroids on a grid of a few triangles a cell) and the
// vertices numbered by first use, so that the vertex cache and the bins a
// triangle lands in are warm from the one before. A scanned or subdivided
// mesh lists its vertices far from their neighbours: its shadow copy's light
// views set up 1.2× faster in this order (bench/results/frame.md).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "mesh/mesh.h"

namespace tsis {

struct DrawOrder {
    std::vector<glm::uvec3> triangles;  // the mesh's triangles, reordered, in the new numbering
    std::vector<uint32_t> vertexOf;     // new vertex i is the mesh's vertex vertexOf[i]
};

// Every triangle once; vertices no triangle uses are left out. The depth a
// pass writes is the same in any order; only coincident triangles' ties
// could pick another winner.
DrawOrder coherentDrawOrder(const Mesh& mesh);

}  // namespace tsis

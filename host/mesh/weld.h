// Vertices that are one point of the surface: seams (UV charts, a sphere's
// date line, crease splits) duplicate vertices, not always bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace tsis {

// Per vertex, the smallest index of the vertices within 1e-6 of the
// bounding-box diagonal of it (greedy in index order: a vertex joins the first
// earlier representative close enough). A non-finite position is its own.
std::vector<uint32_t> weldPositions(const Mesh& mesh);
// The same within an absolute `tolerance` (mm), at most 1e-6 of the diagonal
// times 2^20 cells a side.
std::vector<uint32_t> weldPositions(const Mesh& mesh, double tolerance);

// Undirected edges between welded positions used by exactly one triangle: 0
// for a closed surface, whatever its seams.
size_t boundaryEdges(const Mesh& mesh);
// Per triangle, whether it has such an edge, under the weld `weld`
// (weldPositions).
std::vector<char> trianglesOnBoundary(const Mesh& mesh, const std::vector<uint32_t>& weld);

// Whether every connected part of the mesh is a closed surface wound outward:
// each edge between bit-identical positions used once in each direction, and
// each part's signed volume positive. From a light outside such a mesh every
// ray meets a front face first, so a depth pass may cull the back ones. A
// seam whose copies differ in a bit reads as open (no culling: safe).
bool closedOutward(const Mesh& mesh);

}  // namespace tsis

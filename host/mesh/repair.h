// Checks and repairs every loaded mesh goes through: what a renderer can fix
// is fixed with one note on stderr each, the rest is a tsis::Error.
#pragma once

#include <cstddef>

#include "mesh/mesh.h"

namespace tsis {

// Edges by vertex index (an OBJ/atlas seam, with its duplicated vertices, is
// two boundaries, not a joined edge).
struct EdgeStats {
    size_t edges = 0;        // distinct undirected edges
    size_t boundary = 0;     // used by one triangle
    size_t nonManifold = 0;  // used by three or more
};
EdgeStats edgeStats(const Mesh& mesh);

struct RepairReport {
    size_t mergedVertices =
        0;  // exact duplicates (texcoords too) folded into one (only without UVs)
    size_t degenerateTriangles = 0;   // repeated index or area < 1e-12 · diagonal²
    size_t duplicateTriangles = 0;    // same corners, same order (up to rotation) as an earlier one
    size_t unreferencedVertices = 0;  // used by no triangle, dropped
    size_t nonManifoldEdges = 0;      // reported, kept
};

// Refuses non-finite positions or UVs and out-of-range indices (bugs in a
// parser, or a mesh built by hand); merges exact duplicate vertices when the
// mesh has no UVs (merging would close UV seams); drops degenerate triangles,
// exact duplicate triangles and unreferenced vertices; reports non-manifold edges. Throws when no
// triangle is left.
RepairReport repairMesh(Mesh& mesh);

// One note when the surface is not closed (boundary edges by welded position,
// weld.h: seams do not count), as the dipole and the energy terms assume a
// closed solid; returns the boundary edges. Once per mesh load (prepareMesh).
size_t noteIfOpen(const Mesh& mesh);

}  // namespace tsis

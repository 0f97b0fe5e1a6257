// A coarser copy of a mesh for the passes that only need its depth (the lights'
// shadow maps): vertex clustering on a uniform grid (Rossignac and Borrel
// 1993). Linear time, so a million-triangle scan is simplified in well under
// a second; the copy is not a manifold and has no attributes but positions,
// which is all a depth pass reads.
#pragma once

#include <cstddef>

#include "mesh/mesh.h"

namespace tsis {

struct MeshLod {
    Mesh mesh;              // positions and triangles only
    float deviationMm = 0;  // max distance from a vertex of the input to its cluster's point
};

// Every vertex moves to the mean of the vertices in its grid cell of side
// `cellMm`; triangles whose corners fall in fewer than three cells vanish,
// and one of each set of triangles on the same three cells stays.
// `deviationMm` bounds how far the copy's surface is from the input's: the
// shadow offset that keeps the input from shadowing itself against it.
MeshLod clusterLod(const Mesh& mesh, float cellMm);

// The grid cell for `mesh` to keep about `triangles` triangles: a closed
// surface of area A over cells of side c keeps about 2A/c² of them.
float lodCellForBudget(const Mesh& mesh, size_t triangles);

}  // namespace tsis

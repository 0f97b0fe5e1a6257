// A closed mesh as the walks' boundary: first-hit rays through Embree 3 (single
// rays, float geometry; positions and normals are recomputed in double from
// the hit's facet and barycentrics). Embree is 5–6× faster than CGAL's AABB
// tree (first_intersection, exact predicates) on this workload: rays from
// inside in random directions, 1 thread, builtin:sphere 443K vs 85K rays/s,
// builtin:default 1.38M vs 0.23M (bench/bench_raycast.cpp, a loaded machine).
// No Embree type leaks out of this header.
#pragma once

#include <memory>
#include <vector>

#include "mesh/mesh.h"
#include "volumetric/boundary.h"

namespace tsis {

class MeshBoundary : public Boundary {
  public:
    explicit MeshBoundary(const Mesh& mesh);
    ~MeshBoundary() override;
    MeshBoundary(const MeshBoundary&) = delete;
    MeshBoundary& operator=(const MeshBoundary&) = delete;

    bool intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax,
                   SurfaceHit& hit) const override;
    double epsilon() const override { return epsilon_; }
    bool facet(int facet, glm::dvec3 (&v)[3], glm::dvec3& normal) const override;
    std::span<const int> facetNeighbours(int facet) const override;

    // The interpolated vertex normal at a hit (what the G-buffer and the
    // composite's exit term use), or the facet's normal without vertex normals.
    glm::dvec3 shadingNormal(const SurfaceHit& hit) const;

  private:
    void buildNeighbours();

    struct Scene;
    std::unique_ptr<Scene> scene_;
    Mesh mesh_;  // a copy: the boundary outlives the frame's scene
    std::vector<glm::dvec3> facetNormals_;
    // Facets sharing a (position-welded) vertex, facet f's at
    // neighbours_[neighbourStart_[f] … neighbourStart_[f + 1]).
    std::vector<int> neighbourStart_, neighbours_;
    double epsilon_;
};

}  // namespace tsis

// Exact visibility between surface points and lights: segment queries against
// the mesh's triangles in an AABB tree (CGAL, exact predicates). No CGAL type
// leaks out of this header.
#pragma once

#include <glm/vec3.hpp>
#include <memory>

#include "mesh/mesh.h"

namespace tsis {

class RayCaster {
  public:
    // Builds the tree over the mesh's non-degenerate triangles.
    explicit RayCaster(const Mesh& mesh);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    // True when the closed segment [a, b] touches no triangle. Safe to call
    // from several threads at once.
    bool segmentClear(const glm::dvec3& a, const glm::dvec3& b) const;

    size_t triangleCount() const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace tsis

#include "render/ray_caster.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

namespace tsis {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 point(const glm::dvec3& p) {
    return {p.x, p.y, p.z};
}

}  // namespace

struct RayCaster::Tree {
    Triangles triangles;  // the primitives point into this vector: filled before the tree
    AabbTree tree;
};

RayCaster::RayCaster(const Mesh& mesh) : tree_(std::make_unique<Tree>()) {
    tree_->triangles.reserve(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles) {
        K::Triangle_3 tri(point(mesh.positions[t.x]), point(mesh.positions[t.y]),
                          point(mesh.positions[t.z]));
        // CGAL's triangle intersection tests require non-degenerate triangles;
        // a degenerate one has no area and blocks nothing a neighbour does not.
        if (!tri.is_degenerate()) tree_->triangles.push_back(tri);
    }
    tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
    // Built now: the tree would otherwise build itself lazily on the first
    // query, which is not thread-safe.
    tree_->tree.build();
}

RayCaster::~RayCaster() = default;

bool RayCaster::segmentClear(const glm::dvec3& a, const glm::dvec3& b) const {
    // A point segment has no direction to be blocked in (CGAL requires a proper one).
    if (tree_->triangles.empty() || a == b) return true;
    return !tree_->tree.do_intersect(K::Segment_3(point(a), point(b)));
}

size_t RayCaster::triangleCount() const {
    return tree_->triangles.size();
}

}  // namespace tsis

// First-hit rays from inside a mesh, the volumetric walk's workload: Embree 3
// (volumetric/mesh_boundary.h) against CGAL's AABB tree (first_intersection
// with exact predicates, as render/ray_caster.cpp builds it). Prints rays per
// second of each on one thread.
//   bench_raycast [MESH]   (default builtin:sphere)
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cstdio>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/mesh_io.h"
#include "volumetric/dielectric.h"
#include "volumetric/mesh_boundary.h"
#include "volumetric/rng.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

int main(int argc, char** argv) {
    using namespace tsis;
    Mesh mesh = loadMesh(argc > 1 ? argv[1] : "builtin:sphere");
    normalizeMesh(mesh, 10.0);
    ensureNormals(mesh);
    const int n = 200000;
    std::vector<glm::dvec3> origins, dirs;
    Rng rng(1, 1);
    for (int i = 0; i < n; ++i) {  // points near the centre, random directions
        origins.push_back(uniformSphere(rng.uniform(), rng.uniform()) * rng.uniform());
        dirs.push_back(uniformSphere(rng.uniform(), rng.uniform()));
    }
    MeshBoundary embree(mesh);
    Triangles tris;
    for (const glm::uvec3& t : mesh.triangles) {
        auto p = [&](unsigned i) {
            return K::Point_3(mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
        };
        K::Triangle_3 tri(p(t.x), p(t.y), p(t.z));
        if (!tri.is_degenerate()) tris.push_back(tri);
    }
    Tree tree(tris.cbegin(), tris.cend());
    tree.build();
    auto time = [&](auto&& body) {
        const auto t0 = std::chrono::steady_clock::now();
        double hits = 0;
        for (int i = 0; i < n; ++i) hits += body(i);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return std::make_pair(n / s, hits);
    };
    const auto e = time([&](int i) {
        SurfaceHit h;
        return embree.intersect(origins[i], dirs[i], kInfinity, h) ? h.t : 0.0;
    });
    const auto c = time([&](int i) {
        const K::Ray_3 ray(K::Point_3(origins[i].x, origins[i].y, origins[i].z),
                           K::Vector_3(dirs[i].x, dirs[i].y, dirs[i].z));
        const auto hit = tree.first_intersection(ray);
        if (!hit) return 0.0;
        const K::Point_3* p = boost::get<K::Point_3>(&hit->first);
        return p ? std::sqrt(CGAL::squared_distance(ray.source(), *p)) : 0.0;
    });
    std::printf(
        "%s, %zu triangles: Embree %.0f rays/s, CGAL %.0f rays/s (%.1f×); mean t %.6f / %.6f\n",
        mesh.name.c_str(), mesh.triangles.size(), e.first, c.first, e.first / c.first, e.second / n,
        c.second / n);
}

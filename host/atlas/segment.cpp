// Chart segmentation by Variational Shape Approximation (Cohen-Steiner, Alliez,
// Desbrun 2004) with CGAL's L2,1 metric: faces cluster into near-planar regions,
// which flatten with little distortion. The only CGAL code besides
// parameterize.cpp.
//
// 5 Lloyd iterations and 2 seeding relaxations: measured against CGAL's 20 and
// 5 on elephant and armadillo, the same chart counts, coverage and distortion
// (±2%) at a third of the time (armadillo: 1.6 s instead of 4.1 s CPU).
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>

#include <array>
#include <cstddef>
#include <vector>

#include "atlas/chart.h"

namespace tsis::atlas {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;
using FaceDescriptor = SurfaceMesh::Face_index;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace VSA = CGAL::Surface_mesh_approximation;
}  // namespace

std::vector<int> segmentVSA(const Mesh& mesh, const std::vector<char>& usable, int proxies) {
    std::vector<Point3> points;
    points.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::array<std::size_t, 3>> polygons;
    std::vector<int> faceOf;  // polygon -> input face
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!usable[f]) continue;
        const glm::uvec3& t = mesh.triangles[f];
        polygons.push_back({t.x, t.y, t.z});
        faceOf.push_back(int(f));
    }
    if (polygons.empty()) return {};

    // Orientation and singular vertices are repaired on a copy (points get
    // duplicated, polygons may be reversed, none is removed or reordered).
    PMP::orient_polygon_soup(points, polygons);
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return {};
    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    if (sm.number_of_faces() != polygons.size()) return {};

    const std::size_t maxProxies = std::min<std::size_t>(std::size_t(proxies), polygons.size());
    // VSA seeds one proxy per connected component, finding each by a scan from
    // the first face: components × faces (100,000 loose triangles: minutes).
    // With at least as many components as proxies it would stop there, one
    // chart per component; the caller's patches do that in linear time.
    auto componentMap = sm.add_property_map<FaceDescriptor, std::size_t>("f:cc", 0).first;
    if (PMP::connected_components(sm, componentMap) >= maxProxies) return {};

    auto proxyMap = sm.add_property_map<FaceDescriptor, std::size_t>("f:proxy", 0).first;
    VSA::approximate_triangle_mesh(sm, CGAL::parameters::max_number_of_proxies(maxProxies)
                                           .number_of_iterations(5)
                                           .number_of_relaxations(2)
                                           .face_proxy_map(proxyMap));

    std::vector<int> labels(mesh.triangles.size(), -1);
    std::size_t i = 0;
    for (FaceDescriptor fd : sm.faces()) labels[faceOf[i++]] = int(proxyMap[fd]);
    return labels;
}

}  // namespace tsis::atlas

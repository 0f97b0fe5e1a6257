// Chart parameterisation: CGAL's ARAP_parameterizer_3 (Liu et al. 2008) at its
// default λ = 1000 (λ = 0 would be the conformal ASAP map). Measured on the CGAL
// data meshes, LSCM gave about 4× the area distortion and the authalic / fixed-
// border parameterizers pin the border to a circle, so ARAP it is.
//
// CGAL's ARAP re-factorises its constant system matrix twice per iteration;
// CachedLU factorises it once per chart.
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <array>
#include <cstddef>
#include <vector>

#include "atlas/chart.h"

namespace tsis::atlas {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;
using VertexIndex = SurfaceMesh::Vertex_index;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

using EigenMatrix = CGAL::Eigen_sparse_matrix<double>::EigenType;

// Eigen SparseLU that factorises a matrix once and reuses the factors while it
// is asked to solve with the same matrix object (ARAP's A is constant).
class CachedLU : public CGAL::Eigen_solver_traits<Eigen::SparseLU<EigenMatrix>> {
  public:
    using Base = CGAL::Eigen_solver_traits<Eigen::SparseLU<EigenMatrix>>;
    bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D) {
        D = 1;
        if (factored_ != &A) {
            if (!factor(A, D)) return false;
            factored_ = &A;
        }
        return Base::linear_solver(B, X);
    }

  private:
    const Matrix* factored_ = nullptr;
};

using Parameterizer = SMP::ARAP_parameterizer_3<SurfaceMesh, CGAL::Default, CachedLU>;
}  // namespace

bool parameterizeARAP(const ChartMesh& chart, std::vector<glm::dvec2>& uv, std::string* why) {
    std::vector<Point3> points;
    points.reserve(chart.positions.size());
    for (const glm::dvec3& p : chart.positions) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::array<std::size_t, 3>> polygons;
    polygons.reserve(chart.triangles.size());
    for (const Tri& t : chart.triangles)
        polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});

    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    if (sm.number_of_vertices() != points.size() || sm.number_of_faces() != polygons.size()) {
        if (why) *why = "not a polygon mesh";
        return false;
    }
    // The chart is a disk: any border halfedge names its one border.
    SurfaceMesh::Halfedge_index border = SurfaceMesh::null_halfedge();
    for (SurfaceMesh::Halfedge_index h : sm.halfedges())
        if (sm.is_border(h)) {
            border = h;
            break;
        }
    if (border == SurfaceMesh::null_halfedge()) {
        if (why) *why = "no border";
        return false;
    }
    auto uvMap = sm.add_property_map<VertexIndex, Point2>("v:uv", Point2(0, 0)).first;
    Parameterizer arap;  // λ = 1000, 50 iterations, tolerance 1e-6
    const SMP::Error_code status = SMP::parameterize(sm, arap, border, uvMap);
    if (status != SMP::OK) {
        if (why) *why = SMP::get_error_message(status);
        return false;
    }
    uv.resize(points.size());
    for (VertexIndex v : sm.vertices()) uv[v.idx()] = glm::dvec2(uvMap[v].x(), uvMap[v].y());
    return true;
}

}  // namespace tsis::atlas

// A mesh's atlas texels: which triangle holds each texel centre (the rule GL
// rasterises the geometry atlas by) and the surface area each texel stands for.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "mesh/mesh.h"
#include "util/union_find.h"

namespace tsis {

// Calls fn(triangle, x, y) for every texel centre ((x+½)/res, (y+½)/res) inside
// a triangle's UV image; a centre on an edge shared by two triangles goes to
// one of them (a top-left-style rule). y counts up from v = 0.
void rasterUVTriangles(const Mesh& mesh, int resolution,
                       const std::function<void(size_t tri, int x, int y)>& fn);

// Calls fn(x, y, s, r) for every texel of a res² atlas whose centre lies
// within `reach` texels of triangle `tri`'s UV bounding box (0.5: the
// texels the box touches), with the centre's barycentrics (s, r) towards
// the triangle's corners 1 and 2 — inside where s, r ≥ 0 and s + r ≤ 1 (the
// caller's test, with its own tolerance); nothing for a triangle without UV
// area. Unlike rasterUVTriangles, a centre on an edge is every touching
// triangle's (the per-texel bakes keep the last).
void forEachTexelNear(const Mesh& mesh, const glm::uvec3& tri, int resolution, double reach,
                      const std::function<void(int x, int y, double s, double r)>& fn);

// The mesh's UV charts: its vertices joined when a triangle shares them (a
// chart's id is its root, the smallest vertex index in it).
UnionFind uvCharts(const Mesh& mesh);

// Per triangle, A3D/AUV: its surface area over its UV area (0 for a triangle
// without UV area, which holds no texel).
std::vector<double> areaRatios(const Mesh& mesh);

// Per triangle, the surface area of one texel over its UV area (mm² per unit
// UV area), so that the texels a chart holds at `resolution` sum to the
// chart's surface area. Texel centres sample a chart's border: alone
// (A3D/AUV) they miss or add up to half a texel along it, a few per cent of
// the flux of a small chart, which a material blurring over several charts
// shows as blotches. A chart that holds no texel centre keeps A3D/AUV.
std::vector<float> texelAreaRatios(const Mesh& mesh, int resolution);

}  // namespace tsis

// Internal pieces of the atlas builder shared by its .cpp files. Plain structs
// only: the CGAL code stays in segment.cpp and parameterize.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/mesh.h"
#include "util/union_find.h"

namespace tsis::atlas {

using Tri = std::array<int, 3>;

// Face adjacency of a triangle soup. Edge e of face f runs from corner e to
// corner (e+1)%3. Two faces are neighbours across an edge only when exactly two
// usable faces use it, in opposite directions (a consistently oriented manifold
// edge); everything else is a border.
struct Adjacency {
    std::vector<std::array<int, 3>> across;  // neighbour face or -1
    std::vector<char> usable;                // non-degenerate faces
};

// One round of merging pieces into their neighbours: every labelled face f
// (label ≥ 0) whose piece `pieceOf(f)` `moves(piece, f)` takes the label its
// piece shares the most edges with across `adj` (ties: the smallest label).
// The counts are made before any label changes. False when no moving piece
// touches another label.
template <typename PieceOf, typename Moves>
bool moveToMostSharedLabel(const Adjacency& adj, std::vector<int>& labels, PieceOf pieceOf,
                           Moves moves) {
    std::unordered_map<size_t, std::vector<std::pair<int, int>>> border;  // piece -> (label, edges)
    for (size_t f = 0; f < labels.size(); ++f) {
        if (labels[f] < 0) continue;
        const size_t piece = pieceOf(f);
        if (!moves(piece, f)) continue;
        for (const int g : adj.across[f]) {
            if (g < 0 || labels[size_t(g)] < 0 || labels[size_t(g)] == labels[f]) continue;
            auto& list = border[piece];
            auto it = std::find_if(list.begin(), list.end(),
                                   [&](const auto& p) { return p.first == labels[size_t(g)]; });
            if (it == list.end())
                list.emplace_back(labels[size_t(g)], 1);
            else
                ++it->second;
        }
    }
    if (border.empty()) return false;
    std::unordered_map<size_t, int> target;
    for (const auto& [piece, list] : border) {
        auto best = list.front();
        for (const auto& p : list)
            if (p.second > best.second || (p.second == best.second && p.first < best.first))
                best = p;
        target[piece] = best.first;
    }
    for (size_t f = 0; f < labels.size(); ++f)
        if (labels[f] >= 0)
            if (auto it = target.find(pieceOf(f)); it != target.end()) labels[f] = it->second;
    return true;
}
Adjacency buildAdjacency(const Mesh& mesh);

// A topological disk ready for parameterisation: local vertices (a vertex of
// the input split where the chart's faces around it form several fans).
struct ChartMesh {
    std::vector<glm::dvec3> positions;
    std::vector<uint32_t> sourceVertex;  // local vertex -> input vertex
    std::vector<Tri> triangles;          // local vertex indices, input orientation
    std::vector<uint32_t> faces;         // local triangle -> input triangle
};

// segment.cpp — VSA labels per face (-1 for unusable faces), or an empty
// vector when CGAL cannot make a polygon mesh of the soup or it has at least
// `proxies` connected components (VSA would cost components × faces).
// parts > 1: the usable faces cut into that many parts (splitFaces), each
// segmented on its own with proxies in proportion to its faces, on up to
// `threads` threads; labels are unique across parts and do not depend on
// `threads`. A part CGAL cannot segment makes it segment the whole mesh.
std::vector<int> segmentVSA(const Mesh& mesh, const Adjacency& adj, int proxies, int parts = 1,
                            int threads = 1);

// split.cpp — a part (0 … parts−1) per usable face, -1 for unusable ones: the
// faces' centroids cut recursively across the longest side of their bounding
// box into parts of about equal face count; then pieces of a part cut off
// from its largest piece join the neighbouring part they share most edges
// with, so each part is one face-connected piece where the mesh allows.
std::vector<int> splitFaces(const Mesh& mesh, const Adjacency& adj, int parts);

// smooth.cpp — the shape charts are made of. A noisy scan (looksLikeNoisyScan)
// is charted on a copy smoothed by Taubin's λ|μ steps (same connectivity) until
// its median angle between neighbouring faces is at most kSmoothDihedralDegrees;
// other meshes as they are (nullopt: no copy). `iterations`: the λ|μ pairs
// applied.
//
// Noise is relief at the triangles' scale: a median angle between neighbouring
// faces above kRoughDihedralDegrees (the data meshes: 3–12°) whose sharp edges
// are ridges and valleys alike (at least kMinConcaveShare valleys), on at least
// kMinScanFaces faces. A box, a slab or a low-poly solid also has a high median
// (a box: 90°) but its sharp edges are ridges; smoothed, a 2 mm slab became a
// pillow whose faces mapped to strips (coverage 0.017 instead of 0.5).
constexpr double kRoughDihedralDegrees = 20;
constexpr double kSmoothDihedralDegrees = 10;
constexpr double kMinConcaveShare = 0.25;
constexpr size_t kMinScanFaces = 1000;
constexpr int kMaxSmoothingIterations = 64;
double medianDihedralDegrees(const Mesh& mesh, const Adjacency& adj);
// Of the edges sharper than kRoughDihedralDegrees, the share that are valleys.
double concaveShareOfSharpEdges(const Mesh& mesh, const Adjacency& adj);
bool looksLikeNoisyScan(const Mesh& mesh, const Adjacency& adj);
std::optional<Mesh> smoothedForCharting(const Mesh& mesh, const Adjacency& adj,
                                        int* iterations = nullptr);

// parameterize.cpp — ARAP (λ = 1000) of a disk. Returns false (with a reason)
// when CGAL reports an error; the result is not validated here.
bool parameterizeARAP(const ChartMesh& chart, std::vector<glm::dvec2>& uv, std::string* why);

// charts.cpp — charts from labels: connected, disk-shaped, parameterised and
// validated pieces, in a deterministic order (by smallest input face).
struct Chart {
    ChartMesh mesh;
    std::vector<glm::dvec2> uv;  // per local vertex, same area as in 3D (ΣAUV = ΣA3D)
};
struct ChartOptions {
    double maxDistortion = 0.06;
    int threads = 0;
    // Called (under a lock) with the fraction of faces in finished charts; when
    // empty, makeCharts reports on its own Progress line.
    std::function<void(double)> onProgress;
};
std::vector<Chart> makeCharts(const Mesh& mesh, const Adjacency& adj,
                              const std::vector<int>& labels, const ChartOptions& opt);

// Charts whose smallest bounding rectangle is more than maxAspect times longer
// than wide cut in two across the middle of its long side (triangles by
// centroid), each half split into its vertex-connected pieces, recursively.
// UVs are kept (so distortion is unchanged); long thin charts pack badly.
void splitElongatedCharts(std::vector<Chart>& charts, double maxAspect);

// Label post-processing: majority filters over edge neighbours and over the
// faces around a face's vertices (which removes the one- and two-triangle-wide
// spikes VSA leaves on fine meshes); with borderRadius > 0, a strict-majority
// filter over the faces within that many vertex rings of each border face
// (which straightens borders jagged over several triangles); then connected
// pieces smaller than minFaces merged into the neighbour they share most
// edges with.
void smoothLabels(const Mesh& mesh, const Adjacency& adj, std::vector<int>& labels, int minFaces,
                  int borderRadius = 0);

// Area-weighted RMS of log(r) of a parameterised chart (after scaling UVs to
// the chart's 3D area); +inf when a triangle is flipped or degenerate in UV.
double chartDistortion(const ChartMesh& chart, const std::vector<glm::dvec2>& uv);

// True when segments [a,b] and [c,d] share a point (exact for coordinates
// whose pairwise differences are exact in double, e.g. floats in [0,1]).
bool segmentsIntersect(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d);

// Indices i of segments that intersect some other segment they do not share an
// endpoint id with (ids: endpoints' vertex ids, used to skip neighbours).
struct Segment {
    glm::dvec2 a, b;
    uint32_t ia, ib;  // endpoint ids
};
std::vector<size_t> intersectingSegments(const std::vector<Segment>& segs);

}  // namespace tsis::atlas

// Charts: from per-face labels to parameterised topological disks.
//
// A chart's surface is its faces glued along the edges they share with a
// neighbour of the same chart (Adjacency: manifold, consistently oriented
// edges only). Its vertices are the classes of face corners glued through those
// edges, so an input vertex where the chart's faces form several fans becomes
// several chart vertices, and every chart vertex is one fan: the chart is a
// 2-manifold with border. It is a disk when it is connected, V − E + F = 1 and
// its border is one loop. A piece that is not a disk, whose ARAP solve fails,
// or whose map is not injective or too distorted is split in two at the
// geodesic Voronoi boundary of two far-apart faces; a single triangle is laid
// out isometrically, so splitting ends.
#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <queue>
#include <thread>
#include <unordered_map>
#include <unordered_set>

#include "atlas/chart.h"
#include "atlas/pack.h"
#include "util/error.h"
#include "util/progress.h"

namespace tsis::atlas {

namespace {

glm::dvec3 pos(const Mesh& m, uint32_t v) {
    return glm::dvec3(m.positions[v]);
}

double area3(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

double signedArea2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Exact sign of the 2D orientation determinant: a double evaluation with an
// error filter, then quad precision, which holds the products of coordinate
// differences of floats exactly.
__extension__ typedef __float128 Quad;
int orient(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const double l = (b.x - a.x) * (c.y - a.y), r = (b.y - a.y) * (c.x - a.x);
    const double det = l - r;
    const double bound = 3.4e-16 * (std::abs(l) + std::abs(r));
    if (det > bound) return 1;
    if (det < -bound) return -1;
    const Quad ql = (Quad(b.x) - Quad(a.x)) * (Quad(c.y) - Quad(a.y));
    const Quad qr = (Quad(b.y) - Quad(a.y)) * (Quad(c.x) - Quad(a.x));
    const Quad q = ql - qr;
    return q > 0 ? 1 : (q < 0 ? -1 : 0);
}

bool onSegment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {  // p collinear with a, b
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

}  // namespace

bool segmentsIntersect(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
              o4 = orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    if (o1 == 0 && onSegment(a, b, c)) return true;
    if (o2 == 0 && onSegment(a, b, d)) return true;
    if (o3 == 0 && onSegment(c, d, a)) return true;
    if (o4 == 0 && onSegment(c, d, b)) return true;
    return false;
}

std::vector<size_t> intersectingSegments(const std::vector<Segment>& segs) {
    if (segs.size() < 2) return {};
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    double total = 0;
    for (const Segment& s : segs) {
        lo = glm::min(lo, glm::min(s.a, s.b));
        hi = glm::max(hi, glm::max(s.a, s.b));
        total += glm::length(s.b - s.a);
    }
    // A uniform grid with about one cell per segment, cells no smaller than the
    // mean segment length.
    const glm::dvec2 ext = glm::max(hi - lo, glm::dvec2(1e-300));
    double cell =
        std::max(total / double(segs.size()), std::sqrt(ext.x * ext.y / double(segs.size())));
    cell = std::max(cell, std::max(ext.x, ext.y) / 4096.0);
    const int nx = std::max(1, int(ext.x / cell) + 1), ny = std::max(1, int(ext.y / cell) + 1);
    std::vector<std::vector<uint32_t>> grid(size_t(nx) * size_t(ny));
    auto cellOf = [&](double v, double l, int n) {
        return std::clamp(int((v - l) / cell), 0, n - 1);
    };
    for (size_t i = 0; i < segs.size(); ++i) {
        const glm::dvec2 a = glm::min(segs[i].a, segs[i].b), b = glm::max(segs[i].a, segs[i].b);
        for (int y = cellOf(a.y, lo.y, ny); y <= cellOf(b.y, lo.y, ny); ++y)
            for (int x = cellOf(a.x, lo.x, nx); x <= cellOf(b.x, lo.x, nx); ++x)
                grid[size_t(y) * nx + x].push_back(uint32_t(i));
    }
    std::vector<char> hit(segs.size(), 0);
    for (const auto& bucket : grid) {
        for (size_t p = 0; p < bucket.size(); ++p) {
            const Segment& s = segs[bucket[p]];
            for (size_t q = p + 1; q < bucket.size(); ++q) {
                const Segment& t = segs[bucket[q]];
                if (s.ia == t.ia || s.ia == t.ib || s.ib == t.ia || s.ib == t.ib) continue;
                if (hit[bucket[p]] && hit[bucket[q]]) continue;
                if (std::max(s.a.x, s.b.x) < std::min(t.a.x, t.b.x) ||
                    std::max(t.a.x, t.b.x) < std::min(s.a.x, s.b.x) ||
                    std::max(s.a.y, s.b.y) < std::min(t.a.y, t.b.y) ||
                    std::max(t.a.y, t.b.y) < std::min(s.a.y, s.b.y))
                    continue;
                if (segmentsIntersect(s.a, s.b, t.a, t.b)) hit[bucket[p]] = hit[bucket[q]] = 1;
            }
        }
    }
    std::vector<size_t> out;
    for (size_t i = 0; i < segs.size(); ++i)
        if (hit[i]) out.push_back(i);
    return out;
}

Adjacency buildAdjacency(const Mesh& mesh) {
    const size_t n = mesh.triangles.size();
    Adjacency adj;
    adj.across.assign(n, {-1, -1, -1});
    adj.usable.assign(n, 0);
    double total = 0;
    std::vector<double> areas(n, 0);
    for (size_t f = 0; f < n; ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        if (t.x == t.y || t.y == t.z || t.z == t.x) continue;
        areas[f] = area3(pos(mesh, t.x), pos(mesh, t.y), pos(mesh, t.z));
        total += areas[f];
    }
    const double tiny = 1e-10 * total / double(std::max<size_t>(n, 1));
    for (size_t f = 0; f < n; ++f) adj.usable[f] = areas[f] > tiny;

    // Half-edges sorted by undirected edge key.
    std::vector<std::pair<uint64_t, uint32_t>> half;  // key, f*3+e
    half.reserve(3 * n);
    for (size_t f = 0; f < n; ++f) {
        if (!adj.usable[f]) continue;
        const glm::uvec3 t = mesh.triangles[f];
        for (int e = 0; e < 3; ++e) {
            const uint64_t a = t[e], b = t[(e + 1) % 3];
            half.emplace_back((std::min(a, b) << 32) | std::max(a, b), uint32_t(f * 3 + e));
        }
    }
    std::sort(half.begin(), half.end());
    for (size_t i = 0; i < half.size();) {
        size_t j = i;
        while (j < half.size() && half[j].first == half[i].first) ++j;
        if (j - i == 2) {
            const uint32_t h0 = half[i].second, h1 = half[i + 1].second;
            const uint32_t f0 = h0 / 3, e0 = h0 % 3, f1 = h1 / 3, e1 = h1 % 3;
            const uint32_t from0 = mesh.triangles[f0][e0], from1 = mesh.triangles[f1][e1];
            if (from0 != from1 && f0 != f1) {  // opposite directions
                adj.across[f0][e0] = int(f1);
                adj.across[f1][e1] = int(f0);
            }
        }
        i = j;
    }
    return adj;
}

namespace {

// Vertices of more faces than this (coincident copies of a triangle, a fan of
// thousands) are hubs: visiting their faces from each of their faces costs
// degree², so the filters below count a hub's labels in a histogram instead
// (vertexRingRule) or do not walk through it (straightenBorders). Ordinary
// vertices, poles of fine spheres included, stay below it.
constexpr uint32_t kHubDegree = 256;

// Strict-majority filter over the faces within `radius` vertex rings of each
// border face (start/ring: the faces around each vertex), in place, until
// nothing changes (at most 4·radius passes). After the first pass only faces
// near a change are looked at again: the others would decide as before.
void straightenBorders(const Mesh& mesh, const std::vector<uint32_t>& start,
                       const std::vector<uint32_t>& ring, std::vector<int>& labels, int radius) {
    const size_t n = labels.size();
    std::vector<uint32_t> faceSeen(n, 0), vertexSeen(mesh.positions.size(), 0);
    uint32_t stamp = 0;
    std::vector<uint32_t> front, next, near;
    std::unordered_map<int, int> votes;
    std::vector<char> dirty(n, 1);
    for (int pass = 0; pass < 4 * radius; ++pass) {
        size_t changed = 0;
        for (size_t f = 0; f < n; ++f) {
            if (labels[f] < 0 || !dirty[f]) continue;
            dirty[f] = 0;
            // Faces within `radius` rings: breadth first over shared vertices.
            ++stamp;
            faceSeen[f] = stamp;
            front.assign(1, uint32_t(f));
            near.clear();
            bool border = false;
            for (int r = 0; r < radius && (r == 0 || border); ++r) {
                next.clear();
                for (uint32_t g : front)
                    for (int k = 0; k < 3; ++k) {
                        const uint32_t v = mesh.triangles[g][k];
                        if (vertexSeen[v] == stamp || start[v + 1] - start[v] > kHubDegree)
                            continue;
                        vertexSeen[v] = stamp;
                        for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
                            const uint32_t h = ring[i];
                            if (faceSeen[h] == stamp || labels[h] < 0) continue;
                            faceSeen[h] = stamp;
                            border |= labels[h] != labels[f];
                            next.push_back(h);
                            near.push_back(h);
                        }
                    }
                front.swap(next);
            }
            if (!border) continue;  // inside a label: no majority against it
            votes.clear();
            for (uint32_t h : near) ++votes[labels[h]];
            const int total = int(near.size());
            for (auto [l, c] : votes)
                if (l != labels[f] && 2 * c > total) {  // so also c > own
                    labels[f] = l;
                    ++changed;
                    for (uint32_t h : near) dirty[h] = 1;
                    break;
                }
        }
        if (changed == 0) break;
    }
}

// The vertex-ring rule of smoothLabels: a face's votes are the labels of the
// faces around each of its vertices (a face sharing two vertices votes twice),
// its own excepted. An ordinary vertex's faces are visited; a hub's are counted
// in a (vertex, label) histogram kept up to date as labels change. Only a label
// with 60% of a hub's faces can win through it, and that label is the hub's
// `top` (a strict majority is always the top: a hub's face count is fixed and
// top follows every increment), so the candidates stay few and the rule costs
// O(faces · ordinary degree), however many faces share a hub.
void vertexRingRule(const Mesh& mesh, const std::vector<uint32_t>& start,
                    const std::vector<uint32_t>& ring, std::vector<int>& labels) {
    const size_t n = labels.size();
    auto degree = [&](uint32_t v) { return start[v + 1] - start[v]; };
    std::unordered_map<uint64_t, int> hubCount;  // (vertex << 32 | label) -> faces
    std::unordered_map<uint32_t, int> top;       // hub -> its most frequent label
    auto count = [&](uint32_t v, int l) {
        const auto it = hubCount.find((uint64_t(v) << 32) | uint32_t(l));
        return it == hubCount.end() ? 0 : it->second;
    };
    auto bump = [&](uint32_t v, int l, int delta) {
        const int c = hubCount[(uint64_t(v) << 32) | uint32_t(l)] += delta;
        auto [it, fresh] = top.emplace(v, l);
        if (!fresh && delta > 0 && c > count(v, it->second)) it->second = l;
    };
    for (uint32_t v = 0; v + 1 < start.size(); ++v)
        if (degree(v) > kHubDegree)
            for (uint32_t i = start[v]; i < start[v + 1]; ++i) bump(v, labels[ring[i]], 1);

    std::vector<std::pair<int, int>> votes;  // label, count
    std::vector<uint32_t> hubs;
    for (int pass = 0; pass < 6; ++pass) {
        size_t changed = 0;
        for (size_t f = 0; f < n; ++f) {
            if (labels[f] < 0) continue;
            votes.clear();
            hubs.clear();
            int own = 0, total = 0;
            auto vote = [&](int l, int c) {
                auto it =
                    std::find_if(votes.begin(), votes.end(), [&](auto& p) { return p.first == l; });
                if (it == votes.end())
                    votes.emplace_back(l, c);
                else
                    it->second += c;
            };
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = mesh.triangles[f][k];
                if (degree(v) > kHubDegree) {
                    hubs.push_back(v);  // f is one of its faces
                    total += int(degree(v)) - 1;
                    own += count(v, labels[f]) - 1;
                    continue;
                }
                for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
                    const int l = labels[ring[i]];
                    if (ring[i] == f || l < 0) continue;
                    ++total;
                    if (l == labels[f])
                        ++own;
                    else
                        vote(l, 1);
                }
            }
            if (!hubs.empty()) {
                for (uint32_t h : hubs) {
                    const int t = top.at(h);
                    if (t != labels[f]) vote(t, 0);
                }
                for (auto& [l, c] : votes)
                    for (uint32_t h : hubs) c += count(h, l);
            }
            for (auto [l, c] : votes)
                if (c > own && 10 * c >= 6 * total) {
                    for (uint32_t h : hubs) {
                        bump(h, labels[f], -1);
                        bump(h, l, 1);
                    }
                    labels[f] = l;
                    ++changed;
                    break;
                }
        }
        if (changed == 0) break;
    }
}

}  // namespace

void smoothLabels(const Mesh& mesh, const Adjacency& adj, std::vector<int>& labels, int minFaces,
                  int borderRadius) {
    const size_t n = labels.size();
    // Edge rule: two or three neighbours agreeing on another label win.
    std::vector<int> next = labels;
    for (int pass = 0; pass < 8; ++pass) {
        size_t changed = 0;
        for (size_t f = 0; f < n; ++f) {
            if (labels[f] < 0) continue;
            int nl[3], k = 0, same = 0;
            for (int e = 0; e < 3; ++e) {
                const int g = adj.across[f][e];
                if (g < 0 || labels[g] < 0) continue;
                if (labels[g] == labels[f])
                    ++same;
                else
                    nl[k++] = labels[g];
            }
            int pick = labels[f];
            if (k >= 2 && nl[0] == nl[1])
                pick = nl[0];
            else if (k == 3 && (nl[0] == nl[2] || nl[1] == nl[2]))
                pick = nl[2];
            else if (same == 0 && k > 0)
                pick = *std::min_element(nl, nl + k);
            next[f] = pick;
            changed += pick != labels[f];
        }
        labels.swap(next);
        next = labels;
        if (changed == 0) break;
    }

    // Vertex-ring rule: a label that holds 60% of the faces around a face's
    // three vertices (and more than the face's own) takes it (in place, in
    // face order).
    std::vector<uint32_t> start(mesh.positions.size() + 1, 0), ring;
    for (size_t f = 0; f < n; ++f)
        if (labels[f] >= 0)
            for (int k = 0; k < 3; ++k) ++start[mesh.triangles[f][k] + 1];
    for (size_t v = 0; v < mesh.positions.size(); ++v) start[v + 1] += start[v];
    ring.resize(start.back());
    {
        std::vector<uint32_t> fillAt(start.begin(), start.end() - 1);
        for (size_t f = 0; f < n; ++f)
            if (labels[f] >= 0)
                for (int k = 0; k < 3; ++k) ring[fillAt[mesh.triangles[f][k]]++] = uint32_t(f);
    }
    vertexRingRule(mesh, start, ring, labels);
    if (borderRadius > 0) straightenBorders(mesh, start, ring, labels, borderRadius);

    // Small connected pieces join the neighbouring label they share most edges with.
    for (int round = 0; round < 3; ++round) {
        UnionFind comps{n};
        for (size_t f = 0; f < n; ++f)
            for (int e = 0; e < 3; ++e) {
                const int g = adj.across[f][e];
                if (g >= 0 && labels[f] >= 0 && labels[g] == labels[f]) comps.unite(int(f), g);
            }
        std::vector<int> size(n, 0);
        for (size_t f = 0; f < n; ++f)
            if (labels[f] >= 0) ++size[comps.find(int(f))];
        const bool moved = moveToMostSharedLabel(
            adj, labels, [&](size_t f) { return size_t(comps.find(int(f))); },
            [&](size_t piece, size_t) { return size[piece] < minFaces; });
        if (!moved) break;
    }
}

double chartDistortion(const ChartMesh& chart, const std::vector<glm::dvec2>& uv) {
    double sum3 = 0, sumUV = 0;
    std::vector<double> a3(chart.triangles.size()), auv(chart.triangles.size());
    for (size_t t = 0; t < chart.triangles.size(); ++t) {
        const Tri& tr = chart.triangles[t];
        a3[t] = area3(chart.positions[tr[0]], chart.positions[tr[1]], chart.positions[tr[2]]);
        auv[t] = signedArea2(uv[tr[0]], uv[tr[1]], uv[tr[2]]);
        if (!(auv[t] > 0) || !std::isfinite(auv[t])) return std::numeric_limits<double>::infinity();
        sum3 += a3[t];
        sumUV += auv[t];
    }
    const double k = sum3 / sumUV;
    double acc = 0;
    for (size_t t = 0; t < a3.size(); ++t) {
        const double l = std::log(a3[t] / auv[t] / k);
        acc += a3[t] * l * l;
    }
    return std::sqrt(acc / sum3);
}

namespace {

// One piece of work: a set of input faces (sorted).
using FaceSet = std::vector<int>;

struct Topology {
    std::vector<int> corner;                 // corner (3i+k) -> chart vertex
    std::vector<std::array<char, 3>> glued;  // edge glued to a neighbour in the set
    std::vector<std::array<int, 3>> across;  // neighbour's local index or -1
    int vertices = 0;
    int components = 0;
    std::vector<int> component;  // per local face
    int euler = 0, loops = 0;
    bool pinched = false;
    std::vector<std::vector<int>> loopFaces;  // local faces along each border loop
};

Topology analyse(const Mesh& mesh, const Adjacency& adj, const FaceSet& faces) {
    const int n = int(faces.size());
    auto local = [&](int f) {
        auto it = std::lower_bound(faces.begin(), faces.end(), f);
        return (it != faces.end() && *it == f) ? int(it - faces.begin()) : -1;
    };
    Topology topo;
    topo.glued.assign(n, {0, 0, 0});
    topo.across.assign(n, {-1, -1, -1});
    UnionFind corners{size_t(3 * n)}, comps{size_t(n)};
    for (int i = 0; i < n; ++i) {
        const int f = faces[i];
        for (int e = 0; e < 3; ++e) {
            const int g = adj.across[f][e];
            if (g < 0) continue;
            const int j = local(g);
            if (j < 0) continue;
            const uint32_t a = mesh.triangles[f][e], b = mesh.triangles[f][(e + 1) % 3];
            int eg = 0;
            while (eg < 3 && !(mesh.triangles[g][eg] == b && mesh.triangles[g][(eg + 1) % 3] == a))
                ++eg;
            TSIS_CHECK_LT(eg, 3);
            topo.glued[i][e] = 1;
            topo.across[i][e] = j;
            corners.unite(3 * i + e, 3 * j + (eg + 1) % 3);
            corners.unite(3 * i + (e + 1) % 3, 3 * j + eg);
            comps.unite(i, j);
        }
    }
    topo.corner.assign(3 * size_t(n), -1);
    std::vector<int> classId(3 * size_t(n), -1);
    for (int c = 0; c < 3 * n; ++c) {
        const int r = corners.find(c);
        if (classId[r] < 0) classId[r] = topo.vertices++;
        topo.corner[c] = classId[r];
    }
    std::vector<int> compId(size_t(n), -1);
    topo.component.resize(n);
    for (int i = 0; i < n; ++i) {
        const int r = comps.find(i);
        if (compId[r] < 0) compId[r] = topo.components++;
        topo.component[i] = compId[r];
    }
    if (topo.components != 1) return topo;

    // Border half-edges, pinches (two half-edges between the same chart
    // vertices that are not glued to each other), loops.
    int border = 0;
    std::unordered_set<uint64_t> seen;
    std::vector<int> outBorder(size_t(topo.vertices), -1);  // chart vertex -> half-edge 3i+e
    for (int i = 0; i < n; ++i)
        for (int e = 0; e < 3; ++e) {
            const uint64_t a = uint64_t(topo.corner[3 * i + e]),
                           b = uint64_t(topo.corner[3 * i + (e + 1) % 3]);
            if (a == b || !seen.insert((a << 32) | b).second) topo.pinched = true;
            if (!topo.glued[i][e]) {
                ++border;
                if (outBorder[a] >= 0) topo.pinched = true;
                outBorder[a] = 3 * i + e;
            }
        }
    for (int i = 0; i < n; ++i)
        for (int e = 0; e < 3; ++e) {
            if (topo.glued[i][e]) continue;
            const uint64_t a = uint64_t(topo.corner[3 * i + e]),
                           b = uint64_t(topo.corner[3 * i + (e + 1) % 3]);
            if (seen.count((b << 32) | a)) topo.pinched = true;
        }
    topo.euler = topo.vertices - (3 * n + border) / 2 + n;
    if (topo.pinched) return topo;
    std::vector<char> visited(size_t(3 * n), 0);
    for (int h = 0; h < 3 * n; ++h) {
        if (topo.glued[h / 3][h % 3] || visited[h]) continue;
        ++topo.loops;
        topo.loopFaces.emplace_back();
        int cur = h;
        while (!visited[cur]) {
            visited[cur] = 1;
            topo.loopFaces.back().push_back(cur / 3);
            const int end = topo.corner[3 * (cur / 3) + (cur % 3 + 1) % 3];
            cur = outBorder[end];
            if (cur < 0) {
                topo.pinched = true;
                return topo;
            }
        }
    }
    return topo;
}

// Dijkstra over glued face adjacency with centroid distances, from `seeds`;
// returns distance and the index of the nearest seed per local face.
void geodesic(const std::vector<glm::dvec3>& centroid, const Topology& topo,
              const std::vector<int>& seeds, std::vector<double>& dist, std::vector<int>& owner) {
    const size_t n = centroid.size();
    dist.assign(n, std::numeric_limits<double>::infinity());
    owner.assign(n, -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (size_t s = 0; s < seeds.size(); ++s) {
        dist[seeds[s]] = 0;
        owner[seeds[s]] = int(s);
        queue.emplace(0.0, seeds[s]);
    }
    while (!queue.empty()) {
        auto [d, i] = queue.top();
        queue.pop();
        if (d > dist[i]) continue;
        for (int e = 0; e < 3; ++e) {
            const int j = topo.across[i][e];
            if (j < 0) continue;
            const double nd = d + glm::length(centroid[j] - centroid[i]);
            if (nd < dist[j]) {
                dist[j] = nd;
                owner[j] = owner[i];
                queue.emplace(nd, j);
            }
        }
    }
}

int farthest(const std::vector<double>& dist, const std::vector<int>& among) {
    int best = among.front();
    for (int i : among)
        if (dist[i] > dist[best] || (dist[i] == dist[best] && i < best)) best = i;
    return best;
}

// Splits a connected piece in two at the geodesic Voronoi boundary of two far
// faces. With several border loops both seeds lie on the longest loop, so a
// tube is cut along its length (two disks) rather than across (two tubes).
std::pair<FaceSet, FaceSet> splitInTwo(const Mesh& mesh, const FaceSet& faces,
                                       const Topology& topo) {
    const size_t n = faces.size();
    std::vector<glm::dvec3> centroid(n);
    for (size_t i = 0; i < n; ++i) {
        const glm::uvec3 t = mesh.triangles[faces[i]];
        centroid[i] = (pos(mesh, t.x) + pos(mesh, t.y) + pos(mesh, t.z)) / 3.0;
    }
    std::vector<int> among(n);
    std::iota(among.begin(), among.end(), 0);
    if (topo.loops >= 2) {
        size_t longest = 0;
        for (size_t l = 1; l < topo.loopFaces.size(); ++l)
            if (topo.loopFaces[l].size() > topo.loopFaces[longest].size()) longest = l;
        among = topo.loopFaces[longest];
    }
    std::vector<double> dist;
    std::vector<int> owner;
    geodesic(centroid, topo, {among.front()}, dist, owner);
    const int a = farthest(dist, among);
    geodesic(centroid, topo, {a}, dist, owner);
    int b = farthest(dist, among);
    if (b == a) b = (a + 1) % int(n);
    geodesic(centroid, topo, {a, b}, dist, owner);
    std::pair<FaceSet, FaceSet> halves;
    for (size_t i = 0; i < n; ++i)
        (owner[i] == 1 ? halves.second : halves.first).push_back(faces[i]);
    TSIS_CHECK(!halves.first.empty() && !halves.second.empty());
    return halves;
}

// Chart vertex positions and local triangles of a disk piece.
ChartMesh chartMesh(const Mesh& mesh, const FaceSet& faces, const Topology& topo) {
    ChartMesh cm;
    cm.positions.resize(size_t(topo.vertices));
    cm.sourceVertex.resize(size_t(topo.vertices));
    cm.faces.assign(faces.begin(), faces.end());
    cm.triangles.resize(faces.size());
    for (size_t i = 0; i < faces.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const int v = topo.corner[3 * i + k];
            const uint32_t src = mesh.triangles[faces[i]][k];
            cm.triangles[i][k] = v;
            cm.sourceVertex[v] = src;
            cm.positions[v] = pos(mesh, src);
        }
    return cm;
}

// Validation of a parameterised disk: finite, every triangle positively
// oriented, a border that does not cross itself (together: an injective map),
// distortion under the limit.
bool acceptable(const ChartMesh& cm, const Topology& topo, std::vector<glm::dvec2>& uv,
                double maxDistortion) {
    double signedSum = 0;
    for (const Tri& t : cm.triangles) signedSum += signedArea2(uv[t[0]], uv[t[1]], uv[t[2]]);
    if (!std::isfinite(signedSum)) return false;
    if (signedSum < 0)
        for (glm::dvec2& p : uv) p.x = -p.x;
    const double d = chartDistortion(cm, uv);
    if (!(d <= maxDistortion)) return false;
    std::vector<Segment> border;
    for (size_t i = 0; i < cm.triangles.size(); ++i)
        for (int e = 0; e < 3; ++e)
            if (!topo.glued[i][e]) {
                const int a = cm.triangles[i][e], b = cm.triangles[i][(e + 1) % 3];
                border.push_back({uv[a], uv[b], uint32_t(a), uint32_t(b)});
            }
    return intersectingSegments(border).empty();
}

}  // namespace

std::vector<Chart> makeCharts(const Mesh& mesh, const Adjacency& adj,
                              const std::vector<int>& labels, const ChartOptions& opt) {
    // Initial pieces: faces grouped by label.
    std::vector<int> order;
    for (size_t f = 0; f < labels.size(); ++f)
        if (labels[f] >= 0) order.push_back(int(f));
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return labels[a] < labels[b]; });
    std::deque<FaceSet> queue;
    for (size_t i = 0; i < order.size();) {
        size_t j = i;
        FaceSet set;
        while (j < order.size() && labels[order[j]] == labels[order[i]]) set.push_back(order[j++]);
        std::sort(set.begin(), set.end());
        queue.push_back(std::move(set));
        i = j;
    }

    std::mutex mutex;
    std::condition_variable wake;
    int busy = 0;
    std::exception_ptr error;
    std::vector<Chart> charts;
    long long doneFaces = 0;
    std::optional<Progress> ownProgress;
    if (!opt.onProgress) ownProgress.emplace("atlas charts", (long long)order.size());

    auto process = [&](FaceSet faces, std::vector<FaceSet>& more) -> bool {
        const Topology topo = analyse(mesh, adj, faces);
        if (topo.components > 1) {
            std::vector<FaceSet> parts(size_t(topo.components));
            for (size_t i = 0; i < faces.size(); ++i) parts[topo.component[i]].push_back(faces[i]);
            for (auto& p : parts) more.push_back(std::move(p));
            return false;
        }
        Chart chart;
        chart.mesh = chartMesh(mesh, faces, topo);
        const bool disk = !topo.pinched && topo.euler == 1 && topo.loops == 1;
        bool ok = false;
        if (disk && faces.size() == 1) {
            const glm::dvec3 p0 = chart.mesh.positions[0], p1 = chart.mesh.positions[1],
                             p2 = chart.mesh.positions[2];
            const glm::dvec3 ex = glm::normalize(p1 - p0);
            const glm::dvec3 ny = glm::normalize((p2 - p0) - ex * glm::dot(p2 - p0, ex));
            chart.uv = {glm::dvec2(0), glm::dvec2(glm::length(p1 - p0), 0),
                        glm::dvec2(glm::dot(p2 - p0, ex), glm::dot(p2 - p0, ny))};
            ok = chart.uv[2].y > 0;
            if (!ok) {
                // A sliver float rounding made collinear (or a NaN normalisation):
                // a right triangle of its longest edge keeps it in the atlas, at
                // the (almost nil) area it has in 3D after the rescale below.
                const double e = std::max(
                    {glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2), 1e-12});
                chart.uv = {glm::dvec2(0), glm::dvec2(e, 0), glm::dvec2(0, e)};
                ok = std::isfinite(e);
            }
        } else if (disk) {
            std::string why;
            ok = parameterizeARAP(chart.mesh, chart.uv, &why) &&
                 acceptable(chart.mesh, topo, chart.uv, opt.maxDistortion);
        }
        if (!ok) {
            TSIS_CHECK_GT(faces.size(), size_t(1));  // a single usable triangle always works
            auto [a, b] = splitInTwo(mesh, faces, topo);
            more.push_back(std::move(a));
            more.push_back(std::move(b));
            return false;
        }
        // Same area in UV as in 3D: one density for every chart before packing.
        double s3 = 0, suv = 0;
        for (const Tri& t : chart.mesh.triangles) {
            s3 += area3(chart.mesh.positions[t[0]], chart.mesh.positions[t[1]],
                        chart.mesh.positions[t[2]]);
            suv += signedArea2(chart.uv[t[0]], chart.uv[t[1]], chart.uv[t[2]]);
        }
        const double k = std::sqrt(s3 / suv);
        for (glm::dvec2& p : chart.uv) p *= k;
        std::lock_guard lock(mutex);
        doneFaces += (long long)faces.size();
        if (opt.onProgress)
            opt.onProgress(double(doneFaces) / double(std::max<size_t>(order.size(), 1)));
        else
            ownProgress->update(doneFaces);
        charts.push_back(std::move(chart));
        return true;
    };

    auto worker = [&] {
        std::unique_lock lock(mutex);
        for (;;) {
            wake.wait(lock, [&] { return !queue.empty() || busy == 0 || error; });
            if (error || queue.empty()) break;
            FaceSet faces = std::move(queue.front());
            queue.pop_front();
            ++busy;
            lock.unlock();
            std::vector<FaceSet> more;
            try {
                process(std::move(faces), more);
            } catch (...) {
                lock.lock();
                if (!error) error = std::current_exception();
                --busy;
                wake.notify_all();
                break;
            }
            lock.lock();
            for (auto& m : more) queue.push_back(std::move(m));
            --busy;
            wake.notify_all();
        }
    };
    int threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
    threads = std::clamp(threads, 1, 64);
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
    if (ownProgress) ownProgress->finish();

    std::sort(charts.begin(), charts.end(), [](const Chart& a, const Chart& b) {
        return a.mesh.faces.front() < b.mesh.faces.front();
    });
    return charts;
}

namespace {

// The triangles `tris` of chart `c` as charts, one per piece connected through
// shared vertices (same UVs, local vertices renumbered).
void appendPieces(const Chart& c, const std::vector<uint32_t>& tris, std::vector<Chart>& out) {
    UnionFind sets(c.uv.size());
    for (uint32_t t : tris) {
        const Tri& tri = c.mesh.triangles[t];
        for (int k = 1; k < 3; ++k) sets.unite(uint32_t(tri[0]), uint32_t(tri[k]));
    }
    std::unordered_map<uint32_t, size_t> pieceOf;  // root -> index in out
    std::vector<int> local(c.uv.size(), -1);
    for (uint32_t t : tris) {
        const uint32_t root = sets.find(uint32_t(c.mesh.triangles[t][0]));
        auto [it, added] = pieceOf.emplace(root, out.size());
        if (added) out.emplace_back();
        Chart& p = out[it->second];
        Tri tri = c.mesh.triangles[t];
        for (int& v : tri) {
            if (local[v] < 0) {
                local[v] = int(p.uv.size());
                p.uv.push_back(c.uv[v]);
                p.mesh.positions.push_back(c.mesh.positions[v]);
                p.mesh.sourceVertex.push_back(c.mesh.sourceVertex[v]);
            }
            v = local[v];
        }
        p.mesh.triangles.push_back(tri);
        p.mesh.faces.push_back(c.mesh.faces[t]);
    }
}

}  // namespace

void splitElongatedCharts(std::vector<Chart>& charts, double maxAspect) {
    std::vector<Chart> done;
    std::deque<Chart> todo(std::make_move_iterator(charts.begin()),
                           std::make_move_iterator(charts.end()));
    while (!todo.empty()) {
        Chart c = std::move(todo.front());
        todo.pop_front();
        const glm::dvec2 r = minAreaRectRotation(c.uv);
        std::vector<double> along(c.uv.size());
        double lo = INFINITY, hi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
        for (size_t i = 0; i < c.uv.size(); ++i) {
            const glm::dvec2 p = c.uv[i];
            along[i] = r.x * p.x + r.y * p.y;
            const double y = -r.y * p.x + r.x * p.y;
            lo = std::min(lo, along[i]);
            hi = std::max(hi, along[i]);
            ylo = std::min(ylo, y);
            yhi = std::max(yhi, y);
        }
        if (c.mesh.triangles.size() < 2 || !(hi - lo > maxAspect * (yhi - ylo))) {
            done.push_back(std::move(c));
            continue;
        }
        const double mid = 0.5 * (lo + hi);
        std::vector<uint32_t> half[2];
        for (size_t t = 0; t < c.mesh.triangles.size(); ++t) {
            const Tri& tri = c.mesh.triangles[t];
            half[(along[tri[0]] + along[tri[1]] + along[tri[2]]) / 3 < mid ? 0 : 1].push_back(
                uint32_t(t));
        }
        if (half[0].empty() || half[1].empty()) {
            done.push_back(std::move(c));
            continue;
        }
        std::vector<Chart> pieces;
        for (const auto& h : half) appendPieces(c, h, pieces);
        for (Chart& p : pieces) todo.push_back(std::move(p));
    }
    charts = std::move(done);
}

}  // namespace tsis::atlas

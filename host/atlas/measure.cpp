// Atlas quality: distortion r, flips, overlaps, coverage.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>

#include "atlas/atlas.h"
#include "atlas/chart.h"
#include "mesh/uv_texels.h"
#include "util/error.h"

namespace tsis {

AtlasStats measureAtlas(const Mesh& mesh, int resolution) {
    TSIS_CHECK_GT(resolution, 0);
    TSIS_CHECK_EQ(mesh.uvs.size(), mesh.positions.size());
    AtlasStats st;
    const size_t n = mesh.triangles.size();
    std::vector<double> a3(n), auv(n);
    double total3 = 0;
    for (size_t t = 0; t < n; ++t) {
        const glm::uvec3 tr = mesh.triangles[t];
        const glm::dvec3 p0 = mesh.positions[tr.x], p1 = mesh.positions[tr.y],
                         p2 = mesh.positions[tr.z];
        a3[t] = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
        const glm::dvec2 u0 = mesh.uvs[tr.x], u1 = mesh.uvs[tr.y], u2 = mesh.uvs[tr.z];
        auv[t] = 0.5 * ((u1.x - u0.x) * (u2.y - u0.y) - (u1.y - u0.y) * (u2.x - u0.x));
        total3 += a3[t];
    }
    const double tiny3 = 1e-10 * total3 / double(std::max<size_t>(n, 1));

    // UV charts: triangles connected through shared vertices; a chart's
    // orientation is the sign of its total signed UV area.
    UnionFind charts = uvCharts(mesh);
    std::vector<double> chartSign(mesh.positions.size(), 0);
    std::vector<char> isRoot(mesh.positions.size(), 0);
    for (size_t t = 0; t < n; ++t) {
        if (a3[t] <= tiny3) continue;
        const uint32_t r = charts.find(mesh.triangles[t].x);
        chartSign[r] += auv[t];
        isRoot[r] = 1;
    }
    st.charts = int(std::count(isRoot.begin(), isRoot.end(), 1));

    // r over triangles with area in 3D; flipped ones do not enter r.
    std::vector<std::pair<double, double>> rw;  // ratio, weight
    double sum3 = 0, sumUV = 0;
    for (size_t t = 0; t < n; ++t) {
        if (a3[t] <= tiny3) continue;
        const double s = chartSign[charts.find(mesh.triangles[t].x)] < 0 ? -1 : 1;
        if (!(auv[t] * s > 0)) {
            ++st.flipped;
            continue;
        }
        rw.emplace_back(a3[t] / std::abs(auv[t]), a3[t]);
        sum3 += a3[t];
        sumUV += std::abs(auv[t]);
    }
    if (!rw.empty()) {
        const double k = sum3 / sumUV;
        double mean = 0;
        for (auto& [r, w] : rw) {
            r /= k;
            mean += r * w;
        }
        mean /= sum3;
        double var = 0;
        for (auto& [r, w] : rw) var += w * (r - mean) * (r - mean);
        st.rWstd = std::sqrt(var / sum3);
        std::sort(rw.begin(), rw.end());
        st.rMin = rw.front().first;
        st.rMax = rw.back().first;
        auto percentile = [&](double p) {
            double acc = 0;
            for (auto& [r, w] : rw) {
                acc += w;
                if (acc >= p * sum3) return r;
            }
            return rw.back().first;
        };
        st.rP01 = percentile(0.01);
        st.rP99 = percentile(0.99);
    }

    // Overlaps, 1: two triangles claiming one texel centre.
    std::vector<char> overlapped(n, 0);
    std::vector<int32_t> owner(size_t(resolution) * size_t(resolution), -1);
    size_t covered = 0;
    rasterUVTriangles(mesh, resolution, [&](size_t t, int x, int y) {
        int32_t& o = owner[size_t(y) * resolution + x];
        if (o < 0) {
            o = int32_t(t);
            ++covered;
        } else {
            overlapped[t] = overlapped[size_t(o)] = 1;
        }
    });
    st.coverage = double(covered) / (double(resolution) * resolution);

    // Overlaps, 2: exact intersection tests between border edges (edges of one
    // triangle only) that share no vertex.
    std::vector<std::pair<uint64_t, uint32_t>> edges;  // undirected key, triangle
    edges.reserve(3 * n);
    for (size_t t = 0; t < n; ++t) {
        if (a3[t] <= tiny3 && auv[t] == 0) continue;  // a degenerate triangle parked on a point
        const glm::uvec3 tr = mesh.triangles[t];
        for (int e = 0; e < 3; ++e) {
            const uint64_t a = tr[e], b = tr[(e + 1) % 3];
            edges.emplace_back((std::min(a, b) << 32) | std::max(a, b), uint32_t(t));
        }
    }
    std::sort(edges.begin(), edges.end());
    std::vector<atlas::Segment> segs;
    std::vector<uint32_t> segTri;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].first == edges[i].first) ++j;
        if (j - i == 1) {
            const uint32_t a = uint32_t(edges[i].first >> 32),
                           b = uint32_t(edges[i].first & 0xffffffffu);
            if (mesh.uvs[a] != mesh.uvs[b]) {
                segs.push_back({glm::dvec2(mesh.uvs[a]), glm::dvec2(mesh.uvs[b]), a, b});
                segTri.push_back(edges[i].second);
            }
        }
        i = j;
    }
    for (size_t s : atlas::intersectingSegments(segs)) overlapped[segTri[s]] = 1;
    st.overlaps = size_t(std::count(overlapped.begin(), overlapped.end(), 1));
    return st;
}

Json atlasStatsJson(const AtlasStats& s) {
    Json j = Json::object();
    j["charts"] = s.charts;
    j["coverage"] = s.coverage;
    j["r_wstd"] = s.rWstd;
    j["r_p01"] = s.rP01;
    j["r_p99"] = s.rP99;
    j["r_min"] = s.rMin;
    j["r_max"] = s.rMax;
    j["flipped"] = s.flipped;
    j["overlaps"] = s.overlaps;
    j["seconds"] = s.seconds;
    j["from_cache"] = s.fromCache;
    return j;
}

}  // namespace tsis

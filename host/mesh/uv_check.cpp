#include "mesh/uv_check.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <limits>
#include <tuple>

#include "util/error.h"

namespace tsis {

namespace {

constexpr double kRangeEps = 1e-6;    // UVs a rounding away from [0,1] are fine
constexpr double kMinUVArea = 1e-14;  // about a float ulp squared at 1.0
constexpr double kTouch = 1e-7;       // overlap shallower than this is touching
constexpr size_t kMaxPairs = 1000000;

struct Tri2 {
    glm::dvec2 p[3];
    glm::dvec2 lo, hi;
};

// Separating axis test on the six edge normals: two triangles overlap when no
// axis separates them by more than -kTouch, so neighbours that share an edge
// or a vertex (projections meeting exactly) never count.
bool overlap(const Tri2& a, const Tri2& b) {
    for (const Tri2* t : {&a, &b})
        for (int e = 0; e < 3; ++e) {
            const glm::dvec2 d = t->p[(e + 1) % 3] - t->p[e];
            const double len = std::hypot(d.x, d.y);
            const glm::dvec2 n(-d.y / len, d.x / len);
            double loA = std::numeric_limits<double>::max(), hiA = -loA, loB = loA, hiB = -loA;
            for (int k = 0; k < 3; ++k) {
                const double pa = n.x * a.p[k].x + n.y * a.p[k].y;
                const double pb = n.x * b.p[k].x + n.y * b.p[k].y;
                loA = std::min(loA, pa), hiA = std::max(hiA, pa);
                loB = std::min(loB, pb), hiB = std::max(hiB, pb);
            }
            if (hiA <= loB + kTouch || hiB <= loA + kTouch) return false;
        }
    return true;
}

}  // namespace

UVCheck checkUVs(const Mesh& mesh) {
    UVCheck r;
    if (!mesh.hasUVs()) {
        r.ok = false;
        r.problem = concat("UVs of '", mesh.name, "': the mesh has none");
        return r;
    }
    size_t firstOut = 0, firstDegenerate = 0;
    for (size_t i = 0; i < mesh.uvs.size(); ++i) {
        const glm::vec2 uv = mesh.uvs[i];
        const bool in = uv.x >= -kRangeEps && uv.x <= 1 + kRangeEps && uv.y >= -kRangeEps &&
                        uv.y <= 1 + kRangeEps;  // false for NaN too
        if (!in && r.outOfRange++ == 0) firstOut = i;
    }

    // Bin each usable triangle by its UV bounding box into a grid of about
    // one triangle per cell.
    const size_t n = mesh.triangles.size();
    std::vector<Tri2> tris(n);
    std::vector<char> usable(n, 0);
    for (size_t t = 0; t < n; ++t) {
        Tri2& tr = tris[t];
        for (int k = 0; k < 3; ++k) tr.p[k] = glm::dvec2(mesh.uvs[mesh.triangles[t][k]]);
        tr.lo = glm::min(tr.p[0], glm::min(tr.p[1], tr.p[2]));
        tr.hi = glm::max(tr.p[0], glm::max(tr.p[1], tr.p[2]));
        const double area = mesh.triangleUVArea(t);
        if (!(area >= kMinUVArea)) {
            if (r.degenerate++ == 0) firstDegenerate = t;
            continue;
        }
        usable[t] = std::isfinite(tr.lo.x + tr.lo.y + tr.hi.x + tr.hi.y);
    }
    // The grid spans the usable triangles' UV bounds within [0,1]², so a
    // chart packed into a corner still spreads over many cells and one wild
    // coordinate does not squash the rest into one cell.
    glm::dvec2 lo(1.0), hi(0.0);
    for (size_t t = 0; t < n; ++t)
        if (usable[t]) lo = glm::min(lo, tris[t].lo), hi = glm::max(hi, tris[t].hi);
    lo = glm::clamp(lo, 0.0, 1.0), hi = glm::clamp(hi, 0.0, 1.0);
    const int g = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(n))), 1, 1024);
    const glm::dvec2 scale = double(g) / glm::max(hi - lo, glm::dvec2(1e-300));
    // Clamped as doubles: converting an out-of-range double to int is undefined.
    auto cx = [&](double x) {
        return static_cast<int>(std::clamp((x - lo.x) * scale.x, 0.0, g - 1.0));
    };
    auto cy = [&](double y) {
        return static_cast<int>(std::clamp((y - lo.y) * scale.y, 0.0, g - 1.0));
    };
    std::vector<std::vector<uint32_t>> grid(static_cast<size_t>(g) * g);
    for (size_t t = 0; t < n; ++t) {
        if (!usable[t]) continue;
        for (int y = cy(tris[t].lo.y); y <= cy(tris[t].hi.y); ++y)
            for (int x = cx(tris[t].lo.x); x <= cx(tris[t].hi.x); ++x)
                grid[static_cast<size_t>(y) * g + x].push_back(static_cast<uint32_t>(t));
    }
    // A UV layout folded onto itself has O(n²) overlapping pairs: stop
    // counting at kMaxPairs rather than take minutes to say so.
    size_t firstA = 0, firstB = 0;
    bool capped = false;
    for (int y = 0; y < g && !capped; ++y)
        for (int x = 0; x < g && !capped; ++x) {
            const std::vector<uint32_t>& c = grid[static_cast<size_t>(y) * g + x];
            for (size_t i = 0; i < c.size() && !capped; ++i)
                for (size_t j = i + 1; j < c.size(); ++j) {
                    const Tri2 &a = tris[c[i]], &b = tris[c[j]];
                    const glm::dvec2 ilo = glm::max(a.lo, b.lo), ihi = glm::min(a.hi, b.hi);
                    if (ilo.x >= ihi.x || ilo.y >= ihi.y) continue;
                    // Test each pair once: in the cell holding the low corner
                    // of their bounding boxes' intersection.
                    if (cx(ilo.x) != x || cy(ilo.y) != y) continue;
                    if (!overlap(a, b)) continue;
                    const size_t p = std::min(c[i], c[j]), q = std::max(c[i], c[j]);
                    if (r.overlapping++ == 0 || std::tie(p, q) < std::tie(firstA, firstB))
                        firstA = p, firstB = q;
                    if (r.overlapping >= kMaxPairs) {
                        capped = true;
                        break;
                    }
                }
        }

    std::string problems;
    auto add = [&](const std::string& s) { problems += (problems.empty() ? "" : "; ") + s; };
    auto count = [](size_t n, const char* one, const char* many) {
        return concat(n, " ", n == 1 ? one : many);
    };
    if (r.outOfRange)
        add(concat(count(r.outOfRange, "vertex", "vertices"), " outside [0,1] (e.g. vertex ",
                   firstOut, ")"));
    if (r.degenerate)
        add(concat(count(r.degenerate, "degenerate triangle", "degenerate triangles"), " (e.g. ",
                   firstDegenerate, ")"));
    if (r.overlapping)
        add(concat(
            capped ? "at least " : "",
            count(r.overlapping, "pair of overlapping triangles", "pairs of overlapping triangles"),
            " (e.g. ", firstA, " and ", firstB, ")"));
    r.ok = problems.empty();
    if (!r.ok) r.problem = concat("UVs of '", mesh.name, "': ", problems);
    return r;
}

}  // namespace tsis

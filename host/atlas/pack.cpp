// Skyline packing of chart outlines; see pack.h.
#include "atlas/pack.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <thread>

#include "util/error.h"

namespace tsis::atlas {

namespace {

double cross(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(),
              [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (p.size() < 3) return p;
    std::vector<glm::dvec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

}  // namespace

glm::dvec2 minAreaRectRotation(const std::vector<glm::dvec2>& uv) {
    const std::vector<glm::dvec2> hull = convexHull(uv);
    glm::dvec2 best(1, 0);
    double bestArea = INFINITY, bestW = 0, bestH = 0;
    for (size_t i = 0; i < hull.size(); ++i) {
        glm::dvec2 e = hull[(i + 1) % hull.size()] - hull[i];
        const double len = std::hypot(e.x, e.y);
        if (len == 0) continue;
        e /= len;
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (glm::dvec2 p : hull) {
            const glm::dvec2 r(e.x * p.x + e.y * p.y, -e.y * p.x + e.x * p.y);
            lo = glm::min(lo, r);
            hi = glm::max(hi, r);
        }
        const double area = (hi.x - lo.x) * (hi.y - lo.y);
        if (area < bestArea * (1 - 1e-9)) {
            bestArea = area;
            best = e;
            bestW = hi.x - lo.x;
            bestH = hi.y - lo.y;
        }
    }
    if (bestH > bestW) best = glm::dvec2(-best.y, best.x);  // a quarter turn more
    return best;
}

namespace {

// A chart at one density and orientation: its dilated conservative raster as
// runs of texels per row.
struct Outline {
    int w = 0, h = 0;
    std::vector<std::vector<std::pair<int, int>>> runs;  // per row: [begin, end) columns
    std::vector<int> longest;                            // per row: longest run
    std::vector<int> testOrder;                          // rows, longest run first
    glm::dvec2 shift;  // frame coordinates = quarterTurns(rotated)·scale + shift
    int orientation = 0;
    long long texels = 0;
};

glm::dvec2 quarterTurns(glm::dvec2 p, int o) {
    for (int i = 0; i < o; ++i) p = glm::dvec2(-p.y, p.x);
    return p;
}

// An outline wider than maxW or taller than maxH cannot be placed: it gets its
// size (clamped to maxW+1 × maxH+1) and no raster, so a chart of vanishing area
// at a huge density costs nothing (the fuzzer found one that took seconds).
Outline makeOutline(const std::vector<glm::dvec2>& pts, const std::vector<Tri>& tris, double scale,
                    int o, int dilate, int maxW, int maxH) {
    constexpr double kEps = 1e-3;  // texels: float rounding of the final UVs stays inside
    Outline out;
    out.orientation = o;
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    std::vector<glm::dvec2> q(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        q[i] = quarterTurns(pts[i], o) * scale;
        lo = glm::min(lo, q[i]);
        hi = glm::max(hi, q[i]);
    }
    out.shift = glm::dvec2(dilate + kEps) - lo;
    for (glm::dvec2& p : q) p += out.shift;
    hi += out.shift;
    const double w = std::floor(hi.x + kEps) + 1 + dilate, h = std::floor(hi.y + kEps) + 1 + dilate;
    out.w = w <= maxW ? int(w) : maxW + 1;  // NaN too
    out.h = h <= maxH ? int(h) : maxH + 1;
    if (out.w > maxW || out.h > maxH) return out;
    std::vector<uint8_t> mask(size_t(out.w) * out.h, 0);
    for (const Tri& t : tris) {
        const glm::dvec2 v[3] = {q[t[0]], q[t[1]], q[t[2]]};
        const double ymin = std::min({v[0].y, v[1].y, v[2].y}),
                     ymax = std::max({v[0].y, v[1].y, v[2].y});
        const int ylo = std::max(0, int(std::floor(ymin - kEps))),
                  yhi = std::min(out.h - 1, int(std::floor(ymax + kEps)));
        for (int y = ylo; y <= yhi; ++y) {
            // x-extent of the triangle within the slab [y, y+1] (widened by kEps).
            const double y0 = y - kEps, y1 = y + 1 + kEps;
            double xmin = INFINITY, xmax = -INFINITY;
            for (int k = 0; k < 3; ++k) {
                const glm::dvec2 a = v[k], b = v[(k + 1) % 3];
                if (a.y >= y0 && a.y <= y1) {
                    xmin = std::min(xmin, a.x);
                    xmax = std::max(xmax, a.x);
                }
                for (double yl : {y0, y1})
                    if ((a.y < yl && b.y > yl) || (a.y > yl && b.y < yl)) {
                        const double x = a.x + (b.x - a.x) * (yl - a.y) / (b.y - a.y);
                        xmin = std::min(xmin, x);
                        xmax = std::max(xmax, x);
                    }
            }
            if (!(xmin <= xmax)) continue;
            const int x0 = std::max(0, int(std::floor(xmin - kEps)));
            const int x1 = std::min(out.w - 1, int(std::floor(xmax + kEps)));
            std::fill(mask.begin() + size_t(y) * out.w + x0,
                      mask.begin() + size_t(y) * out.w + x1 + 1, 1);
        }
    }
    // Chebyshev dilation: rows, then columns.
    if (dilate > 0) {
        std::vector<uint8_t> tmp(mask.size(), 0);
        for (int y = 0; y < out.h; ++y)
            for (int x = 0; x < out.w; ++x)
                if (mask[size_t(y) * out.w + x])
                    for (int xd = std::max(0, x - dilate); xd <= std::min(out.w - 1, x + dilate);
                         ++xd)
                        tmp[size_t(y) * out.w + xd] = 1;
        std::fill(mask.begin(), mask.end(), 0);
        for (int y = 0; y < out.h; ++y)
            for (int x = 0; x < out.w; ++x)
                if (tmp[size_t(y) * out.w + x])
                    for (int yd = std::max(0, y - dilate); yd <= std::min(out.h - 1, y + dilate);
                         ++yd)
                        mask[size_t(yd) * out.w + x] = 1;
    }
    out.runs.resize(size_t(out.h));
    out.longest.assign(size_t(out.h), 0);
    for (int y = 0; y < out.h; ++y) {
        const uint8_t* row = &mask[size_t(y) * out.w];
        for (int x = 0; x < out.w;) {
            if (!row[x]) {
                ++x;
                continue;
            }
            int e = x;
            while (e < out.w && row[e]) ++e;
            out.runs[y].emplace_back(x, e);
            out.longest[y] = std::max(out.longest[y], e - x);
            out.texels += e - x;
            x = e;
        }
    }
    out.testOrder.resize(size_t(out.h));
    std::iota(out.testOrder.begin(), out.testOrder.end(), 0);
    std::stable_sort(out.testOrder.begin(), out.testOrder.end(),
                     [&](int a, int b) { return out.longest[a] > out.longest[b]; });
    return out;
}

// Occupancy of the W×H packing area: a bit per texel, and per row the longest
// free run (an upper bound is enough: it only prunes).
class Occupancy {
  public:
    Occupancy(int W, int H)
        : W_(W), H_(H), words_((W + 63) / 64), bits_(size_t(words_) * H, 0), free_(size_t(H), W) {}

    // The last occupied column in [a, b) of row y, or -1.
    int lastOccupied(int y, int a, int b) const {
        const uint64_t* row = &bits_[size_t(y) * words_];
        for (int w = (b - 1) >> 6; w >= (a >> 6); --w) {
            uint64_t m = row[w];
            const int lo = w * 64, hi = lo + 64;
            if (a > lo) m &= ~uint64_t(0) << (a - lo);
            if (b < hi) m &= (b - lo) == 0 ? 0 : (~uint64_t(0) >> (64 - (b - lo)));
            if (m) return lo + 63 - __builtin_clzll(m);
        }
        return -1;
    }
    void fill(int y, int a, int b) {
        uint64_t* row = &bits_[size_t(y) * words_];
        for (int x = a; x < b; ++x) row[x >> 6] |= uint64_t(1) << (x & 63);
    }
    void updateFree(int y) {
        int best = 0, run = 0;
        const uint64_t* row = &bits_[size_t(y) * words_];
        for (int x = 0; x < W_; ++x) {
            if (row[x >> 6] >> (x & 63) & 1)
                run = 0;
            else
                best = std::max(best, ++run);
        }
        free_[y] = best;
    }
    int freeRun(int y) const { return free_[y]; }
    int width() const { return W_; }
    int height() const { return H_; }

  private:
    int W_, H_, words_;
    std::vector<uint64_t> bits_;
    std::vector<int> free_;
};

// The lowest (then leftmost) position where `ol` fits with its bottom row at
// most at yLimit; false when none.
bool firstFit(const Occupancy& occ, const Outline& ol, int yLimit, int& bx, int& by, int startY = 0,
              int startX = 0) {
    const int W = occ.width();
    int hot = ol.testOrder.front();  // the row that collided last is tried first
    auto collide = [&](int r, int x, int y) {
        for (auto [a, b] : ol.runs[r]) {
            const int p = occ.lastOccupied(y + r, x + a, x + b);
            if (p >= 0) return p - a + 1;
        }
        return -1;
    };
    for (int y = startY; y <= yLimit; ++y) {
        bool rowsFree = true;
        for (int r : ol.testOrder) {
            if (ol.longest[r] == 0) break;
            if (occ.freeRun(y + r) < ol.longest[r]) {
                rowsFree = false;
                break;
            }
        }
        if (!rowsFree) continue;
        for (int x = y == startY ? startX : 0; x + ol.w <= W;) {
            int jump = collide(hot, x, y);
            if (jump < 0)
                for (int r : ol.testOrder) {
                    if (r == hot) continue;
                    jump = collide(r, x, y);
                    if (jump >= 0) {
                        hot = r;
                        break;
                    }
                }
            if (jump < 0) {
                bx = x;
                by = y;
                return true;
            }
            x = jump;
        }
    }
    return false;
}

struct Placed {
    int x = 0, y = 0;
    int orientation = 0;
    glm::dvec2 shift;  // the outline's
};

// The outlines of every chart in its four orientations at one density, made
// when first asked for (shared by the orders tried at that density).
class Outlines {
  public:
    Outlines(const std::vector<std::vector<glm::dvec2>>& pts, const std::vector<PackChart>& charts,
             double scale, int dilate, int W, int H)
        : pts_(pts),
          charts_(charts),
          scale_(scale),
          dilate_(dilate),
          W_(W),
          H_(H),
          made_(4 * charts.size(), 0),
          outlines_(4 * charts.size()) {}
    const Outline& get(size_t c, int o) {
        const size_t i = 4 * c + size_t(o);
        if (!made_[i]) {
            outlines_[i] = makeOutline(pts_[c], *charts_[c].triangles, scale_, o, dilate_, W_, H_);
            made_[i] = 1;
        }
        return outlines_[i];
    }

  private:
    const std::vector<std::vector<glm::dvec2>>& pts_;
    const std::vector<PackChart>& charts_;
    double scale_;
    int dilate_, W_, H_;
    std::vector<char> made_;
    std::vector<Outline> outlines_;
};

// Packs all charts into W×H in one order; false when one does not fit.
bool packInOrder(Outlines& outlines, const std::vector<size_t>& order, int W, int H,
                 std::vector<Placed>& placed, double* footprint) {
    Occupancy occ(W, H);
    placed.assign(order.size(), Placed());
    long long used = 0;
    // Where the last search per orientation stopped. Positions scanned before
    // it did not fit an outline of the same shape, and only fill up since, so
    // the next chart of that shape (copies of one triangle: thousands in a
    // row) resumes there instead of rescanning every full row.
    struct Resume {
        const Outline* shape = nullptr;
        int y = 0, x = 0;
    } resume[4];
    auto sameShape = [](const Outline& a, const Outline& b) {
        return a.w == b.w && a.h == b.h && a.runs == b.runs;
    };
    for (size_t c : order) {
        int bestMid = INT_MAX;
        const Outline* best = nullptr;
        int bestX = 0, bestY = 0;
        for (int o = 0; o < 4; ++o) {
            const Outline& ol = outlines.get(c, o);
            if (ol.w > W || ol.h > H) continue;
            // The lowest middle row wins (measured a little better than the
            // lowest top or the lowest bottom); only y < bestMid - h/2 can.
            const int yLimit = std::min(H - ol.h, bestMid == INT_MAX ? H : bestMid - ol.h / 2 - 1);
            if (yLimit < 0) continue;
            Resume& r = resume[o];
            const bool same = r.shape && sameShape(*r.shape, ol);
            int x, y;
            if (firstFit(occ, ol, yLimit, x, y, same ? r.y : 0, same ? r.x : 0)) {
                bestMid = y + ol.h / 2;
                bestX = x;
                bestY = y;
                best = &ol;
                r = {&ol, y, x};
            } else {
                r = {&ol, yLimit + 1, 0};  // nothing fits up to yLimit
            }
        }
        if (!best) return false;
        const Outline& ol = *best;
        for (int r = 0; r < ol.h; ++r) {
            for (auto [a, b] : ol.runs[r]) occ.fill(bestY + r, bestX + a, bestX + b);
            if (!ol.runs[r].empty()) occ.updateFree(bestY + r);
        }
        used += ol.texels;
        placed[c] = {bestX, bestY, ol.orientation, ol.shift};
    }
    if (footprint) *footprint = double(used) / (double(W) * H);
    return true;
}

// Packs all charts at `scale`, trying each order until one fits; false when
// none does.
bool packAt(const std::vector<std::vector<glm::dvec2>>& pts, const std::vector<PackChart>& charts,
            const std::vector<std::vector<size_t>>& orders, double scale, int W, int H, int dilate,
            std::vector<Placed>& placed, double* footprint) {
    Outlines outlines(pts, charts, scale, dilate, W, H);
    for (const std::vector<size_t>& order : orders)
        if (packInOrder(outlines, order, W, H, placed, footprint)) return true;
    return false;
}

}  // namespace

PackResult packCharts(const std::vector<PackChart>& charts, int resolution, int gutterTexels,
                      int threads) {
    TSIS_CHECK_GT(resolution, 8);
    TSIS_CHECK_GE(gutterTexels, 0);
    PackResult result;
    if (charts.empty()) return result;
    const int dilate = (gutterTexels + 1) / 2;
    // Dilated frames may reach `dilate - 1` texels into the 1-texel margin.
    const int W = resolution - 2 + 2 * dilate, H = W;
    const int offset = 1 - dilate;

    // Each chart rotated to its smallest bounding rectangle.
    std::vector<std::vector<glm::dvec2>> pts(charts.size());
    double totalArea = 0;
    for (size_t c = 0; c < charts.size(); ++c) {
        const glm::dvec2 r = minAreaRectRotation(*charts[c].uv);
        for (glm::dvec2 p : *charts[c].uv)
            pts[c].emplace_back(r.x * p.x + r.y * p.y, -r.y * p.x + r.x * p.y);
        for (const Tri& t : *charts[c].triangles) {
            const glm::dvec2 a = pts[c][t[0]], b = pts[c][t[1]], d = pts[c][t[2]];
            totalArea += 0.5 * std::abs(cross(a, b, d));
        }
    }
    // Largest first, in two orders (a density fits when either packs): by
    // long side × short side² of the bounding rectangle, then by its area.
    // Measured better than by short side, long side or chart area alone, and
    // than either order by itself.
    std::vector<double> key1(charts.size()), key2(charts.size());
    double longestSide = 0;
    for (size_t c = 0; c < charts.size(); ++c) {
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (glm::dvec2 p : pts[c]) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const double w = hi.x - lo.x, h = hi.y - lo.y, shortSide = std::min(w, h);
        longestSide = std::max({longestSide, w, h});
        key1[c] = std::max(w, h) * shortSide * shortSide;
        key2[c] = w * h;
    }
    std::vector<std::vector<size_t>> orders;
    for (const std::vector<double>* key : {&key1, &key2}) {
        std::vector<size_t> order(charts.size());
        std::iota(order.begin(), order.end(), size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [&](size_t a, size_t b) { return (*key)[a] > (*key)[b]; });
        orders.push_back(std::move(order));
    }

    // Search on the density: lo fits, hi does not; two probes per round, run
    // side by side when there are two threads.
    struct Probe {
        double scale = 0;
        bool fits = false;
        double footprint = 0;
        std::vector<Placed> placed;
    };
    const bool parallel = threads > 1;
    double lo = 0, hi = INFINITY;
    Probe best;
    // From the area, but no denser than lets the longest chart side fit: a
    // chart of (almost) no area spanning its frame would start at an absurd
    // density and shrink 30 rounds to nowhere.
    const double s0 = std::min(std::sqrt(0.7 * double(W) * H / std::max(totalArea, 1e-300)),
                               double(W - 2 * dilate - 2) / std::max(longestSide, 1e-300));
    auto run = [&](Probe& p) {
        p.fits = packAt(pts, charts, orders, p.scale, W, H, dilate, p.placed, &p.footprint);
    };
    auto runBoth = [&](Probe(&probe)[2]) {
        if (parallel) {
            std::thread other(run, std::ref(probe[1]));
            run(probe[0]);
            other.join();
        } else {
            run(probe[0]);
            run(probe[1]);
        }
    };
    // Every chart takes at least its outline at a vanishing density (a texel
    // and its gutter). When those alone overflow the frame no density fits,
    // and 30 rounds of shrinking probes would each place thousands of charts
    // in vain (a soup of co-located one-triangle charts took minutes).
    {
        Outlines least(pts, charts, 1e-9 * s0, dilate, W, H);
        long long texels = 0;
        for (size_t c = 0; c < charts.size(); ++c) texels += least.get(c, 0).texels;
        if (texels > (long long)W * H)
            fail("atlas: cannot pack ", charts.size(), " charts into ", resolution,
                 "² texels (even a texel each, with its gutter, overflows; a mesh of many "
                 "separate or non-manifold pieces?)");
    }
    for (int round = 0; round < 30 && !(lo > 0 && hi / lo < 1.003); ++round) {
        Probe probe[2];
        if (lo == 0 && hi == INFINITY)
            probe[0].scale = s0, probe[1].scale = 0.88 * s0;
        else if (lo == 0)
            probe[0].scale = 0.88 * hi, probe[1].scale = 0.77 * hi;
        else if (hi == INFINITY)
            probe[0].scale = 1.12 * lo, probe[1].scale = 1.25 * lo;
        else
            probe[0].scale = lo + (hi - lo) / 3, probe[1].scale = lo + 2 * (hi - lo) / 3;
        runBoth(probe);
        for (Probe& p : probe)
            if (p.fits && p.scale > lo) {
                lo = p.scale;
                best = std::move(p);
            }
        for (Probe& p : probe)
            if (!p.fits && p.scale > lo) hi = std::min(hi, p.scale);
        if (hi <= lo) hi = lo * 1.01;  // a fit above a failure: packing is not monotone
        if (lo == 0 && hi < 1e-12 * s0) break;
    }
    if (lo == 0)
        fail("atlas: cannot pack ", charts.size(), " charts into ", resolution, "² texels");
    const std::vector<Placed>& bestPlaced = best.placed;
    const double bestFoot = best.footprint;

    result.texelsPerUnit = lo;
    result.footprint = bestFoot;
    result.uv.resize(charts.size());
    for (size_t c = 0; c < charts.size(); ++c) {
        const Placed& p = bestPlaced[c];
        const glm::dvec2 origin(p.x + offset, p.y + offset);
        for (glm::dvec2 q : pts[c]) {
            const glm::dvec2 frame = quarterTurns(q, p.orientation) * lo + p.shift;
            result.uv[c].push_back((frame + origin) / double(resolution));
        }
    }
    return result;
}

}  // namespace tsis::atlas

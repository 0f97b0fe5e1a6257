// Texture atlases: every triangle of a mesh gets a place in [0,1]² so that the
// integral over the surface becomes an integral over texture space (docs/design.md §1).
//
// Pipeline of buildAtlas (host/atlas/atlas.cpp):
//   shape     a noisy scan (median angle between neighbouring faces > 20°) is
//             segmented and flattened as a smoothed copy (Taubin λ|μ, same
//             connectivity; chart.h, smooth.cpp); the output keeps its positions;
//   segment   Variational Shape Approximation (CGAL), proxies = max(50, faces/200)
//             up to a cap (AtlasOptions); from 200K faces in parts of ~150K
//             faces, in parallel (segmentVSA in chart.h); labels smoothed (edge and vertex-ring
//             majority filters; under the cap also a strict majority over up to
//             3 vertex rings, which straightens borders), pieces under 1/10 of
//             a proxy's faces merged into a neighbour (charts.cpp);
//   charts    each connected piece made a topological disk (Euler characteristic
//             1, one border loop, no pinched vertex), else split in two at the
//             geodesic Voronoi boundary of two far faces (recursively);
//   param     ARAP (CGAL ARAP_parameterizer_3, λ = 1000) per chart, charts in
//             parallel; validated here: no flipped triangle, a border that does
//             not cross itself, area-weighted RMS of log(A3D/AUV) ≤
//             maxChartDistortion — a chart that fails is split in two;
//   elongate  a chart more than 3 times longer than wide (smallest bounding
//             rectangle) cut across its middle into connected pieces, UVs kept;
//   pack      charts scaled to one texel density and packed as dilated
//             conservative rasters at `resolution` (atlas/pack.h).
// Degenerate triangles (repeated index or no area) get their own vertices,
// parked on one UV point of a neighbouring chart (zero UV area).
// TSIS_ATLAS_DEBUG=1 prints the time after each stage on stderr.
// No CGAL type leaks out of this header.
#pragma once

#include <cstddef>
#include <string>

#include "mesh/mesh.h"
#include "util/json.h"

namespace tsis {

struct AtlasOptions {
    int resolution = 1024;  // texels per side the atlas is made for (texel centres at (i+½)/res)
    int gutterTexels = 2;   // empty texels at least between two charts at `resolution`
    // Charts from VSA: max(minProxies, min(triangles / trianglesPerProxy,
    // maxProxies × max(1, (resolution / 1024)²))). The cap keeps big meshes to
    // as many charts as the atlas holds with its gutters (the data meshes, up
    // to bunny00's 377 proxies, are below it): at 208K triangles, 1040
    // proxies made 1626 charts and a coverage of 0.45 at 1024².
    int trianglesPerProxy = 200;
    int minProxies = 50;
    int maxProxies = 400;
    // A chart whose area-weighted RMS of log(A3D/AUV) (after uniform scaling) is
    // above this is split in two and each half parameterised again.
    double maxChartDistortion = 0.06;
    int threads = 0;       // chart-level worker threads; 0 = hardware concurrency
    bool useCache = true;  // ensureAtlas: read and write the on-disk cache
};

struct AtlasStats {
    int charts = 0;             // connected pieces in UV space
    double coverage = 0;        // fraction of texel centres covered at the resolution
    double rWstd = 0;           // area-weighted stddev of r = (A3D/AUV)/(ΣA3D/ΣAUV)
    double rP01 = 0, rP99 = 0;  // area-weighted 1st / 99th percentiles of r
    double rMin = 0, rMax = 0;
    size_t flipped = 0;   // triangles oriented against their chart (or with zero UV area)
    size_t overlaps = 0;  // triangles overlapping another in UV space
    double seconds = 0;   // build (or cache load) wall time
    bool fromCache = false;
};

// Gives the mesh UVs for every vertex, splitting vertices along chart seams:
// the result may have more vertices than the input (positions, normals and
// the file's texcoords copied; the triangles' file materials too); triangles keep their order and
// count. Throws tsis::Error with a clear line when it cannot (empty mesh, non-finite positions).
Mesh buildAtlas(const Mesh& mesh, const AtlasOptions& opt, AtlasStats* stats = nullptr);

// The policy behind `--atlas`:
//   "auto"  the mesh's own UVs when tsis::checkUVs accepts them, else a built atlas;
//   "file"  the mesh's own UVs, a tsis::Error when it has none or they are invalid;
//   "build" always a built atlas.
// Built atlases go through the on-disk cache (see atlas/cache.h) unless
// opt.useCache is false.
Mesh ensureAtlas(const Mesh& mesh, const std::string& mode, const AtlasOptions& opt,
                 AtlasStats* stats = nullptr);

// `mesh` normalised to sizeMm (normalizeMesh) with its atlas (ensureAtlas).
// The atlas belongs to the shape, not the size: it is made at kAtlasSizeMm and
// the mesh scaled after, so a new --size-mm finds the cached atlas and gets
// the same UVs.
constexpr double kAtlasSizeMm = 10.0;
Mesh atlasAtSize(Mesh mesh, double sizeMm, const std::string& mode, const AtlasOptions& opt,
                 AtlasStats* stats = nullptr);

// r statistics, flips, overlaps (texel-centre raster of triangle ids at
// `resolution` plus exact segment tests between UV border edges) and coverage
// (texel centres covered at `resolution`). `seconds` is 0.
AtlasStats measureAtlas(const Mesh& meshWithUVs, int resolution);

// Keys: charts, coverage, r_wstd, r_p01, r_p99, r_min, r_max, flipped, overlaps,
// seconds, from_cache.
Json atlasStatsJson(const AtlasStats& stats);

// A (2·res)×res PNG: charts in colour on the left, a heat map of log2 r on the
// right (blue r < 1, white r = 1, red r > 1; saturated at r = 2^∓½ ≈ 0.71 and 1.41).
// Row 0 is v = 1. Writes `path` itself: `tsis atlas -o` gives it its output's
// temporary (util/output_set.h), which is renamed into place with the others.
void writeAtlasPng(const std::string& path, const Mesh& meshWithUVs, int resolution);

}  // namespace tsis

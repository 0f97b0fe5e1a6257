// ensureAtlas: which UVs a render uses (`--atlas auto|file|build`).
#include "atlas/atlas.h"
#include "atlas/cache.h"
#include "mesh/uv_check.h"
#include "util/error.h"
#include "util/timer.h"

namespace tsis {

Mesh ensureAtlas(const Mesh& mesh, const std::string& mode, const AtlasOptions& opt,
                 AtlasStats* stats) {
    if (mode != "auto" && mode != "file" && mode != "build")
        fail("--atlas ", mode, ": expected auto, file or build");
    if (mode != "build") {
        const Timer timer;
        std::string problem = "it has no texture coordinates";
        if (mesh.hasUVs()) {
            const UVCheck check = checkUVs(mesh);
            if (check.ok) {
                if (stats) {
                    *stats = measureAtlas(mesh, opt.resolution);
                    stats->seconds = timer.ms() / 1000.0;
                }
                return mesh;
            }
            problem = "its texture coordinates are not a valid atlas: " + check.problem;
        }
        if (mode == "file")
            fail(mesh.name, ": --atlas file: ", problem, " (use --atlas auto to build one)");
    }
    return atlas::buildAtlasCached(mesh, opt, stats);
}

Mesh atlasAtSize(Mesh mesh, double sizeMm, const std::string& mode, const AtlasOptions& opt,
                 AtlasStats* stats) {
    normalizeMesh(mesh, kAtlasSizeMm);
    Mesh out = ensureAtlas(mesh, mode, opt, stats);
    if (sizeMm != kAtlasSizeMm) normalizeMesh(out, sizeMm);  // centred: a uniform scale
    return out;
}

}  // namespace tsis

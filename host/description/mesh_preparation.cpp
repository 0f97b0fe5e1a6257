#include "description/mesh_preparation.h"

#include "mesh/mesh_io.h"
#include "mesh/repair.h"
#include "mesh/uv_check.h"
#include "render/object_materials.h"
#include "util/error.h"

namespace tsis {

double fileSizeMm(const Mesh& mesh, const FileView& view, std::optional<double> unitsMm,
                  const std::string& spec) {
    if (spec.rfind("builtin:", 0) == 0)
        fail("--size-mm file: ", spec, " has no size of its own; give --size-mm S");
    if (view.statedMmPerUnit && unitsMm)
        fail("--units: mesh '", mesh.name, "' states its unit (glTF: metres); not with --units");
    const std::optional<double> mmPerUnit = view.statedMmPerUnit ? view.statedMmPerUnit : unitsMm;
    if (!mmPerUnit)
        fail("--size-mm file: mesh '", mesh.name,
             "' does not state its unit; give --units m, cm or mm");
    const double diagonal = boundingDiagonal(mesh) * *mmPerUnit;
    if (!(diagonal >= kMinSizeMm && diagonal <= kMaxSizeMm))
        fail("--size-mm file: mesh '", mesh.name, "' is ", diagonal,
             " mm across (its bounding-box diagonal), outside [", kMinSizeMm, ", ", kMaxSizeMm,
             "]; give --size-mm S");
    return diagonal;
}

namespace {

// A loaded mesh turned by --mesh-up and --rotate (with `view`, its file's
// cameras and lights alike), after a note when it is not closed.
void turn(Mesh& mesh, FileView* view, const MeshOptions& o) {
    noteIfOpen(mesh);
    const glm::dmat3 rotation = meshRotation(o.rotateDegrees, o.zUp);
    const glm::dvec3 centre = rotateMesh(mesh, rotation);
    if (view) rotateView(*view, rotation, centre);
}

// A turned mesh at sizeMm with its atlas, then the normals it lacks, split at
// o.creaseDegrees: after the atlas, so that neither the atlas nor its cache
// key depends on the crease (the copies share their vertex's UV).
Mesh finish(Mesh turned, double sizeMm, const MeshOptions& o) {
    Mesh mesh = atlasAtSize(std::move(turned), sizeMm, o.atlasMode, o.atlas);
    ensureNormals(mesh, o.creaseDegrees);
    return mesh;
}

}  // namespace

Mesh atlasMesh(Mesh mesh, double sizeMm, const MeshOptions& o, AtlasStats* stats) {
    turn(mesh, nullptr, o);
    return atlasAtSize(std::move(mesh), sizeMm, o.atlasMode, o.atlas, stats);
}

Mesh prepareLoadedMesh(Mesh mesh, double sizeMm, const MeshOptions& o) {
    turn(mesh, nullptr, o);
    return finish(std::move(mesh), sizeMm, o);
}

Mesh prepareMesh(const std::string& spec, double sizeMm, const MeshOptions& o) {
    return prepareLoadedMesh(loadMesh(spec), sizeMm, o);
}

void loadMeshInto(Scene& scene, const std::string& spec, double size, const MeshOptions& o,
                  const FileViewUse& use, const MaterialOverrides& overrides, ProfileModel profile,
                  const std::function<void(Scene&, double)>& fileSize,
                  std::optional<double> unitsMm, FileMaterials* kept) {
    FileView view;
    Mesh mesh = loadMesh(spec, &view);
    loadMeshInto(scene, std::move(mesh), std::move(view), spec, size, o, use, overrides, profile,
                 fileSize, unitsMm, kept);
}

void loadMeshInto(Scene& scene, Mesh mesh, FileView view, const std::string& spec, double size,
                  const MeshOptions& o, const FileViewUse& use, const MaterialOverrides& overrides,
                  ProfileModel profile, const std::function<void(Scene&, double)>& fileSize,
                  std::optional<double> unitsMm, FileMaterials* kept) {
    turn(mesh, &view, o);
    if (fileSize) {
        size = fileSizeMm(mesh, view, unitsMm, spec);
        fileSize(scene, size);
    }
    scene.sizeMm = size;
    normalizeView(view, normalizationOf(mesh, size));
    // Before the atlas: a wrong --camera costs no waiting.
    useFileView(scene, view, use, size, mesh.name);
    keepUsedMaterials(mesh, view);
    if (kept) *kept = {view.materials, view.mmPerFileUnit, mesh.name};
    scene.objectMaterials = objectMaterials(view.materials, scene.material, overrides, profile,
                                            view.mmPerFileUnit, mesh.name);
    scene.mesh = finish(std::move(mesh), size, o);
}

}  // namespace tsis

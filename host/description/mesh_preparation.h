// A mesh made ready for a frame as `tsis render` makes it: turned, scaled to
// its size, given its atlas and the normals it lacks, with its file's camera,
// lights and materials brought along.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "atlas/atlas.h"
#include "description/scene_description.h"
#include "mesh/file_view.h"
#include "mesh/mesh.h"
#include "render/object_materials.h"
#include "scene/from_file.h"
#include "scene/scene.h"

namespace tsis {

// --size-mm file: the turned mesh's bounding-box diagonal in mm through the
// unit its format states (view, glTF: metres) or else --units; an error for
// a builtin mesh, a file without a stated unit and no --units, --units on a
// file that states one, or a size outside kMinSizeMm to kMaxSizeMm.
double fileSizeMm(const Mesh& mesh, const FileView& view, std::optional<double> unitsMm,
                  const std::string& spec);

// A loaded (and repaired) mesh with its atlas: a note when it is not closed,
// then turned, normalised to sizeMm and given UVs by o.atlasMode (the atlas
// cache key holds the turned positions).
Mesh atlasMesh(Mesh mesh, double sizeMm, const MeshOptions& o, AtlasStats* stats = nullptr);
// atlasMesh, then the normals the file lacks, split at o.creaseDegrees: after
// the atlas, so that neither the atlas nor its cache key depends on the
// crease (the copies share their vertex's UV).
Mesh prepareLoadedMesh(Mesh mesh, double sizeMm, const MeshOptions& o);
// Loads the mesh `spec` names (a file, builtin:NAME or a data mesh name) and
// prepares it (prepareLoadedMesh).
Mesh prepareMesh(const std::string& spec, double sizeMm, const MeshOptions& o);

// A mesh file's materials as read, before they were resolved: kept to
// resolve them again through another profile.
struct FileMaterials {
    std::vector<FileMaterial> materials;
    double mmPerFileUnit = 1;
    std::string meshName;
};

// The mesh `spec` names into `scene` (which holds the description's
// material, camera and lights): its file's camera and lights where `use`
// lets them, its materials, then the mesh prepared at `size`. With
// `fileSize` (--size-mm file) the size is the file's own (fileSizeMm of
// `unitsMm`), and `fileSize` places the scene's defaults by it first.
void loadMeshInto(Scene& scene, const std::string& spec, double size, const MeshOptions& o,
                  const FileViewUse& use, const MaterialOverrides& overrides, ProfileModel profile,
                  const std::function<void(Scene&, double)>& fileSize = {},
                  std::optional<double> unitsMm = std::nullopt, FileMaterials* kept = nullptr);
// The same for a mesh already loaded with its file's view (`spec` names it).
void loadMeshInto(Scene& scene, Mesh mesh, FileView view, const std::string& spec, double size,
                  const MeshOptions& o, const FileViewUse& use, const MaterialOverrides& overrides,
                  ProfileModel profile, const std::function<void(Scene&, double)>& fileSize,
                  std::optional<double> unitsMm, FileMaterials* kept);

}  // namespace tsis

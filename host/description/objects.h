// A scene of several objects, each its own mesh (a file, builtin:NAME or
// arrays) placed by its own transform and scattering in its own material:
// the library's Scene::fromObjects. The objects become one mesh whose file
// materials are theirs, so every method sees them as it sees a file of
// several objects (media, atlas, shadows between them).
#pragma once

#include <vector>

#include "description/scene_description.h"
#include "mesh/file_view.h"
#include "mesh/mesh.h"

namespace tsis {

// The objects as one mesh in mm, their file materials (and each given
// material as one more) in `view`, which states mm as its unit. Throws
// tsis::Error naming the object (index and mesh) whose mesh or material is wrong.
Mesh combinedMesh(const std::vector<ObjectDescription>& objects, FileView& view);

// A given material as a file material (tsis' own parameters, as a glTF's
// extras.tsis gives them), resolved with the file's.
FileMaterial fileMaterialOf(const MaterialDescription& m, const std::string& name);

}  // namespace tsis

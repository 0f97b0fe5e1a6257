// The surface's maps (issue 39, docs/design.md §2 "Materials"):
//  * a material's tangent-space normal map turns the shading normal of its
//    triangles, in the G-buffer (the lobe and the exit's Ft(cos θo)) and in
//    the flux atlas and the light views (the entry's cos θi and Ft);
//  * its roughness map (glTF's metallic-roughness texture, G channel; OBJ
//    map_Pr) times its roughness sets the GGX lobe's R per texel.
// Baked once per mesh, materials and atlas resolution into an object-space
// normal and a roughness per atlas texel, which every pass reads at the
// point's atlas coordinates; the dipole's geometry (the position and normal
// atlases the kernels gather over) stays the mesh's. A map's detail is the
// atlas': finer than a texel it averages out.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "mesh/media.h"
#include "scene/scene.h"

namespace tsis {

struct SurfaceAtlas {
    int resolution = 0;
    // The shading normal per texel, res², row 0 at v = 0 (GL order); (0, 0, 0)
    // where no normal-mapped triangle covers it (the geometry's normal
    // there). Empty: no material has a normal map.
    std::vector<glm::vec3> normal;
    // The lobe's roughness R per texel, likewise (the map's, else the
    // triangle's material's); 0 where no triangle covers it (the medium's
    // R there). Empty: no roughness map is used and each medium's triangles
    // share one R (or --roughness R replaces them all).
    std::vector<float> roughness;
    uint64_t key = 0;  // changes with whatever changed the normals or roughness
    bool empty() const { return normal.empty() && roughness.empty(); }
};

// Per-vertex tangents from the texture coordinates (Mesh::texcoords, image
// convention: v down): xyz the unit tangent along +u, orthogonal to the
// vertex normal, w the handedness (±1) of the bitangent cross(n, t) · w,
// which points up the image (+y of a glTF normal map). Each triangle adds
// its UV-gradient frame, weighted by its area, to its corners (as
// MikkTSpace does for a smooth mesh whose UVs are continuous, without its
// splitting of corners that disagree). Zero where no triangle gives one.
std::vector<glm::vec4> vertexTangents(const Mesh& mesh);

// The shading normals and roughness of `scene` (its solids `media`) at
// `resolution`: the normals empty when no triangle's material has a normal
// map, the roughness when none has a roughness map and no medium holds
// triangles of several roughnesses, both when the mesh has no texture
// coordinates; the file's roughness only with `fileRoughness` (--roughness file).
SurfaceAtlas bakeSurfaceAtlas(const Scene& scene, const Media& media, int resolution,
                              bool fileRoughness);

}  // namespace tsis

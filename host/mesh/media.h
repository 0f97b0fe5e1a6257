// Media: the separate solids of a mesh. Light that enters one never leaves
// through another (docs/design.md §2 "Media"), so every method sums the
// profile only over entry points of the exit point's own medium.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace tsis {

struct Media {
    uint32_t count = 0;
    std::vector<uint32_t> ofVertex;  // the medium of each vertex (and so of its triangles)
    // The file material of each medium: its first triangle's (Mesh::materialOf).
    // A piece whose triangles carry several takes η, the exit scale and
    // volumetric's medium from this one; each of its points scatters with its
    // own triangle's profile (render/scene_media.h, render/albedo_atlas.h).
    std::vector<uint32_t> materialOf;
};

// One medium per closed connected piece of the surface (triangles sharing a
// welded vertex, no edge of one triangle); the open pieces together are one
// more (a slab given as two faces, loose sheets: their light mixes, as the
// dipole on one surface always did). Numbered in order of their first
// triangle; vertices no triangle uses join medium 0.
Media findMedia(const Mesh& mesh);

// The tag a surface point carries to the kernels in a float channel (position
// w, light-view flux a): 1 + medium, so "> 0" still reads as covered.
inline float mediumTag(uint32_t medium) {
    return 1.0f + static_cast<float>(medium);
}

}  // namespace tsis

// The keys that decide what a frame may reuse from the last one: equal keys,
// equal contents. Each key covers everything its contents depend on.
#pragma once

#include <cstdint>

#include "mesh/mesh.h"
#include "render/render_options.h"
#include "scene/scene.h"
#include "util/hash.h"

namespace tsis {

// The mesh's geometry and UVs: decides when to re-upload it.
uint64_t meshHash(const Mesh& mesh);

// Every material: media (σs′, σa, η), albedos and textures.
void hashMaterials(Hasher& h, const Scene& scene);

// The lights field by field, the environment (map, intensity, rotation) and
// every material's η (Fresnel at entry): what the irradiance on the surface
// depends on besides the mesh (the albedo factor has its own key,
// render/albedo_atlas.h).
void hashIrradiance(Hasher& h, const Scene& scene);

// Everything the light maps and the flux atlas depend on: the mesh, the
// lights, η and the parameters whose effect is Lighting (render/render_params.h).
uint64_t lightingKey(const Scene& scene, const RenderOptions& options, uint64_t meshHash);

// One light's view (its shadow map, and flux and position maps when `maps`):
// the light field by field, the mesh, the map resolution and, for the maps,
// `shading` (what the flux map reads of the materials: η per medium, the
// albedo atlas' key), without them `lodTriangles` (--light-lod: the copy a
// big mesh's depth is drawn from). A frame redraws only the views whose key
// changed.
uint64_t lightViewKey(const Light& light, uint64_t meshHash, int resolution, bool maps,
                      uint64_t shading, int lodTriangles);

// Everything that changes the radiosity a frame computes, except the sample
// set: frames with equal keys may be averaged. The parameters come from their
// table (effect Radiosity, read by the method), so a new one is covered.
uint64_t accumulationKey(const Scene& scene, const RenderOptions& options, uint64_t lightingKey);

}  // namespace tsis

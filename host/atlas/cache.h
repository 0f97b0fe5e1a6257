// On-disk cache of built atlases, so that the second render of a mesh starts
// at once.
//
// Where: $TSIS_CACHE_DIR/atlas, else $XDG_CACHE_HOME/tsis/atlas, else
// ~/.cache/tsis/atlas; no cache when none of these is set.
// Key: 128-bit hash of the builder version, the options that change the result
// and the mesh's positions and triangles (not its name or normals: normals are
// copied from the mesh at load time).
// File <key>.atlas: header, per output vertex its input vertex and UV, the
// triangles, the build statistics, and a 64-bit checksum of all of that. An
// entry that is short, fails the checksum, does not fit the mesh or is not a
// regular file (a folder, say) is ignored and rebuilt; any failure to write is
// ignored. Without TSIS_CACHE_DIR the folder must be private (util/cache_dir.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "atlas/atlas.h"

namespace tsis::atlas {

// Bump when the builder's output changes for the same input.
constexpr int kAtlasVersion = 8;

// Under cacheDirectory() (util/cache_dir.h): "atlas".
std::optional<std::filesystem::path> atlasCacheDirectory();
std::string cacheKey(const Mesh& mesh, const AtlasOptions& opt);

std::optional<Mesh> loadCachedAtlas(const std::filesystem::path& file, const Mesh& mesh,
                                    AtlasStats* stats);
// Writes atomically; returns false (and leaves nothing behind) on failure.
bool storeCachedAtlas(const std::filesystem::path& file, const Mesh& atlas,
                      const std::vector<uint32_t>& sourceVertex, size_t inputVertices,
                      const AtlasStats& stats);

// Fills the atlas' positions (and normals and the file's texcoords, when the
// mesh has them) from the input vertex of each of its vertices, and copies the
// triangles' file materials (the atlas keeps the triangles' order).
void copySourceAttributes(const Mesh& mesh, const std::vector<uint32_t>& sourceVertex, Mesh& atlas);

// buildAtlas that also returns the input vertex of every output vertex.
Mesh buildAtlasWithSources(const Mesh& mesh, const AtlasOptions& opt, AtlasStats* stats,
                           std::vector<uint32_t>* sourceVertex);

// buildAtlas through the cache (when opt.useCache and a cache directory exist).
Mesh buildAtlasCached(const Mesh& mesh, const AtlasOptions& opt, AtlasStats* stats = nullptr);

}  // namespace tsis::atlas

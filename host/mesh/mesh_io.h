// Loading meshes from OFF, OBJ, PLY, STL and glTF 2.0 files and the built-in procedural ones.
// Every failure is a tsis::Error naming the file and the problem. A loaded mesh
// has been checked and repaired (repair.h; one stderr note per repair); its
// normals are the file's, if any: callers run normalizeMesh and ensureNormals.
#pragma once

#include <string>

#include "mesh/file_view.h"
#include "mesh/mesh.h"

namespace tsis {

// `spec` is a path (format from its extension, .off/.obj/.ply/.stl/.gltf/.glb), "builtin:NAME",
// or a bare name resolved under the unpacked data meshes (data/meshes/NAME.off).
// `view`, when given, receives the file's cameras, lights (glTF) and materials
// (glTF, OBJ's .mtl files; Mesh::materialIds index them); without it the
// loader notes them as ignored and the mesh has no materialIds.
Mesh loadMesh(const std::string& spec, FileView* view = nullptr);

Mesh loadOFF(const std::string& path);
Mesh loadOBJ(const std::string& path, FileView* view = nullptr);
Mesh loadPLY(const std::string& path);
Mesh loadSTL(const std::string& path);
Mesh loadGLTF(const std::string& path, FileView* view = nullptr);  // .gltf or .glb

// Parsers from memory (used by the loaders and the fuzz targets).
Mesh parseOFF(const std::string& text, const std::string& name);
// OBJ: mtllib files are read from `folder` (none when it is empty).
Mesh parseOBJ(const std::string& text, const std::string& name, const std::string& folder = "",
              FileView* view = nullptr);
Mesh parsePLY(const std::string& bytes, const std::string& name);
Mesh parseSTL(const std::string& bytes, const std::string& name);
// glTF 2.0, text or binary (.glb) by its first bytes; external buffers are read
// from `folder`, or refused when it is empty.
Mesh parseGLTF(const std::string& bytes, const std::string& name, const std::string& folder = "",
               FileView* view = nullptr);

}  // namespace tsis

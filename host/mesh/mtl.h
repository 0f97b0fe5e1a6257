// Wavefront .mtl material libraries (an OBJ's mtllib): newmtl, Kd (albedo),
// map_Kd (albedo texture), Ni (η) and the surface's roughness are read: Pr
// (the PBR extension's R), else Ns by Blender's mapping R = 1 − √Ns / 30;
// every other statement is one note per kind. The materials go to FileView::materials
// (file_view.h).
#pragma once

#include <string>
#include <vector>

#include "mesh/file_view.h"

namespace tsis {

// The materials of one .mtl text, in the order of their newmtl. `path` is the
// library's path (map_Kd files are resolved against its folder, and must
// exist: a missing one is a note and the material keeps its Kd only);
// `meshName` names the OBJ in notes and errors. A bad number, a non-finite or
// negative Kd, Pr or Ns or a non-positive Ni is a tsis::Error naming the file, the line
// and the material.
std::vector<FileMaterial> parseMTL(const std::string& text, const std::string& path,
                                   const std::string& meshName);

}  // namespace tsis

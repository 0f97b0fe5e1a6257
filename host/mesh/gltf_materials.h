// A glTF's materials as FileMaterials (file_view.h), for gltf.cpp: what is
// read (baseColorFactor, baseColorTexture, KHR_materials_ior,
// KHR_materials_volume, extras.tsis) and one note per kind of what is not.
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "mesh/file_view.h"

namespace tsis::gltf {

// The encoded bytes of each image tinygltf handed to its image loader (from
// a bufferView, a data URI or a file), by image index; empty when none.
using ImageBytes = std::vector<std::string>;

// One FileMaterial per glTF material, in file order. `folder` resolves image
// URIs ("" when parsing from memory: external images are then dropped with a
// note). A material whose texture is dropped keeps its factor. Bad values
// (non-finite or negative factors, an extras.tsis key of the wrong type, a
// texture or image that does not exist) are a tsis::Error naming the file,
// the material and the key.
std::vector<FileMaterial> readMaterials(const tinygltf::Model& model, const std::string& name,
                                        const std::string& folder, const ImageBytes& images);

}  // namespace tsis::gltf

// The materials of a mesh file's objects (issue 20 item 3, docs/design.md §2
// "Materials"): each FileMaterial the loader kept becomes an ObjectMaterial.
//  * tsis' own parameters first (glTF extras): a preset, or σs′ + σa;
//  * else albedo (baseColorFactor / Kd, times the mean of its texture when it
//    has one) + mean free path, inverted through the profile's total
//    reflectance (render/albedo_inversion.h). The mean free path: --mfp, the
//    extras' mfp, or from KHR_materials_volume (σa = −ln(colour)/distance and
//    the albedo's σs′/σt′ give σt′), else the scene's material's (a note);
//  * η: --eta, the file's (KHR_materials_ior, Ni, extras), else the scene's.
// A texture that cannot be read is a note; the albedo factor alone stays.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mesh/file_view.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace tsis {

// What the command line says over a file's materials.
struct MaterialOverrides {
    bool replaceAll = false;        // --material, --albedo, --sigma-s/-a: the file's are not used
    std::optional<glm::dvec3> mfp;  // --mfp alone: every material's mean free path (mm)
    std::optional<double> eta;      // --eta: every material's η
};

// One ObjectMaterial per file material (none with replaceAll). `fallback`:
// the scene's material; `mmPerFileUnit` scales the file's distances; `file`
// names the notes and errors.
std::vector<ObjectMaterial> objectMaterials(const std::vector<FileMaterial>& materials,
                                            const Material& fallback,
                                            const MaterialOverrides& overrides, ProfileModel model,
                                            double mmPerFileUnit, const std::string& file);

}  // namespace tsis

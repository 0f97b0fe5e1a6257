// A scene's camera and lights from those its mesh file places
// (mesh/file_view.h, already normalised with the mesh), where the command
// line does not give its own. docs/guide/scenes-and-materials.md "Cameras and lights from the
// file".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mesh/file_view.h"
#include "scene/scene.h"

namespace tsis {

// What the command line left to the file, per kind.
struct FileViewUse {
    bool camera = true;              // false: --eye, --target or --up given
    std::optional<int> cameraIndex;  // --camera N (default: the first camera)
    bool fov = true;                 // the camera's yfov (false: --fov given)
    bool lights = true;              // false: the scene's own lights (why: lightsGivenBy)
    std::string lightsGivenBy = "--light given";  // the note's reason when !lights
    // --light-units file: the lights at the file's candela and lux, no re-levelling.
    bool fileLightUnits = false;
};

// The file's camera: its eye, up and yfov; the target on its view ray at the
// point nearest the object's centre (the origin), at least sizeMm/2 ahead.
Camera cameraFromFile(const FileCamera& camera, double sizeMm);

// The file's lights in tsis' units (docs/design.md §2). Photometric to
// radiometric at 683 lm/W; lux (lm/m²) to W/mm²; a point light's candela
// times (mmPerFileUnit/1000)², so that the irradiance it gives the rescaled
// object is the one it gives the file's object at the file's metres. Then one
// factor for all, so that the strongest gives an irradiance of 1 W/mm² at the
// object's centre (a point light: at its distance, at least sizeMm/2), the
// level of the default light: the file's balance and colours are kept and the
// radiosity AOVs stay in the default scene's range. Spot lights become point
// lights.
// With `relevel` false (--light-units file) that factor is left out: the
// lights are the file's own power in tsis' units.
std::vector<Light> lightsFromFile(const std::vector<FileLight>& lights, double mmPerFileUnit,
                                  double sizeMm, bool relevel = true);

// Replaces the scene's camera and lights (already the command line's or the
// defaults) by the file's where `use` lets it, with one note on stderr per
// kind of thing left out; notes and errors name the mesh file `meshName`.
void useFileView(Scene& scene, const FileView& view, const FileViewUse& use, double sizeMm,
                 const std::string& meshName);

}  // namespace tsis

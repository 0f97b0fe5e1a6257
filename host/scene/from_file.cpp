#include "scene/from_file.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <string>

#include "mesh/parse_util.h"
#include "util/error.h"

namespace tsis {

namespace {

using meshparse::note;
using meshparse::plural;

constexpr double kLumensPerWatt = 683.0;  // the photometric constant (555 nm)
constexpr double kMm2PerM2 = 1e6;

double maxComponent(const glm::dvec3& v) {
    return std::max({v.x, v.y, v.z});
}

std::string cameraName(const FileView& view, size_t i) {
    const std::string& n = view.cameras[i].name;
    return concat(i, n.empty() ? "" : " '" + n + "'");
}

// "0 'Front', 1 'Side', 2": the cameras --camera can pick.
std::string cameraList(const FileView& view) {
    std::string s;
    for (size_t i = 0; i < view.cameras.size(); ++i) s += (i ? ", " : "") + cameraName(view, i);
    return s;
}

}  // namespace

Camera cameraFromFile(const FileCamera& c, double sizeMm) {
    Camera cam;
    // Any point on the ray gives the same image; the one nearest the object's
    // centre is what the viewer orbits and --print-view prints.
    const double d = std::max(glm::dot(-c.eye, c.forward), 0.5 * sizeMm);
    cam.eye = glm::vec3(c.eye);
    cam.target = glm::vec3(c.eye + d * c.forward);
    cam.up = glm::vec3(c.up);
    cam.fovYDegrees = static_cast<float>(glm::degrees(c.yfovRadians));
    return cam;
}

std::vector<Light> lightsFromFile(const std::vector<FileLight>& lights, double mmPerFileUnit,
                                  double sizeMm, bool relevel) {
    std::vector<glm::dvec3> rgb;
    double strongest = 0;  // the largest irradiance at the centre, W/mm²
    for (const FileLight& l : lights) {
        const glm::dvec3 radiometric = l.color * l.intensity / kLumensPerWatt;  // W/sr or W/m²
        if (l.type == FileLight::Type::Directional) {
            rgb.push_back(radiometric / kMm2PerM2);
            strongest = std::max(strongest, maxComponent(rgb.back()));
        } else {
            const double k = mmPerFileUnit / 1000.0;  // this scene's mm per real mm
            rgb.push_back(radiometric * (k * k));
            const double d2 = std::max(glm::dot(l.position, l.position), 0.25 * sizeMm * sizeMm);
            strongest = std::max(strongest, maxComponent(rgb.back()) / d2);
        }
    }
    const double exposure =
        relevel && strongest > 0 && std::isfinite(1.0 / strongest) ? 1.0 / strongest : 1.0;
    std::vector<Light> out;
    for (size_t i = 0; i < lights.size(); ++i) {
        Light t;
        const bool directional = lights[i].type == FileLight::Type::Directional;
        t.type = directional ? Light::Type::Directional : Light::Type::Point;
        t.vec = glm::vec3(directional ? lights[i].direction : lights[i].position);
        t.rgb = glm::vec3(rgb[i] * exposure);
        out.push_back(t);
    }
    return out;
}

void useFileView(Scene& scene, const FileView& view, const FileViewUse& use, double sizeMm,
                 const std::string& name) {
    const size_t cameras = view.cameras.size();
    if (use.cameraIndex) {
        const int n = *use.cameraIndex;
        if (cameras == 0) fail("--camera ", n, ": mesh '", name, "' has no perspective camera");
        if (n < 0 || static_cast<size_t>(n) >= cameras)
            fail("--camera ", n, ": mesh '", name, "' has ", cameras, " ",
                 plural(cameras, "camera", "cameras"), " (", cameraList(view), ")");
    }
    if (cameras && use.camera) {
        const size_t i = static_cast<size_t>(use.cameraIndex.value_or(0));
        const float fov = scene.camera.fovYDegrees;
        scene.camera = cameraFromFile(view.cameras[i], sizeMm);
        if (!use.fov) {
            scene.camera.fovYDegrees = fov;
        } else if (!(scene.camera.fovYDegrees >= 1.0f && scene.camera.fovYDegrees <= 170.0f)) {
            fail("mesh '", name, "': camera ", cameraName(view, i), ": yfov ",
                 view.cameras[i].yfovRadians, " rad is outside 1°–170° (--fov gives another)");
        }
        if (cameras > 1)
            note(name, concat(cameras - 1, " other ", plural(cameras - 1, "camera", "cameras"),
                              " ignored (camera ", cameraName(view, i),
                              " used; --camera N picks another)"));
    } else if (cameras) {
        note(name, concat(cameras, " ", plural(cameras, "camera", "cameras"),
                          " ignored (--eye, --target or --up given)"));
    }

    const size_t lights = view.lights.size();
    if (use.fileLightUnits && lights == 0 && !scene.env)
        fail("--light-units file: mesh '", name,
             "' has no lights (KHR_lights_punctual) and no --env is given");
    if (lights && !use.lights) {
        note(name, concat(lights, " ", plural(lights, "light", "lights"), " ignored (",
                          use.lightsGivenBy, ")"));
    } else if (lights) {
        const size_t used = std::min(lights, static_cast<size_t>(kMaxLights));
        const std::vector<FileLight> file(view.lights.begin(), view.lights.begin() + used);
        scene.lights = lightsFromFile(file, view.mmPerFileUnit, sizeMm, !use.fileLightUnits);
        for (const Light& l : scene.lights)
            if (!std::isfinite(l.rgb.x + l.rgb.y + l.rgb.z + l.vec.x + l.vec.y + l.vec.z))
                fail("mesh '", name, "': a light's position or intensity is out of range");
        if (lights > used)
            note(name,
                 concat(lights - used, " ", plural(lights - used, "light", "lights"),
                        " beyond the first ", kMaxLights, " ignored (at most ", kMaxLights, ")"));
        size_t spots = 0, ranges = 0;
        for (const FileLight& l : file) {
            spots += l.type == FileLight::Type::Spot;
            ranges += l.range > 0;
        }
        if (spots)
            note(name, concat(spots, " spot ", plural(spots, "light", "lights"), " used as point ",
                              plural(spots, "light", "lights"), " (cones ignored)"));
        if (ranges)
            note(name, concat("range of ", ranges, " ", plural(ranges, "light", "lights"),
                              " ignored (tsis' lights reach everything)"));
    }
}

}  // namespace tsis

// `import tsis`: the public API (include/tsis/) for Python through pybind11.
// Options are keyword arguments with the CLI's names (size_mm → --size-mm),
// images numpy arrays (row 0 = top), stats a dict, errors tsis.Error with the
// text `tsis` prints.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>

#include "tsis/tsis.h"

namespace py = pybind11;
using namespace tsis::api;

namespace {

std::string optionName(std::string name) {
    std::replace(name.begin(), name.end(), '_', '-');
    return name;
}

// One keyword argument: str as typed, bool for a flag, a number, or a
// sequence (x,y,z for a vector; each item for the repeatable light).
void setOption(Options& o, const std::string& name, const py::handle& v) {
    if (py::isinstance<py::bool_>(v)) {
        o.set(name, v.cast<bool>() ? "true" : "false");
    } else if (py::isinstance<py::str>(v)) {
        o.set(name, v.cast<std::string>());
    } else if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) {
        o.set(name, v.cast<double>());
    } else if (name == "light") {
        o.unset(name);
        for (const py::handle item : v) o.set(name, item.cast<std::string>());
    } else {
        std::string joined;
        for (const py::handle item : v)
            joined += (joined.empty() ? "" : ",") + py::str(item).cast<std::string>();
        o.set(name, joined);
    }
}

Options optionsOf(const py::kwargs& kwargs) {
    Options o;
    for (const auto& [k, v] : kwargs) setOption(o, optionName(k.cast<std::string>()), v);
    return o;
}

py::array_t<float> toNumpy(const Image& i) {
    py::array_t<float> a({i.height, i.width, i.channels});
    std::copy(i.pixels.begin(), i.pixels.end(), a.mutable_data());
    return a;
}

Image fromNumpy(const py::array_t<float, py::array::c_style | py::array::forcecast>& a) {
    if (a.ndim() != 2 && a.ndim() != 3)
        throw tsis::Error("image: expected an H×W or H×W×C array, got " + std::to_string(a.ndim()) +
                          " dimensions");
    Image i{static_cast<int>(a.shape(1)),
            static_cast<int>(a.shape(0)),
            a.ndim() == 3 ? static_cast<int>(a.shape(2)) : 1,
            {}};
    i.pixels.assign(a.data(), a.data() + a.size());
    return i;
}

template <typename T>
std::vector<T> rowsOf3(const py::array_t<T, py::array::c_style | py::array::forcecast>& a,
                       const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw tsis::Error(std::string(what) + ": expected an N×3 array");
    return std::vector<T>(a.data(), a.data() + a.size());
}

py::object frameToPython(const Frame& f) {
    py::array_t<uint8_t> rgb({f.height, f.width, 3});
    std::copy(f.rgb8.begin(), f.rgb8.end(), rgb.mutable_data());
    const py::object stats = py::module_::import("json").attr("loads")(f.statsJson);
    return py::module_::import("types").attr("SimpleNamespace")(
        py::arg("image") = rgb, py::arg("radiance") = toNumpy(f.radiance),
        py::arg("radiosity") = toNumpy(f.radiosity), py::arg("position") = toNumpy(f.position),
        py::arg("normal") = toNumpy(f.normal), py::arg("coverage") = toNumpy(f.coverage),
        py::arg("flux_atlas") = toNumpy(f.fluxAtlas), py::arg("lavg") = f.lavg,
        py::arg("stats") = stats);
}

// The renderer tsis.render() uses: made on first use, kept for the next
// frames, and never destroyed (its GL and CL would outlive the interpreter's
// teardown otherwise).
Renderer& sharedRenderer() {
    static Renderer* r = new Renderer();
    return *r;
}

py::object renderFrame(Renderer& r, const Scene& s, const py::kwargs& kw) {
    const Options o = optionsOf(kw);
    Frame f;
    {
        py::gil_scoped_release release;
        f = r.render(s, o);
    }
    return frameToPython(f);
}

}  // namespace

PYBIND11_MODULE(tsis, m) {
    m.doc() =
        "tsis: translucent materials rendered with the dipole BSSRDF (README, docs/design.md)";
    py::register_exception<tsis::Error>(m, "Error", PyExc_RuntimeError);

    py::class_<Material>(m, "Material")
        .def(py::init([](const std::string& name, Vec3 sigmaS, Vec3 sigmaA, float eta) {
                 return Material{name, sigmaS, sigmaA, eta};
             }),
             py::arg("name") = "custom", py::arg("sigma_s"), py::arg("sigma_a"),
             py::arg("eta") = 1.3f)
        .def_readwrite("name", &Material::name)
        .def_readwrite("sigma_s", &Material::sigmaSPrime, "reduced scattering σs' (1/mm, RGB)")
        .def_readwrite("sigma_a", &Material::sigmaA, "absorption σa (1/mm, RGB)")
        .def_readwrite("eta", &Material::eta)
        .def("__repr__", [](const Material& x) {
            return py::str("Material({!r}, sigma_s={}, sigma_a={}, eta={})")
                .format(x.name, x.sigmaSPrime, x.sigmaA, x.eta);
        });
    m.def("preset_material", &presetMaterial, py::arg("name"));
    m.def("preset_materials", &presetMaterialNames);

    py::class_<Light>(m, "Light")
        .def(py::init([](std::optional<Vec3> position, std::optional<Vec3> direction, Vec3 rgb) {
                 if (position.has_value() == direction.has_value())
                     throw tsis::Error("Light: give position (a point light) or direction");
                 return Light{direction.has_value(), position.value_or(direction.value_or(Vec3{})),
                              rgb};
             }),
             py::kw_only(), py::arg("position") = py::none(), py::arg("direction") = py::none(),
             py::arg("rgb") = Vec3{1, 1, 1})
        .def_readwrite("directional", &Light::directional)
        .def_readwrite("vec", &Light::vec, "point: position (mm); directional: direction")
        .def_readwrite("rgb", &Light::rgb, "point: intensity (W/sr); directional: W/mm²");

    py::class_<Camera>(m, "Camera")
        .def(py::init([](Vec3 eye, Vec3 target, Vec3 up, float fov) {
                 return Camera{eye, target, up, fov};
             }),
             py::arg("eye"), py::arg("target") = Vec3{0, 0, 0}, py::arg("up") = Vec3{0, 1, 0},
             py::arg("fov") = 35.0f)
        .def_readwrite("eye", &Camera::eye)
        .def_readwrite("target", &Camera::target)
        .def_readwrite("up", &Camera::up)
        .def_readwrite("fov", &Camera::fovYDegrees);

    py::class_<Scene>(m, "Scene")
        .def(py::init([](const py::kwargs& kw) { return Scene(optionsOf(kw)); }),
             "Scene(mesh='builtin:default', size_mm=10, material='skin1', …): the scene options "
             "of `tsis render`")
        .def_static(
            "from_arrays",
            [](const py::array_t<float, py::array::c_style | py::array::forcecast>& vertices,
               const py::array_t<uint32_t, py::array::c_style | py::array::forcecast>& triangles,
               const py::kwargs& kw) {
                return Scene::fromArrays(rowsOf3(vertices, "vertices"),
                                         rowsOf3(triangles, "triangles"), optionsOf(kw));
            },
            py::arg("vertices"), py::arg("triangles"),
            "vertices N×3 and triangles M×3 (counter-clockwise from outside); options as Scene()")
        .def_property("material", &Scene::material, &Scene::setMaterial)
        .def_property("lights", &Scene::lights, &Scene::setLights)
        .def_property("camera", &Scene::camera, &Scene::setCamera)
        .def_property_readonly("mesh_name", &Scene::meshName)
        .def_property_readonly("vertex_count", &Scene::vertexCount)
        .def_property_readonly("triangle_count", &Scene::triangleCount);

    py::class_<Renderer>(m, "Renderer")
        .def(py::init<const std::string&, const std::string&>(), py::arg("cl_device") = "",
             py::arg("gl") = "")
        .def("render", &renderFrame, py::arg("scene"),
             "a frame: image (H×W×3 uint8), radiance, radiosity, position, normal, coverage, "
             "flux_atlas (float32, row 0 = top), lavg, stats (dict); options as `tsis render`");
    m.def(
        "render",
        [](const Scene& s, const py::kwargs& kw) { return renderFrame(sharedRenderer(), s, kw); },
        py::arg("scene"), "Renderer.render with one renderer kept for every call");
    m.def(
        "compare",
        [](const py::array_t<float, py::array::c_style | py::array::forcecast>& a,
           const py::array_t<float, py::array::c_style | py::array::forcecast>& b,
           const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>&
               mask) {
            const Image mi = mask ? fromNumpy(*mask) : Image{};
            const Metrics x = compare(fromNumpy(a), fromNumpy(b), mask ? &mi : nullptr);
            py::dict d;
            d["rmse"] = x.rmse;
            d["rel_rmse"] = x.relRmse;
            d["mean_rel_err"] = x.meanRelErr;
            d["max_abs"] = x.maxAbs;
            d["psnr"] = x.psnr;
            d["pixels"] = x.pixels;
            d["nonfinite_a"] = x.nonfiniteImage;
            d["nonfinite_b"] = x.nonfiniteReference;
            return d;
        },
        py::arg("image"), py::arg("reference"), py::arg("mask") = py::none(),
        "the metrics of `tsis compare --json` (psnr inf when equal)");
    m.def("option_help", &Options::help);
}

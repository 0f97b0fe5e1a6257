// `import tsis`: the public API (include/tsis/) for Python through pybind11.
// Options are keyword arguments with the CLI's names (size_mm → --size-mm),
// images numpy arrays (row 0 = top), stats a dict, errors tsis.Error with the
// text `tsis` prints.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tsis/tsis.h"

namespace py = pybind11;
using namespace tsis::api;

namespace {

std::string optionName(std::string name) {
    std::replace(name.begin(), name.end(), '_', '-');
    return name;
}

bool isNumpy(const py::handle& v, const char* type) {
    return py::isinstance(v, py::module_::import("numpy").attr(type));
}

std::string typeName(const py::handle& v) {
    return py::str(py::type::of(v).attr("__name__")).cast<std::string>();
}

// One keyword argument: str as typed, bool for a flag, a number (numpy's
// scalars too; an integer written exactly), or a sequence (x,y,z for a
// vector; each item for the repeatable light).
void setOption(Options& o, const std::string& name, const py::handle& v) {
    if (py::isinstance<py::bool_>(v) || isNumpy(v, "bool_")) {
        o.set(name, v.cast<bool>() ? "true" : "false");
    } else if (py::isinstance<py::str>(v)) {
        o.set(name, v.cast<std::string>());
    } else if (PyIndex_Check(v.ptr())) {  // int, numpy.int64, …
        o.set(name, py::str(py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr())))
                        .cast<std::string>());
    } else if (py::isinstance<py::float_>(v) || isNumpy(v, "floating")) {
        o.set(name, PyFloat_AsDouble(v.ptr()));
    } else if (!py::isinstance<py::iterable>(v) || isNumpy(v, "generic")) {
        throw tsis::Error("option --" + name + ": expected a str, number, bool or sequence, not " +
                          typeName(v));
    } else if (name == "light") {
        o.unset(name);
        for (const py::handle item : v) o.set(name, py::str(item).cast<std::string>());
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

// `value` as a numpy array (a list too), with its dtype's kind: 'f', 'i',
// 'u', 'b', … Throws tsis::Error naming `what` when numpy cannot make one.
py::array arrayOf(const py::handle& value, const std::string& what) {
    try {
        return py::module_::import("numpy").attr("asarray")(value);
    } catch (const py::error_already_set& e) {
        throw tsis::Error(what + ": not an array (" + typeName(value) + ")");
    }
}

char kindOf(const py::array& a) {
    return a.dtype().kind();
}

std::string shapeOf(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

// An image for compare: H×W or H×W×C of real numbers, within the stated
// size, checked before anything is copied.
Image imageOf(const py::handle& value, const char* what) {
    const py::array a = arrayOf(value, what);
    if (a.ndim() != 2 && a.ndim() != 3)
        throw tsis::Error(std::string(what) + ": expected an H×W or H×W×C array, got shape " +
                          shapeOf(a));
    if (kindOf(a) != 'f' && kindOf(a) != 'i' && kindOf(a) != 'u')
        throw tsis::Error(std::string(what) + ": expected real numbers, got dtype " +
                          py::str(a.dtype()).cast<std::string>());
    const long long h = a.shape(0), w = a.shape(1), c = a.ndim() == 3 ? a.shape(2) : 1;
    if (w < 1 || h < 1 || c < 1 || c > kMaxCompareChannels || w > kMaxCompareSide ||
        h > kMaxCompareSide || w * h > kMaxComparePixels)
        throw tsis::Error(std::string(what) + ": shape " + shapeOf(a) + " is past compare's " +
                          "limits (at most " + std::to_string(kMaxCompareSide) + " on a side, " +
                          std::to_string(kMaxComparePixels) + " pixels, 1 to " +
                          std::to_string(kMaxCompareChannels) + " channels)");
    const auto f = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
    Image i{static_cast<int>(w), static_cast<int>(h), static_cast<int>(c), {}};
    i.pixels.assign(f.data(), f.data() + f.size());
    return i;
}

// An N×3 array's rows, checked before the copy: vertices finite and within
// float's range, triangle indices integers in [0, 2³²) (the mesh then checks
// them against its vertices).
std::vector<float> vertexRows(const py::handle& value) {
    const py::array a = arrayOf(value, "vertices");
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw tsis::Error("vertices: expected an N×3 array, got shape " + shapeOf(a));
    if (kindOf(a) != 'f' && kindOf(a) != 'i' && kindOf(a) != 'u')
        throw tsis::Error("vertices: expected real numbers, got dtype " +
                          py::str(a.dtype()).cast<std::string>());
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    std::vector<float> out(static_cast<size_t>(d.size()));
    for (size_t k = 0; k < out.size(); ++k) {
        const double x = d.data()[k];
        if (!std::isfinite(x) || std::abs(x) > std::numeric_limits<float>::max())
            throw tsis::Error("vertices: vertex " + std::to_string(k / 3) + " has " +
                              py::repr(py::float_(x)).cast<std::string>() +
                              " (every coordinate must be finite)");
        out[k] = static_cast<float>(x);
    }
    return out;
}

std::vector<uint32_t> triangleRows(const py::handle& value) {
    const py::array a = arrayOf(value, "triangles");
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw tsis::Error("triangles: expected an M×3 array, got shape " + shapeOf(a));
    const char kind = kindOf(a);
    if (kind != 'i' && kind != 'u' && kind != 'f')
        throw tsis::Error("triangles: expected integer vertex indices, got dtype " +
                          py::str(a.dtype()).cast<std::string>());
    std::vector<uint32_t> out(static_cast<size_t>(a.size()));
    auto refuse = [&](size_t k, const std::string& v, const char* why) {
        throw tsis::Error("triangles: triangle " + std::to_string(k / 3) + " has index " + v +
                          ", " + why);
    };
    constexpr double kIndices = 4294967296.0;  // 2³²
    if (kind == 'f') {
        const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
        for (size_t k = 0; k < out.size(); ++k) {
            const double x = d.data()[k];
            const std::string v = py::repr(py::float_(x)).cast<std::string>();
            if (!std::isfinite(x) || x != std::floor(x)) refuse(k, v, "not an integer");
            if (x < 0 || x >= kIndices) refuse(k, v, "outside [0, 2³²)");
            out[k] = static_cast<uint32_t>(x);
        }
    } else if (kind == 'u') {
        const auto u = py::array_t<uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
        for (size_t k = 0; k < out.size(); ++k) {
            if (u.data()[k] >= (1ull << 32))
                refuse(k, std::to_string(u.data()[k]), "outside [0, 2³²)");
            out[k] = static_cast<uint32_t>(u.data()[k]);
        }
    } else {
        const auto i = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
        for (size_t k = 0; k < out.size(); ++k) {
            const int64_t x = i.data()[k];
            if (x < 0 || x >= (int64_t{1} << 32)) refuse(k, std::to_string(x), "outside [0, 2³²)");
            out[k] = static_cast<uint32_t>(x);
        }
    }
    return out;
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

// The scenes a frame reads now, with the GIL released (guarded by the GIL):
// a change to one from another thread meanwhile is refused, not raced.
std::map<const Scene*, int>& scenesInFrames() {
    static std::map<const Scene*, int> busy;
    return busy;
}

class SceneInFrame {
  public:
    explicit SceneInFrame(const Scene& s) : scene_(&s) { ++scenesInFrames()[scene_]; }
    ~SceneInFrame() {
        if (--scenesInFrames()[scene_] == 0) scenesInFrames().erase(scene_);
    }
    SceneInFrame(const SceneInFrame&) = delete;
    SceneInFrame& operator=(const SceneInFrame&) = delete;

  private:
    const Scene* scene_;
};

// A setter of Scene.`name` that refuses while a frame reads the scene.
template <typename T>
auto sceneSetter(void (Scene::*set)(const T&), const char* name) {
    return [set, name](Scene& s, const T& value) {
        if (scenesInFrames().count(&s))
            throw tsis::Error(std::string("Scene.") + name +
                              ": the scene is being rendered on another thread; change it "
                              "between frames (or render a copy: copy.copy(scene))");
        (s.*set)(value);
    };
}

bool onMainThread() {
    const py::module_ threading = py::module_::import("threading");
    return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

// A frame with the GIL released. On the main thread Python's signal
// handlers run while it renders (Ctrl-C: the frame stops, KeyboardInterrupt
// is raised and the renderer stays usable); other threads cannot take signals.
py::object renderFrame(Renderer& r, const Scene& s, const py::kwargs& kw) {
    const Options o = optionsOf(kw);
    std::optional<py::error_already_set> raised;  // by a signal handler
    std::function<bool()> signals;
    if (onMainThread())
        signals = [&raised] {
            const py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() == 0) return false;
            raised.emplace();
            return true;
        };
    Frame f;
    const SceneInFrame reading(s);
    try {
        const py::gil_scoped_release release;
        f = r.render(s, o, signals);
    } catch (const tsis::Cancelled&) {
        if (raised) throw std::move(*raised);
        throw;
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
            [](const py::object& vertices, const py::object& triangles, const py::kwargs& kw) {
                return Scene::fromArrays(vertexRows(vertices), triangleRows(triangles),
                                         optionsOf(kw));
            },
            py::arg("vertices"), py::arg("triangles"),
            "vertices N×3 and triangles M×3 (counter-clockwise from outside); options as Scene()")
        .def_property("material", &Scene::material, sceneSetter(&Scene::setMaterial, "material"))
        .def_property("lights", &Scene::lights, sceneSetter(&Scene::setLights, "lights"))
        .def_property("camera", &Scene::camera, sceneSetter(&Scene::setCamera, "camera"))
        .def("__copy__", [](const Scene& s) { return Scene(s); })
        .def("__deepcopy__", [](const Scene& s, const py::dict&) { return Scene(s); })
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
        [](const py::object& a, const py::object& b, const py::object& mask) {
            const Image image = imageOf(a, "image"), reference = imageOf(b, "reference");
            const Image mi = mask.is_none() ? Image{} : imageOf(mask, "mask");
            const Metrics x = compare(image, reference, mask.is_none() ? nullptr : &mi);
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

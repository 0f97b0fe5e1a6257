// `import tsis`: the public API (include/tsis/) for Python through pybind11.
// Options are keyword arguments with the CLI's names (size_mm → --size-mm),
// images numpy arrays (row 0 = top), stats a dict, errors tsis.Error with the
// text `tsis` prints.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <charconv>
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

// A scalar as typed: a bool "true"/"false", an integer exactly (numpy's
// too), a float the shortest text that reads back the same, a str as it is;
// nullopt for anything else.
std::optional<std::string> scalarText(const py::handle& v) {
    if (py::isinstance<py::bool_>(v) || isNumpy(v, "bool_"))
        return std::string(v.cast<bool>() ? "true" : "false");
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (PyIndex_Check(v.ptr()))  // int, numpy.int64, …
        return py::str(py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr())))
            .cast<std::string>();
    if (py::isinstance<py::float_>(v) || isNumpy(v, "floating")) {
        char buf[64];
        const auto r = std::to_chars(buf, buf + sizeof buf, PyFloat_AsDouble(v.ptr()));
        return std::string(buf, r.ptr);
    }
    return std::nullopt;
}

// One keyword argument: str as typed, bool for a flag, a number (numpy's
// scalars too; an integer written exactly), or a sequence (x,y,z for a
// vector; each item for the repeatable light).
void setOption(Options& o, const std::string& name, const py::handle& v) {
    if (const std::optional<std::string> text = scalarText(v)) {
        o.set(name, *text);
    } else if (!py::isinstance<py::iterable>(v) || isNumpy(v, "generic")) {
        throw tsis::Error("option --" + name + ": expected a str, number, bool or sequence, not " +
                          typeName(v));
    } else if (name == "light") {
        o.unset(name);
        for (const py::handle item : v) o.set(name, py::str(item).cast<std::string>());
    } else {
        std::string joined;
        for (const py::handle item : v) {
            if (!joined.empty()) joined += ',';
            joined += py::str(item).cast<std::string>();
        }
        o.set(name, joined);
    }
}

// RenderSettings' field of option `name` from a Python value (the option's
// keyword of render()); tsis.Error as the option's.
void setSetting(RenderSettings& s, const std::string& name, const py::handle& v) {
    const std::optional<std::string> text = scalarText(v);
    if (!text)
        throw tsis::Error("option --" + name + ": expected a str, number or bool, not " +
                          typeName(v));
    s.set(name, *text);
}

// The field as Python has it: bool, int, float, or str (a choice; "file").
py::object settingValue(const RenderSettings& s, const RenderParameter& p) {
    const std::string t = s.get(p.name);
    switch (p.kind) {
        case RenderParameter::Kind::Flag:
            return py::bool_(t == "true");
        case RenderParameter::Kind::Integer:
            return py::int_(std::stoll(t));
        case RenderParameter::Kind::Real:
            return py::float_(std::stod(t));
        case RenderParameter::Kind::RealOrFile:
            return t == "file" ? py::object(py::str(t)) : py::object(py::float_(std::stod(t)));
        case RenderParameter::Kind::Choice:
            break;
    }
    return py::str(t);
}

// Settings with the render() keywords on top; a keyword that is no render
// setting is refused as Renderer::render refuses the option (`where` says
// who refuses).
RenderSettings settingsWith(RenderSettings s, const py::kwargs& kw,
                            const std::string& where = "Renderer::render") {
    for (const auto& [k, v] : kw) {
        const std::string name = optionName(k.cast<std::string>());
        const auto& rows = RenderSettings::parameters();
        if (name == "method" ||
            std::any_of(rows.begin(), rows.end(), [&](const auto& p) { return p.name == name; })) {
            setSetting(s, name, v);
            continue;
        }
        Options checked;
        setOption(checked, name, v);  // an unknown name or a bad value: the CLI's error
        throw tsis::Error(where + ": option --" + name +
                          (name == "cl-device" || name == "gl"
                               ? " is the Renderer's: give it when making one"
                               : " is the scene's: set it on the Scene"));
    }
    return s;
}

Options optionsOf(const py::dict& kwargs) {
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

// --- values shown and kept -----------------------------------------------

// The shortest text that reads back to `x` (0.1f → "0.1", 150.f → "150").
template <typename T>
std::string num(T x) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

std::string vec(const Vec3& v) {
    return "(" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ")";
}

std::string quoted(const std::string& s) {
    return py::repr(py::str(s)).cast<std::string>();
}

// The option names as Python spells them (size-mm → size_mm).
std::string pythonName(std::string name) {
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

// Whether option `name` takes no value: a flag set to "false" leaves no
// argument behind, an option with a value keeps "--name false" or refuses it.
bool isFlag(const std::string& name) {
    try {
        Options o;
        o.set(name, "false");
        return o.args().empty();
    } catch (const tsis::Error&) {
        return false;
    }
}

// Options as keyword arguments that make them again: {"size_mm": "20",
// "light": ["point:…", …], "allow_outside_assets": True}.
py::dict keywordsOf(const Options& o) {
    py::dict d;
    const std::vector<std::string>& a = o.args();
    for (size_t i = 0; i < a.size(); ++i) {
        const std::string name = a[i].substr(2);
        const py::str key(pythonName(name));
        if (isFlag(name)) {
            d[key] = true;
        } else if (name == "light") {  // the one repeatable scene option
            if (!d.contains(key)) d[key] = py::list();
            d[key].cast<py::list>().append(a[++i]);
        } else {
            d[key] = a[++i];
        }
    }
    return d;
}

// --- notes as warnings ---------------------------------------------------

PyObject* noteWarning = nullptr;  // tsis.NoteWarning, made with the module
bool quiet = false;               // tsis.set_quiet (guarded by the GIL)

// Each note through warnings.warn(text, tsis.NoteWarning), pointing at the
// Python line that made the scene; nothing when quiet. A filter that turns
// warnings into errors raises here.
void warnNotes(const std::vector<std::string>& notes, size_t from = 0) {
    for (size_t i = from; !quiet && i < notes.size(); ++i)
        if (PyErr_WarnEx(noteWarning, notes[i].c_str(), 1) < 0) throw py::error_already_set();
}

// --- Scene, Renderer and Frame as Python holds them -----------------------

// A mesh given as arrays (options() cannot name it; pickling needs it).
struct MeshArrays {
    std::vector<float> vertices;
    std::vector<uint32_t> triangles;
};

struct PyScene : Scene {
    explicit PyScene(Scene s, std::shared_ptr<const MeshArrays> a = nullptr)
        : Scene(std::move(s)), arrays(std::move(a)) {}
    std::shared_ptr<const MeshArrays> arrays;  // null: made from options
};

// A Scene from options, or from arrays when they are given.
PyScene makeScene(const py::dict& options, const py::object& vertices = py::none(),
                  const py::object& triangles = py::none()) {
    if (vertices.is_none()) return PyScene(Scene(optionsOf(options)));
    auto a =
        std::make_shared<MeshArrays>(MeshArrays{vertexRows(vertices), triangleRows(triangles)});
    return PyScene(Scene::fromArrays(a->vertices, a->triangles, optionsOf(options)), a);
}

// A Renderer that remembers what it was made with (for its repr).
struct PyRenderer : Renderer {
    PyRenderer(const std::string& cl, const std::string& g)
        : Renderer(cl, g), clDevice(cl), gl(g) {}
    std::string clDevice, gl;
};

struct PyFrame {
    py::object image, radiance, radiosity, position, normal, coverage, fluxAtlas;
    double lavg = 0;
    py::dict stats;
};

PyFrame frameToPython(const Frame& f) {
    py::array_t<uint8_t> rgb({f.height, f.width, 3});
    std::copy(f.rgb8.begin(), f.rgb8.end(), rgb.mutable_data());
    return {rgb,
            toNumpy(f.radiance),
            toNumpy(f.radiosity),
            toNumpy(f.position),
            toNumpy(f.normal),
            toNumpy(f.coverage),
            toNumpy(f.fluxAtlas),
            f.lavg,
            py::module_::import("json").attr("loads")(f.statsJson)};
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
    return [set, name](PyScene& s, const T& value) {
        if (scenesInFrames().count(&s))
            throw tsis::Error(std::string("Scene.") + name +
                              ": the scene is being rendered on another thread; change it "
                              "between frames (or render a copy: copy.copy(scene))");
        const size_t said = s.notes().size();
        (s.*set)(value);
        warnNotes(s.notes(), said);  // e.g. an environment's
    };
}

bool onMainThread() {
    const py::module_ threading = py::module_::import("threading");
    return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

// The keywords that make `s` again: its method and the settings off their
// defaults (its repr and its pickle).
py::dict changedSettings(const RenderSettings& s) {
    py::dict d;
    d["method"] = s.method;
    const RenderSettings defaults;
    for (const RenderParameter& p : RenderSettings::parameters())
        if (s.get(p.name) != defaults.get(p.name))
            d[pythonName(p.name).c_str()] = settingValue(s, p);
    return d;
}

// A frame with the GIL released. On the main thread Python's signal
// handlers run while it renders (Ctrl-C: the frame stops, KeyboardInterrupt
// is raised and the renderer stays usable); other threads cannot take signals.
// With settings (a tsis.RenderSettings or None) the keywords go on top of
// them; without, they are the options by name, as `tsis render` takes them.
PyFrame renderFrame(Renderer& r, const Scene& s, const py::object& settings, const py::kwargs& kw) {
    std::optional<RenderSettings> typed;
    if (!settings.is_none()) {
        if (!py::isinstance<RenderSettings>(settings))
            throw tsis::Error("render: settings must be a tsis.RenderSettings, not " +
                              typeName(settings));
        typed = settingsWith(settings.cast<RenderSettings>(), kw);
    }
    const Options o = typed ? Options() : optionsOf(kw);
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
        f = typed ? r.render(s, *typed, signals) : r.render(s, o, signals);
    } catch (const tsis::Cancelled&) {
        if (raised) throw std::move(*raised);
        throw;
    }
    return frameToPython(f);
}

// A Material from the keywords of one of its two forms.
Material makeMaterial(const std::string& name, const std::optional<Vec3>& sigmaS,
                      const std::optional<Vec3>& sigmaA, const std::optional<Vec3>& albedo,
                      const std::optional<Vec3>& mfpMm, float eta) {
    const bool bySigma = sigmaS && sigmaA && !albedo && !mfpMm;
    const bool byAlbedo = albedo && mfpMm && !sigmaS && !sigmaA;
    if (!bySigma && !byAlbedo) {
        std::string given;
        for (const auto& [what, has] : {std::pair{"sigma_s", bool(sigmaS)},
                                        {"sigma_a", bool(sigmaA)},
                                        {"albedo", bool(albedo)},
                                        {"mfp_mm", bool(mfpMm)}})
            if (has) given += std::string(given.empty() ? "" : ", ") + what;
        throw tsis::Error(
            "Material: give sigma_s and sigma_a, or albedo and mfp_mm (one form, "
            "both of its values); given: " +
            (given.empty() ? "none" : given));
    }
    Material m = byAlbedo ? Material::fromAlbedo(*albedo, *mfpMm, eta) : Material{};
    if (bySigma) {
        m.sigmaSPrime = *sigmaS;
        m.sigmaA = *sigmaA;
        m.eta = eta;
    }
    m.name = name;
    return m;
}

// A path: str or os.PathLike.
std::string pathOf(const py::object& p) {
    return py::str(py::module_::import("os").attr("fspath")(p)).cast<std::string>();
}

// An environment's pixels as numpy (H×W×3 float32), None when it has none.
py::object pixelsOf(const Environment& e) {
    if (e.pixels.empty()) return py::none();
    return py::array_t<float>({e.height, e.width, 3}, e.pixels.data());
}

// Sets them from an H×W×3 array of real numbers (None: none); the scene
// checks the rest (2:1) when the environment is set.
void setPixels(Environment& e, const py::object& pixels) {
    e.pixels.clear();
    e.width = e.height = 0;
    if (pixels.is_none()) return;
    const py::array a = arrayOf(pixels, "Environment: pixels");
    if (a.ndim() != 3 || a.shape(2) != 3 ||
        (kindOf(a) != 'f' && kindOf(a) != 'i' && kindOf(a) != 'u'))
        throw tsis::Error("Environment: pixels: expected an H×W×3 array of real numbers, got " +
                          py::str(a.dtype()).cast<std::string>() + " of shape " + shapeOf(a));
    const auto f = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
    e.pixels.assign(f.data(), f.data() + f.size());
    e.height = static_cast<int>(a.shape(0));
    e.width = static_cast<int>(a.shape(1));
}

// A sequence `t` of exactly n items for __setstate__.
py::tuple state(const py::tuple& t, size_t n, const char* what) {
    if (t.size() != n) throw std::runtime_error(std::string(what) + ": invalid pickled state");
    return t;
}

// --- objects of a scene of several ----------------------------------------

bool sameMaterial(const Material& a, const Material& b) {
    return a.name == b.name && a.sigmaSPrime == b.sigmaSPrime && a.sigmaA == b.sigmaA &&
           a.eta == b.eta && a.albedo == b.albedo && a.mfpMm == b.mfpMm &&
           a.albedoTexture == b.albedoTexture;
}

bool sameTransform(const Transform& a, const Transform& b) {
    return a.scale == b.scale && a.rotateDegrees == b.rotateDegrees &&
           a.translateMm == b.translateMm;
}

std::string transformRepr(const Transform& t) {
    return "Transform(scale=" + num(t.scale) + ", rotate_deg=" + vec(t.rotateDegrees) +
           ", translate_mm=" + vec(t.translateMm) + ")";
}

// An object's arrays as numpy (N×3 float32, M×3 uint32), None when it has none.
py::object verticesOf(const Object& o) {
    if (o.vertices.empty()) return py::none();
    return py::array_t<float>({py::ssize_t(o.vertices.size() / 3), py::ssize_t(3)},
                              o.vertices.data());
}

py::object trianglesOf(const Object& o) {
    if (o.triangles.empty()) return py::none();
    return py::array_t<uint32_t>({py::ssize_t(o.triangles.size() / 3), py::ssize_t(3)},
                                 o.triangles.data());
}

// Set from arrays checked as Scene.from_arrays checks them (None: none).
void setVertices(Object& o, const py::object& v) {
    o.vertices = v.is_none() ? std::vector<float>{} : vertexRows(v);
}

void setTriangles(Object& o, const py::object& t) {
    o.triangles = t.is_none() ? std::vector<uint32_t>{} : triangleRows(t);
}

Object makeObject(const py::object& mesh, const py::object& vertices, const py::object& triangles,
                  const std::optional<Transform>& transform,
                  const std::optional<Material>& material) {
    Object o;
    if (!mesh.is_none()) o.mesh = pathOf(mesh);
    setVertices(o, vertices);
    setTriangles(o, triangles);
    o.transform = transform.value_or(Transform{});
    o.material = material;
    return o;
}

// A sequence of tsis.Object, each checked to be one.
std::vector<Object> objectsOf(const py::handle& objects) {
    if (!py::isinstance<py::iterable>(objects) || py::isinstance<py::str>(objects))
        throw tsis::Error("Scene.from_objects: objects: expected a sequence of tsis.Object, not " +
                          typeName(objects));
    std::vector<Object> out;
    for (const py::handle item : objects) {
        if (!py::isinstance<Object>(item))
            throw tsis::Error("Scene.from_objects: object " + std::to_string(out.size()) +
                              " is a " + typeName(item) + ", not a tsis.Object");
        out.push_back(item.cast<Object>());
    }
    return out;
}

}  // namespace

PYBIND11_MODULE(_tsis, m) {
    m.doc() =
        "tsis: translucent materials rendered with the dipole BSSRDF (README, docs/design.md)";
    py::register_exception<tsis::Error>(m, "Error", PyExc_RuntimeError);
    m.attr("Error").attr("__doc__") =
        "what tsis refuses or fails at, with the one-line text `tsis` prints (a RuntimeError)";
    noteWarning = PyErr_NewExceptionWithDoc(
        "tsis.NoteWarning", "what loading a scene noted (`tsis render`'s \"tsis: note: …\")",
        PyExc_UserWarning, nullptr);
    m.attr("NoteWarning") = py::handle(noteWarning);
    m.def(
        "set_quiet",
        [](bool q) {
            const bool was = quiet;
            quiet = q;
            return was;
        },
        py::arg("quiet") = true,
        "quiet: scenes made from Python no longer warn their notes (tsis.NoteWarning); returns "
        "the previous setting");

    py::class_<Material>(m, "Material", "a translucent medium (docs/design.md §2)")
        .def(py::init([](const std::string& name, const std::optional<Vec3>& sigmaS,
                         const std::optional<Vec3>& sigmaA, const std::optional<Vec3>& albedo,
                         const std::optional<Vec3>& mfpMm, float eta,
                         const py::object& albedoTexture) {
                 Material x = makeMaterial(name, sigmaS, sigmaA, albedo, mfpMm, eta);
                 if (!albedoTexture.is_none()) x.albedoTexture = pathOf(albedoTexture);
                 return x;
             }),
             py::arg("name") = "custom", py::kw_only(), py::arg("sigma_s") = py::none(),
             py::arg("sigma_a") = py::none(), py::arg("albedo") = py::none(),
             py::arg("mfp_mm") = py::none(), py::arg("eta") = 1.3,
             py::arg("albedo_texture") = py::none(),
             "Material(sigma_s=…, sigma_a=…, eta=1.3) or Material(albedo=…, mfp_mm=…, eta=1.3): "
             "a medium by its scattering and absorption (1/mm, RGB), or by its diffuse "
             "reflectance and mean free path (mm), inverted by the renderer's --profile; "
             "albedo_texture an image file scaling the albedo through the object's texture "
             "coordinates")
        .def_static("preset", &Material::preset, py::arg("name"),
                    "a preset of tsis.preset_materials()")
        .def_readwrite("name", &Material::name, "a preset's name, else 'custom'")
        // σ given: the material is no longer the albedo's (albedo, mfp_mm None).
        .def_property(
            "sigma_s", [](const Material& x) { return x.sigmaSPrime; },
            [](Material& x, const Vec3& v) {
                x.sigmaSPrime = v;
                x.albedo = x.mfpMm = std::nullopt;
            },
            "reduced scattering σs' (1/mm, RGB)")
        .def_property(
            "sigma_a", [](const Material& x) { return x.sigmaA; },
            [](Material& x, const Vec3& v) {
                x.sigmaA = v;
                x.albedo = x.mfpMm = std::nullopt;
            },
            "absorption σa (1/mm, RGB)")
        .def_readwrite("eta", &Material::eta, "the relative index of refraction η")
        .def_readonly("albedo", &Material::albedo,
                      "diffuse reflectance (RGB) when given, else None")
        .def_readonly("mfp_mm", &Material::mfpMm, "mean free path (mm, RGB) when given, else None")
        .def_property(
            "albedo_texture", [](const Material& x) { return x.albedoTexture; },
            [](Material& x, const py::object& path) { x.albedoTexture = pathOf(path); },
            "an albedo texture (an image file, sRGB when 8-bit; '' none): a file material's "
            "own, or set on an object's material (tsis.Object) to apply through its texture "
            "coordinates")
        .def("__repr__",
             [](const Material& x) {
                 std::string s = "Material(" + (x.name == "custom" ? "" : quoted(x.name) + ", ");
                 if (x.albedo && x.mfpMm)
                     s += "albedo=" + vec(*x.albedo) + ", mfp_mm=" + vec(*x.mfpMm);
                 else
                     s += "sigma_s=" + vec(x.sigmaSPrime) + ", sigma_a=" + vec(x.sigmaA);
                 s += ", eta=" + num(x.eta);
                 if (!x.albedoTexture.empty()) s += ", albedo_texture=" + quoted(x.albedoTexture);
                 return s + ")";
             })
        .def(
            "__eq__", [](const Material& a, const Material& b) { return sameMaterial(a, b); },
            py::is_operator())
        .def(py::pickle(
            [](const Material& x) {
                return py::make_tuple(x.name, x.sigmaSPrime, x.sigmaA, x.eta, x.albedo, x.mfpMm,
                                      x.albedoTexture);
            },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 7, "Material");
                return Material{t[0].cast<std::string>(),
                                t[1].cast<Vec3>(),
                                t[2].cast<Vec3>(),
                                t[3].cast<float>(),
                                t[4].cast<std::optional<Vec3>>(),
                                t[5].cast<std::optional<Vec3>>(),
                                t[6].cast<std::string>()};
            }));
    m.def("preset_material", &presetMaterial, py::arg("name"), "Material.preset");
    m.def("preset_materials", &presetMaterialNames,
          "the names of the presets (`tsis materials`): skin1, marble, …");

    py::class_<Light>(m, "Light", "a point or directional light")
        .def(py::init([](std::optional<Vec3> position, std::optional<Vec3> direction, Vec3 rgb) {
                 if (position.has_value() == direction.has_value())
                     throw tsis::Error("Light: give position (a point light) or direction");
                 return Light{direction.has_value(), position.value_or(direction.value_or(Vec3{})),
                              rgb};
             }),
             py::kw_only(), py::arg("position") = py::none(), py::arg("direction") = py::none(),
             py::arg("rgb") = Vec3{1, 1, 1},
             "Light(position=…) a point light at position (mm), rgb its intensity (W/sr); "
             "Light(direction=…) a directional light, rgb its irradiance (W/mm²)")
        .def_readwrite("directional", &Light::directional, "False: a point light")
        .def_readwrite("vec", &Light::vec, "point: position (mm); directional: direction")
        .def_readwrite("rgb", &Light::rgb, "point: intensity (W/sr); directional: W/mm²")
        .def("__repr__",
             [](const Light& l) {
                 return std::string("Light(") + (l.directional ? "direction=" : "position=") +
                        vec(l.vec) + ", rgb=" + vec(l.rgb) + ")";
             })
        .def(
            "__eq__",
            [](const Light& a, const Light& b) {
                return a.directional == b.directional && a.vec == b.vec && a.rgb == b.rgb;
            },
            py::is_operator())
        .def(py::pickle([](const Light& l) { return py::make_tuple(l.directional, l.vec, l.rgb); },
                        [](const py::tuple& t0) {
                            const py::tuple t = state(t0, 3, "Light");
                            return Light{t[0].cast<bool>(), t[1].cast<Vec3>(), t[2].cast<Vec3>()};
                        }));

    py::class_<Environment>(m, "Environment", "a lat-long radiance map lighting the scene")
        .def(py::init([](const py::object& path, const py::object& pixels, double rotateDeg,
                         double intensity) {
                 if (path.is_none() && pixels.is_none())
                     throw tsis::Error("Environment: give a path or pixels");
                 Environment e{path.is_none() ? "" : pathOf(path), intensity, rotateDeg};
                 setPixels(e, pixels);
                 return e;
             }),
             py::arg("path") = py::none(), py::kw_only(), py::arg("pixels") = py::none(),
             py::arg("rotate_deg") = 0.0, py::arg("intensity") = 1.0,
             "a lat-long radiance map in W/(mm²·sr): a file (.exr, .hdr) or pixels (H×W×3, "
             "2:1, row 0 the zenith; path then names it), scaled by intensity and turned by "
             "rotate_deg about +y; checked when set as Scene.environment")
        .def_readwrite("path", &Environment::path, "the map's file; with pixels, only its name")
        .def_property("pixels", &pixelsOf, &setPixels, "H×W×3 float32, or None (a file's)")
        .def_readwrite("rotate_deg", &Environment::rotateDegrees,
                       "the map turned about the up axis (+y), degrees")
        .def_readwrite("intensity", &Environment::intensity, "the map's radiance scaled by it")
        .def("__repr__",
             [](const Environment& e) {
                 const std::string rest =
                     "rotate_deg=" + num(e.rotateDegrees) + ", intensity=" + num(e.intensity);
                 if (e.pixels.empty()) return "Environment(" + quoted(e.path) + ", " + rest + ")";
                 return "<tsis.Environment " + quoted(e.path) + ": " + std::to_string(e.width) +
                        "×" + std::to_string(e.height) + " pixels, " + rest + ">";
             })
        .def(
            "__eq__",
            [](const Environment& a, const Environment& b) {
                return a.path == b.path && a.rotateDegrees == b.rotateDegrees &&
                       a.intensity == b.intensity && a.width == b.width && a.height == b.height &&
                       a.pixels == b.pixels;
            },
            py::is_operator())
        .def(py::pickle(
            [](const Environment& e) {
                return py::make_tuple(e.path, e.rotateDegrees, e.intensity, pixelsOf(e));
            },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 4, "Environment");
                Environment e{t[0].cast<std::string>(), t[2].cast<double>(), t[1].cast<double>()};
                setPixels(e, t[3]);
                return e;
            }));

    py::class_<Camera>(m, "Camera", "a pinhole camera looking from eye at target")
        .def(py::init([](Vec3 eye, Vec3 target, Vec3 up, float fov) {
                 return Camera{eye, target, up, fov};
             }),
             py::arg("eye"), py::arg("target") = Vec3{0, 0, 0}, py::arg("up") = Vec3{0, 1, 0},
             py::arg("fov") = 35.0f,
             "Camera(eye, target=(0, 0, 0), up=(0, 1, 0), fov=35): positions in mm, fov the "
             "vertical field of view in degrees; checked when set as Scene.camera")
        .def_readwrite("eye", &Camera::eye, "where it looks from (mm)")
        .def_readwrite("target", &Camera::target, "what it looks at (mm)")
        .def_readwrite("up", &Camera::up, "the direction shown upwards")
        .def_readwrite("fov", &Camera::fovYDegrees, "vertical field of view (degrees)")
        .def("__repr__",
             [](const Camera& c) {
                 return "Camera(eye=" + vec(c.eye) + ", target=" + vec(c.target) +
                        ", up=" + vec(c.up) + ", fov=" + num(c.fovYDegrees) + ")";
             })
        .def(
            "__eq__",
            [](const Camera& a, const Camera& b) {
                return a.eye == b.eye && a.target == b.target && a.up == b.up &&
                       a.fovYDegrees == b.fovYDegrees;
            },
            py::is_operator())
        .def(py::pickle(
            [](const Camera& c) { return py::make_tuple(c.eye, c.target, c.up, c.fovYDegrees); },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 4, "Camera");
                return Camera{t[0].cast<Vec3>(), t[1].cast<Vec3>(), t[2].cast<Vec3>(),
                              t[3].cast<float>()};
            }));

    py::class_<Transform>(m, "Transform",
                          "where an object stands in its scene: scaled, then turned (degrees "
                          "about x, then y, then z), then moved (mm)")
        .def(py::init([](float scale, Vec3 rotate, Vec3 translate) {
                 return Transform{scale, rotate, translate};
             }),
             py::kw_only(), py::arg("scale") = 1.0f, py::arg("rotate_deg") = Vec3{0, 0, 0},
             py::arg("translate_mm") = Vec3{0, 0, 0},
             "Transform(scale=1, rotate_deg=(0, 0, 0), translate_mm=(0, 0, 0)); checked when "
             "the scene is made (Scene.from_objects)")
        .def_readwrite("scale", &Transform::scale, "the object's size × scale (> 0)")
        .def_readwrite("rotate_deg", &Transform::rotateDegrees, "degrees about x, then y, then z")
        .def_readwrite("translate_mm", &Transform::translateMm, "the move (mm), last")
        .def("__repr__", &transformRepr)
        .def(
            "__eq__", [](const Transform& a, const Transform& b) { return sameTransform(a, b); },
            py::is_operator())
        .def(py::pickle(
            [](const Transform& t) {
                return py::make_tuple(t.scale, t.rotateDegrees, t.translateMm);
            },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 3, "Transform");
                return Transform{t[0].cast<float>(), t[1].cast<Vec3>(), t[2].cast<Vec3>()};
            }));

    py::class_<Object>(m, "Object",
                       "one object of a scene of several (Scene.from_objects): a mesh file or "
                       "builtin:NAME, or arrays (mm), placed by its transform, scattering in its "
                       "material")
        .def(py::init(&makeObject), py::kw_only(), py::arg("mesh") = py::none(),
             py::arg("vertices") = py::none(), py::arg("triangles") = py::none(),
             py::arg("transform") = py::none(), py::arg("material") = py::none(),
             "Object(mesh=None, vertices=None, triangles=None, transform=None, material=None): "
             "a mesh (a file: glTF in metres, others in mm; or builtin:NAME) or vertices N×3 "
             "(mm) and triangles M×3 (counter-clockwise from outside), checked as "
             "Scene.from_arrays checks them; material None: the file's own, else the scene's")
        .def_property(
            "mesh",
            [](const Object& o) -> py::object {
                return o.mesh.empty() ? py::object(py::none()) : py::str(o.mesh);
            },
            [](Object& o, const py::object& mesh) { o.mesh = mesh.is_none() ? "" : pathOf(mesh); },
            "the mesh file or builtin:NAME, or None (arrays)")
        .def_property("vertices", &verticesOf, &setVertices,
                      "N×3 float32 (mm), or None (a mesh file's)")
        .def_property("triangles", &trianglesOf, &setTriangles,
                      "M×3 uint32 vertex indices, or None (a mesh file's)")
        .def_readwrite("transform", &Object::transform, "where it stands (tsis.Transform)")
        .def_readwrite("material", &Object::material,
                       "what all of it scatters in, or None (the file's, else the scene's)")
        .def("__repr__",
             [](const Object& o) {
                 std::string rest = "transform=" + transformRepr(o.transform);
                 if (o.material)
                     rest += ", material=" + py::repr(py::cast(*o.material)).cast<std::string>();
                 if (o.vertices.empty() && o.triangles.empty())
                     return "Object(mesh=" + (o.mesh.empty() ? "None" : quoted(o.mesh)) + ", " +
                            rest + ")";
                 return "<tsis.Object" + (o.mesh.empty() ? "" : " " + quoted(o.mesh)) + ": " +
                        std::to_string(o.vertices.size() / 3) + " vertices, " +
                        std::to_string(o.triangles.size() / 3) + " triangles, " + rest + ">";
             })
        .def(
            "__eq__",
            [](const Object& a, const Object& b) {
                return a.mesh == b.mesh && a.vertices == b.vertices && a.triangles == b.triangles &&
                       sameTransform(a.transform, b.transform) &&
                       a.material.has_value() == b.material.has_value() &&
                       (!a.material || sameMaterial(*a.material, *b.material));
            },
            py::is_operator())
        .def(py::pickle(
            [](const Object& o) {
                return py::make_tuple(o.mesh, verticesOf(o), trianglesOf(o), o.transform,
                                      o.material);
            },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 5, "Object");
                Object o;
                o.mesh = t[0].cast<std::string>();
                setVertices(o, t[1]);
                setTriangles(o, t[2]);
                o.transform = t[3].cast<Transform>();
                o.material = t[4].cast<std::optional<Material>>();
                return o;
            }));

    py::class_<PyScene>(m, "Scene",
                        "what a frame shows: the mesh with its materials, lights, environment "
                        "and camera")
        .def(py::init([](const py::kwargs& kw) {
                 PyScene s = makeScene(kw);
                 warnNotes(s.notes());
                 return s;
             }),
             "Scene(mesh='builtin:default', size_mm=10, material='skin1', …): the scene options "
             "of `tsis render`; each note loading it makes is a tsis.NoteWarning")
        .def_static(
            "from_arrays",
            [](const py::object& vertices, const py::object& triangles, const py::kwargs& kw) {
                PyScene s = makeScene(kw, vertices, triangles);
                warnNotes(s.notes());
                return s;
            },
            py::arg("vertices"), py::arg("triangles"),
            "vertices N×3 and triangles M×3 (counter-clockwise from outside); options as Scene()")
        .def_static(
            "from_objects",
            [](const py::object& objects, const py::kwargs& kw) {
                PyScene s(Scene::fromObjects(objectsOf(objects), optionsOf(kw)));
                warnNotes(s.notes());
                return s;
            },
            py::arg("objects"),
            "several tsis.Object as one scene, each placed by its transform and scattering in "
            "its material (a medium each, shadows between them); the whole scaled to size_mm "
            "(size_mm='file': each at its own size in mm); options as Scene() (no mesh); errors "
            "name the object (\"object 1 (builtin:sphere): scale -1 must be positive\")")
        .def_property_readonly(
            "objects", [](const PyScene& s) { return s.objects(); },
            "the objects as given to Scene.from_objects (copies; [] for any other scene)")
        .def_property("material", &Scene::material, sceneSetter(&Scene::setMaterial, "material"),
                      "the material of every triangle; None when the mesh file's own apply")
        .def_property_readonly("materials", &Scene::materials,
                               "what each part scatters in (the file's, or the one material)")
        .def_property("lights", &Scene::lights, sceneSetter(&Scene::setLights, "lights"),
                      "the lights (tsis.Light); [] with an environment and none given")
        .def_property("environment", &Scene::environment,
                      sceneSetter(&Scene::setEnvironment, "environment"),
                      "the Environment lighting the scene, or None")
        .def_property("camera", &Scene::camera, sceneSetter(&Scene::setCamera, "camera"),
                      "the camera (tsis.Camera)")
        .def_property_readonly("notes", &Scene::notes, "what loading the scene noted")
        .def_property_readonly(
            "render_settings", &Scene::renderSettings,
            "the tsis.RenderSettings its frames start from (the file's light units' exposure)")
        .def(
            "options", [](const PyScene& s) { return keywordsOf(s.options()); },
            "the scene options as keywords that make this scene again (tsis.Scene(**options); "
            "from arrays: Scene.from_arrays(vertices, triangles, **options))")
        .def_property_readonly("mesh_name", &Scene::meshName,
                               "the mesh's name ('arrays', 'objects', a file's or builtin:NAME)")
        .def_property_readonly("vertex_count", &Scene::vertexCount, "the mesh's vertices")
        .def_property_readonly("triangle_count", &Scene::triangleCount, "the mesh's triangles")
        .def("__copy__", [](const PyScene& s) { return PyScene(s); })
        .def("__deepcopy__", [](const PyScene& s, const py::dict&) { return PyScene(s); })
        .def("__repr__",
             [](const PyScene& s) {
                 const auto mat = s.material();
                 const size_t objects = s.objects().size();
                 return "<tsis.Scene " + quoted(s.meshName()) + ": " +
                        (objects ? std::to_string(objects) + " objects, " : "") +
                        std::to_string(s.triangleCount()) + " triangles, material " +
                        (mat       ? mat->name
                         : objects ? "of each object"
                                   : "from the file") +
                        ", " + std::to_string(s.lights().size()) + " lights" +
                        (s.environment() ? ", environment " + quoted(s.environment()->path) : "") +
                        ">";
             })
        // Pickled as its options (and its arrays or objects and an environment of pixels),
        // made again on unpickling.
        .def(py::pickle(
            [](const PyScene& s) {
                py::object v = py::none(), t = py::none();
                if (s.arrays) {
                    const MeshArrays& a = *s.arrays;
                    v = py::array_t<float>({py::ssize_t(a.vertices.size() / 3), py::ssize_t(3)},
                                           a.vertices.data());
                    t = py::array_t<uint32_t>({py::ssize_t(a.triangles.size() / 3), py::ssize_t(3)},
                                              a.triangles.data());
                }
                // An environment of pixels is not among the options.
                const auto env = s.environment();
                const py::object pixelEnv =
                    env && !env->pixels.empty() ? py::cast(*env) : py::object(py::none());
                return py::make_tuple(keywordsOf(s.options()), v, t, pixelEnv, s.objects());
            },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 5, "Scene");
                const auto objects = t[4].cast<std::vector<Object>>();
                PyScene s =
                    objects.empty()
                        ? makeScene(t[0].cast<py::dict>(), t[1], t[2])
                        : PyScene(Scene::fromObjects(objects, optionsOf(t[0].cast<py::dict>())));
                if (!t[3].is_none()) s.setEnvironment(t[3].cast<Environment>());
                return s;
            }));

    // One property per render option, made from the options' table
    // (RenderSettings::parameters()): a new option is one here too.
    py::class_<RenderSettings> settings(
        m, "RenderSettings",
        "how a frame is rendered, typed: a property per render option of `tsis render` "
        "(its keyword of render(): no_specular=True, tone='aces', roughness='file'), checked as "
        "the option is");
    settings
        .def(py::init([](const py::kwargs& kw) {
                 return settingsWith(RenderSettings(), kw, "RenderSettings");
             }),
             "RenderSettings(method='tsis', samples=512, …): the defaults, the keywords on top")
        .def_property(
            "method", [](const RenderSettings& s) { return s.method; },
            [](RenderSettings& s, const std::string& m) { s.set("method", m); },
            "the method (`tsis render --method`): pyramid, tsis, hybrid, mis, ltsm, tsm, lss, "
            "hierarchical, reference or volumetric");
    for (const RenderParameter& p : RenderSettings::parameters())
        settings.def_property(
            pythonName(p.name).c_str(), [p](const RenderSettings& s) { return settingValue(s, p); },
            [p](RenderSettings& s, const py::handle& v) { setSetting(s, p.name, v); },
            p.help.c_str());
    settings
        .def("__eq__",
             [](const RenderSettings& a, const RenderSettings& b) {
                 const auto& rows = RenderSettings::parameters();
                 return a.method == b.method &&
                        std::all_of(rows.begin(), rows.end(), [&](const RenderParameter& p) {
                            return a.get(p.name) == b.get(p.name);
                        });
             })
        .def("__repr__",
             [](const RenderSettings& s) {
                 std::string r = "tsis.RenderSettings(";
                 for (const auto& [k, v] : changedSettings(s))
                     r += (r.back() == '(' ? "" : ", ") + k.cast<std::string>() + "=" +
                          py::repr(v).cast<std::string>();
                 return r + ")";
             })
        .def(py::pickle(&changedSettings, [](const py::dict& d) {
            return settingsWith(RenderSettings(), py::kwargs(d));
        }));

    py::class_<PyFrame>(m, "Frame", "what Renderer.render gives")
        .def_readwrite("image", &PyFrame::image, "tone-mapped sRGB, H×W×3 uint8, row 0 = top")
        .def_readwrite("radiance", &PyFrame::radiance, "H×W×3 float32")
        .def_readwrite("radiosity", &PyFrame::radiosity, "H×W×3 float32")
        .def_readwrite("position", &PyFrame::position, "H×W×3 float32 (mm)")
        .def_readwrite("normal", &PyFrame::normal, "H×W×3 float32")
        .def_readwrite("coverage", &PyFrame::coverage, "H×W×1 float32")
        .def_readwrite("flux_atlas", &PyFrame::fluxAtlas, "the flux atlas, float32")
        .def_readwrite("lavg", &PyFrame::lavg, "log-average luminance of the covered pixels")
        .def_readwrite("stats", &PyFrame::stats, "what `tsis render --stats` writes")
        .def("__repr__",
             [](const PyFrame& f) {
                 const py::object ms = f.stats.contains("ms") ? f.stats["ms"] : py::dict();
                 std::string s =
                     py::str("<tsis.Frame {}×{} {}, lavg {:.4g}")
                         .format(f.stats.attr("get")("width"), f.stats.attr("get")("height"),
                                 f.stats.attr("get")("method"), f.lavg);
                 if (py::isinstance<py::dict>(ms) && ms.contains("total"))
                     s += py::str(", {:.1f} ms").format(ms["total"]).cast<std::string>();
                 return s + ">";
             })
        .def(py::pickle(
            [](const PyFrame& f) {
                return py::make_tuple(f.image, f.radiance, f.radiosity, f.position, f.normal,
                                      f.coverage, f.fluxAtlas, f.lavg, f.stats);
            },
            [](const py::tuple& t0) {
                const py::tuple t = state(t0, 9, "Frame");
                return PyFrame{t[0],
                               t[1],
                               t[2],
                               t[3],
                               t[4],
                               t[5],
                               t[6],
                               t[7].cast<double>(),
                               t[8].cast<py::dict>()};
            }));

    py::class_<PyRenderer>(m, "Renderer",
                           "renders frames, keeping its GL context, programs and light maps "
                           "from one to the next")
        .def(py::init<const std::string&, const std::string&>(), py::arg("cl_device") = "",
             py::arg("gl") = "",
             "cl_device: the OpenCL device (`tsis render --cl-device`; '' $TSIS_CL_DEVICE, else "
             "PoCL); "
             "gl: egl, osmesa or auto (`--gl`; '' $TSIS_GL, else auto)")
        .def(
            "render",
            [](PyRenderer& r, const PyScene& s, const py::object& settings, const py::kwargs& kw) {
                return renderFrame(r, s, settings, kw);
            },
            py::arg("scene"), py::arg("settings") = py::none(),
            "a Frame: image (H×W×3 uint8), radiance, radiosity, position, normal, coverage, "
            "flux_atlas (float32, row 0 = top), lavg, stats (dict); settings a tsis.RenderSettings "
            "(the keywords on top of it), or the options of `tsis render` as keywords")
        .def("__repr__", [](const PyRenderer& r) {
            return "tsis.Renderer(cl_device=" + quoted(r.clDevice) + ", gl=" + quoted(r.gl) + ")";
        });
    m.def(
        "render",
        [](const PyScene& s, const py::object& settings, const py::kwargs& kw) {
            return renderFrame(sharedRenderer(), s, settings, kw);
        },
        py::arg("scene"), py::arg("settings") = py::none(),
        "Renderer.render with one renderer kept for every call");
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
    m.def(
        "write_image",
        [](const py::object& path, const py::object& image) {
            const py::array a = arrayOf(image, "image");
            if (a.dtype().is(py::dtype::of<uint8_t>())) {  // tone-mapped: PNG, JPEG, …
                if (a.ndim() != 3 || a.shape(2) != 3)
                    throw tsis::Error("image: expected an H×W×3 uint8 array, got shape " +
                                      shapeOf(a));
                const auto u = py::array_t<uint8_t, py::array::c_style>::ensure(a);
                Frame f;
                f.height = static_cast<int>(a.shape(0));
                f.width = static_cast<int>(a.shape(1));
                f.rgb8.assign(u.data(), u.data() + u.size());
                writeImage(f, pathOf(path));
            } else {
                writeImage(imageOf(a, "image"), pathOf(path));  // linear: EXR
            }
        },
        py::arg("path"), py::arg("image"),
        "writes Frame.image (H×W×3 uint8; PNG, JPEG… by the extension) or a linear float "
        "image (H×W×C; EXR)");
    m.def(
        "read_image", [](const py::object& path) { return toNumpy(readImage(pathOf(path))); },
        py::arg("path"), "an image file as linear float32, H×W×C");
    m.def("option_help", &Options::help,
          "the options of `tsis render`, scene's and render's, with what each does");
}

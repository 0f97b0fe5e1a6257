"""The Python face of tsis (README "Python"): keyword constructors, reprs,
equality, pickling, notes as warnings, numpy scalars, two renderers on two
threads, and the type stubs (python/tsis/__init__.pyi)."""
import ast
import copy
import pathlib
import pickle
import threading
import time
import warnings

import numpy as np
import pytest

import tsis

SMALL = dict(width=40, height=32, atlas_res=128, light_res=256)
SKY = str(pathlib.Path(__file__).resolve().parents[2] / "data" / "env" / "sky.hdr")


def tetrahedron():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int64)
    return v, t


def roundtrip(x):
    return pickle.loads(pickle.dumps(x))


# --- values --------------------------------------------------------------


def test_material_has_two_keyword_forms():
    m = tsis.Material(albedo=(0.8, 0.6, 0.5), mfp_mm=(3, 1.5, 0.8), eta=1.4)
    assert m.albedo == pytest.approx([0.8, 0.6, 0.5]) and m.mfp_mm == pytest.approx([3, 1.5, 0.8])
    assert m.eta == pytest.approx(1.4) and m.name == "custom"
    assert all(x > 0 for x in m.sigma_s + m.sigma_a)  # inverted by the default profile
    s = tsis.Material("mine", sigma_s=(1, 2, 3), sigma_a=(0.1, 0.2, 0.3))
    assert s.albedo is None and s.mfp_mm is None and s.eta == pytest.approx(1.3)
    for bad, given in [(dict(), "none"), (dict(sigma_s=(1, 1, 1)), "sigma_s"),
                       (dict(albedo=(0.5,) * 3, sigma_a=(1,) * 3), "sigma_a, albedo"),
                       (dict(sigma_s=(1,) * 3, sigma_a=(1,) * 3, albedo=(0.5,) * 3,
                             mfp_mm=(1,) * 3), "sigma_s, sigma_a, albedo, mfp_mm")]:
        with pytest.raises(tsis.Error, match=f"give sigma_s and sigma_a, or albedo and mfp_mm "
                                             f".*; given: {given}$"):
            tsis.Material(**bad)
    # σ set by hand: the material is no longer the albedo's.
    m.sigma_a = [x * 2 for x in m.sigma_a]
    assert m.albedo is None and m.mfp_mm is None


def test_presets():
    assert tsis.Material.preset("skin1") == tsis.preset_material("skin1")
    assert tsis.Material.preset("marble").eta == pytest.approx(1.5)
    with pytest.raises(tsis.Error):
        tsis.Material.preset("nope")


VALUES = [
    tsis.Material.preset("skin1"),
    tsis.Material("thin", sigma_s=(0.1, 0.2, 0.3), sigma_a=(0.01, 0.02, 0.03), eta=1.33),
    tsis.Material(albedo=(0.8, 0.6, 0.5), mfp_mm=(3, 1.5, 0.8)),
    tsis.Light(position=(0, 12, 6), rgb=(150, 150, 150)),
    tsis.Light(direction=(0.6, -0.4, -1), rgb=(0.12, 0.12, 0.12)),
    tsis.Camera(eye=(0, 0, 25), fov=30.5),
    tsis.Environment("sky.hdr", rotate_deg=30, intensity=0.25),
]


@pytest.mark.parametrize("x", VALUES, ids=lambda x: type(x).__name__)
def test_values_have_an_eval_repr_equality_and_pickle(x):
    again = eval(repr(x), vars(tsis))
    assert again == x and not (again != x)
    assert roundtrip(x) == x and copy.deepcopy(x) == x
    assert x != "something else"
    with pytest.raises(TypeError):
        hash(x)  # mutable: not hashable


def test_values_differ_when_a_field_does():
    a, b = tsis.Camera(eye=(0, 0, 25)), tsis.Camera(eye=(0, 0, 25))
    b.fov = 36
    assert a != b
    assert tsis.Environment("a.hdr") != tsis.Environment("a.hdr", intensity=2)
    assert tsis.Light(position=(1, 2, 3)) != tsis.Light(direction=(1, 2, 3))


def test_numpy_scalars_wherever_a_number_goes():
    light = tsis.Light(position=np.array([0, 12, 6]), rgb=(np.int64(150), np.float32(150), 150))
    assert light == tsis.Light(position=(0, 12, 6), rgb=(150, 150, 150))
    assert tsis.Camera(eye=(0, 0, np.float32(25)), fov=np.float64(30)).fov == 30
    assert tsis.Material(sigma_s=np.ones(3), sigma_a=np.full(3, 0.1, np.float32),
                         eta=np.float32(1.25)).eta == 1.25
    assert tsis.Environment(pathlib.Path("x.hdr"), rotate_deg=np.int64(30),
                            intensity=np.float32(0.5)) == tsis.Environment("x.hdr", rotate_deg=30,
                                                                            intensity=0.5)
    s = tsis.Scene(mesh="builtin:sphere")
    assert tsis.render(s, width=np.int64(32), height=np.int16(24), atlas_res=np.int64(64),
                       light_res=256).image.shape == (24, 32, 3)


# --- scenes --------------------------------------------------------------


def test_scene_environment_materials_and_repr():
    s = tsis.Scene(mesh="builtin:sphere", material="marble")
    assert s.environment is None and s.materials == [s.material]
    assert "builtin:sphere" in repr(s) and "marble" in repr(s)
    s.environment = tsis.Environment(SKY, rotate_deg=30)
    assert s.environment == tsis.Environment(SKY, rotate_deg=30) and s.lights == []
    assert s.options()["env_rotate"] == "30" and "sky.hdr" in repr(s)
    with pytest.raises(tsis.Error, match="env-intensity"):
        s.environment = tsis.Environment(SKY, intensity=-1)
    s.environment = None
    assert s.environment is None and len(s.lights) == 2  # the defaults again


def test_an_environment_of_pixels_pickles_with_its_scene():
    sky = np.zeros((16, 32, 3), np.float32)
    sky[:8] = (0.02, 0.03, 0.05)  # the upper half lit
    env = tsis.Environment("sky", pixels=sky, rotate_deg=30)
    assert np.array_equal(env.pixels, sky) and env.pixels.dtype == np.float32
    assert roundtrip(env) == env and repr(env).startswith("<tsis.Environment 'sky': 32×16 pixels")
    assert env != tsis.Environment("sky", pixels=sky * 2, rotate_deg=30)
    assert tsis.Environment(SKY).pixels is None
    s = tsis.Scene(mesh="builtin:sphere")
    s.environment = env
    again = roundtrip(s)
    assert again.environment == env and s.environment == env
    r = tsis.Renderer()
    assert np.array_equal(r.render(again, **SMALL).image, r.render(s, **SMALL).image)
    with pytest.raises(tsis.Error, match="give a path or pixels"):
        tsis.Environment()
    with pytest.raises(tsis.Error, match=r"H×W×3 array of real numbers, got float64 of shape "
                                         r"\(16, 32\)"):
        tsis.Environment(pixels=np.zeros((16, 32)))


def test_notes_are_warnings_unless_quiet():
    open_mesh = dict(vertices=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles=[[0, 1, 2]])
    with pytest.warns(tsis.NoteWarning, match="not closed") as said:
        s = tsis.Scene.from_arrays(**open_mesh)
    assert [str(w.message) for w in said] == s.notes and len(s.notes) == 1
    assert said[0].filename == __file__  # points at the line that made the scene
    assert issubclass(tsis.NoteWarning, UserWarning)
    was = tsis.set_quiet(True)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            assert tsis.Scene.from_arrays(**open_mesh).notes == s.notes
    finally:
        tsis.set_quiet(was)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert tsis.Scene(mesh="builtin:sphere").notes == []
        with pytest.raises(tsis.NoteWarning):
            tsis.Scene.from_arrays(**open_mesh)


def changed_scene():
    s = tsis.Scene(mesh="builtin:sphere", size_mm=12)
    s.material = tsis.Material(albedo=(0.8, 0.6, 0.5), mfp_mm=(2, 1, 0.5), eta=1.4)
    s.lights = [tsis.Light(position=(3, 12, 6), rgb=(140, 150, 160))]
    s.camera = tsis.Camera(eye=(1, 2, 24), fov=33)
    return s


def test_a_scene_pickles_as_its_options_and_renders_the_same_bytes():
    s = changed_scene()
    again = roundtrip(s)
    remade = tsis.Scene(**s.options())
    assert again.options() == s.options() == remade.options()
    assert again.material == s.material and again.lights == s.lights
    assert again.camera == s.camera
    r = tsis.Renderer()
    want = r.render(s, method="tsis", samples=64, **SMALL).image
    for other in (again, remade, copy.copy(s), copy.deepcopy(s)):
        assert np.array_equal(r.render(other, method="tsis", samples=64, **SMALL).image, want)


def test_a_scene_from_arrays_pickles_with_its_arrays():
    v, t = tetrahedron()
    s = tsis.Scene.from_arrays(v, t, size_mm=5, material="marble")
    s.camera = tsis.Camera(eye=(0, 1, 12))
    again = roundtrip(s)
    assert again.mesh_name == "arrays" and again.triangle_count == 4
    assert again.options() == s.options() and "mesh" not in s.options()
    a, b = (tsis.render(x, **SMALL) for x in (s, again))
    assert np.array_equal(a.image, b.image) and np.array_equal(a.radiance, b.radiance)


def test_a_frame_is_a_class_that_pickles():
    f = tsis.render(tsis.Scene(mesh="builtin:sphere"), method="tsis", samples=64, **SMALL)
    assert isinstance(f, tsis.Frame)
    assert repr(f).startswith("<tsis.Frame 40×32 tsis, lavg ") and " ms>" in repr(f)
    g = roundtrip(f)
    for name in ("image", "radiance", "radiosity", "position", "normal", "coverage",
                 "flux_atlas"):
        assert np.array_equal(getattr(g, name), getattr(f, name), equal_nan=True), name
        assert getattr(g, name).dtype == getattr(f, name).dtype
    assert g.lavg == f.lavg and g.stats == f.stats
    assert repr(tsis.Renderer(gl="osmesa")) == "tsis.Renderer(cl_device='', gl='osmesa')"


# --- threads -------------------------------------------------------------


def test_two_renderers_on_two_threads_render_at_once():
    scenes = [tsis.Scene(mesh="builtin:sphere", material=m) for m in ("skin1", "marble")]
    renderers = [tsis.Renderer(), tsis.Renderer()]
    opts = dict(method="volumetric", spp=16, **SMALL)
    for r, s in zip(renderers, scenes):
        r.render(s, **opts)  # programs built, light maps made

    def frames(k):
        return [renderers[k].render(scenes[k], **opts).image for _ in range(3)]

    t = time.perf_counter()
    serial = [frames(0), frames(1)]
    serial_s = time.perf_counter() - t
    threaded = [None, None]
    threads = [threading.Thread(target=lambda k=k: threaded.__setitem__(k, frames(k)))
               for k in (0, 1)]
    t = time.perf_counter()
    [x.start() for x in threads]
    [x.join() for x in threads]
    threaded_s = time.perf_counter() - t
    print(f"two renderers: one after another {serial_s:.2f} s, two threads {threaded_s:.2f} s "
          f"({threaded_s / serial_s:.2f}×)")
    for k in (0, 1):
        assert threaded[k] is not None and len(threaded[k]) == 3
        assert all(np.array_equal(a, b) for a, b in zip(threaded[k], serial[k]))


# --- stubs ---------------------------------------------------------------


def test_stub_covers_the_module():
    stub = pathlib.Path(__file__).resolve().parents[1] / "tsis" / "__init__.pyi"
    tree = ast.parse(stub.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            top.update(t.id for t in targets if isinstance(t, ast.Name))
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name if hasattr(n, "name") else n.target.id
                                  for n in node.body if isinstance(n, (ast.FunctionDef,
                                                                       ast.AnnAssign))}
    public = {n for n in dir(tsis) if not n.startswith("_") and not isinstance(
        getattr(tsis, n), type(tsis))}  # submodules have their own sources
    assert public - top == set()
    for name, names in members.items():
        cls = getattr(tsis, name)
        if issubclass(cls, BaseException):
            continue
        own = {n for n in vars(cls) if not n.startswith("_")}
        assert own - names == set(), name


# --- the package ---------------------------------------------------------


def test_the_package_reexports_the_extension_and_writes_images(tmp_path):
    import tsis._tsis as ext
    assert tsis.Scene is ext.Scene and tsis.distributed.__name__ == "tsis.distributed"
    assert {n for n in dir(ext) if not n.startswith("_")} <= set(tsis.__all__)
    assert pickle.loads(pickle.dumps(tsis.Camera(eye=(1, 2, 3)))) == tsis.Camera(eye=(1, 2, 3))
    f = tsis.render(tsis.Scene(mesh="builtin:sphere"), **SMALL)
    tsis.write_image(tmp_path / "f.png", f.image)
    tsis.write_image(str(tmp_path / "f.exr"), f.radiance)
    assert np.array_equal(np.round(tsis.read_image(tmp_path / "f.png") * 255), f.image)
    assert np.array_equal(tsis.read_image(tmp_path / "f.exr"), f.radiance)
    with pytest.raises(tsis.Error, match=r"H×W×3 uint8 array, got shape \(32, 40\)"):
        tsis.write_image(tmp_path / "g.png", f.image[..., 0])


# --- scenes of several objects --------------------------------------------

OBJECT_SCENE = dict(size_mm="file", light=["dir:0,0,-1:1,1,1"], eye=(0, 0, 12))
OBJECT_FRAME = dict(width=64, height=32, atlas_res=256, light_res=256)


def two_spheres(right="skin1"):
    return [tsis.Object(mesh="builtin:sphere", transform=tsis.Transform(translate_mm=(-3, 0, 0)),
                        material=tsis.Material.preset("marble")),
            tsis.Object(mesh="builtin:sphere",
                        transform=tsis.Transform(scale=1.5, rotate_deg=(0, 90, 0),
                                                 translate_mm=(3, 0, 0)),
                        material=tsis.Material.preset(right))]


def side_mean(f, x, sign):
    """The mean red radiance of the covered pixels on one side of x (mm)."""
    on = (f.coverage[..., 0] > 0.5) & (sign * (f.position[..., 0] - x) > 0)
    return float(f.radiance[..., 0][on].mean()), int(on.sum())


def test_objects_and_transforms_are_values():
    t = tsis.Transform(scale=1.5, rotate_deg=(0, 90, 0), translate_mm=(3, 0, 0))
    assert t.scale == 1.5 and t.rotate_deg == [0, 90, 0] and t.translate_mm == [3, 0, 0]
    assert tsis.Transform() == tsis.Transform(scale=1, rotate_deg=(0, 0, 0),
                                              translate_mm=(0, 0, 0))
    o = two_spheres()[1]
    assert o.mesh == "builtin:sphere" and o.vertices is None and o.triangles is None
    assert o.transform == t and o.material == tsis.Material.preset("skin1")
    textured = tsis.Material(albedo=(0.9, 0.9, 0.9), mfp_mm=(0.5, 0.5, 0.5),
                             albedo_texture=pathlib.Path("halves.png"))
    assert textured.albedo_texture == "halves.png"
    for x in (t, o, tsis.Object(mesh="builtin:cube"), textured):
        again = eval(repr(x), vars(tsis))
        assert again == x and roundtrip(x) == x and copy.deepcopy(x) == x
        with pytest.raises(TypeError):
            hash(x)
    assert o != tsis.Object(mesh="builtin:sphere", transform=t)  # no material
    textured.albedo_texture = ""
    assert textured == tsis.Material(albedo=(0.9, 0.9, 0.9), mfp_mm=(0.5, 0.5, 0.5))


def test_an_object_of_numpy_arrays_is_checked_as_from_arrays_checks():
    v, t = tetrahedron()
    o = tsis.Object(vertices=v, triangles=t.astype(np.uint16))
    assert o.mesh is None and o.vertices.dtype == np.float32 and o.triangles.dtype == np.uint32
    assert np.array_equal(o.vertices, v) and np.array_equal(o.triangles, t)
    assert o == tsis.Object(vertices=v.tolist(), triangles=t.tolist()) and roundtrip(o) == o
    assert repr(o).startswith("<tsis.Object: 4 vertices, 4 triangles, transform=Transform(")
    with pytest.raises(tsis.Error, match=r"vertices: expected an N×3 array, got shape \(4, 2\)"):
        tsis.Object(vertices=v[:, :2], triangles=t)
    with pytest.raises(tsis.Error, match="triangles: triangle 0 has index -2, outside"):
        tsis.Object(vertices=v, triangles=-t)
    with pytest.raises(tsis.Error, match=r"vertex 1 has nan"):
        o.vertices = np.where(np.arange(12).reshape(4, 3) == 4, np.nan, v)
    s = tsis.Scene.from_objects([o], material="marble")
    assert s.triangle_count == 4 and s.objects == [o]
    assert np.array_equal(tsis.render(s, **SMALL).image,
                          tsis.render(tsis.Scene.from_arrays(v, t, material="marble"),
                                      **SMALL).image)


def test_two_objects_scatter_in_their_own_materials():
    same = tsis.Scene.from_objects(two_spheres("marble"), **OBJECT_SCENE)
    other = tsis.Scene.from_objects(two_spheres("ketchup"), **OBJECT_SCENE)
    assert len(other.objects) == 2 and other.objects[1].material.name == "ketchup"
    assert len(other.materials) == 2 and "2 objects" in repr(other)
    r = tsis.Renderer()
    a, b = (r.render(s, **OBJECT_FRAME) for s in (same, other))
    (left_a, n_left), (left_b, n_left_b) = side_mean(a, -1.5, -1), side_mean(b, -1.5, -1)
    (right_a, n_right), (right_b, n_right_b) = side_mean(a, 1.0, 1), side_mean(b, 1.0, 1)
    print(f"left {left_a:.5f} / {left_b:.5f} ({n_left} px), "
          f"right {right_a:.5f} / {right_b:.5f} ({n_right} px)")
    assert n_left > 20 and n_right > 2 * n_left  # 1.5× the radius
    assert (n_left_b, n_right_b) == (n_left, n_right)
    assert left_b == pytest.approx(left_a, rel=0.03)  # the left one's pixels unchanged
    assert abs(right_b / right_a - 1) > 0.1


def test_object_errors_name_the_object():
    bad = two_spheres()
    bad[1].transform.scale = -1
    with pytest.raises(tsis.Error, match=r"^object 1 \(builtin:sphere\): scale -1 must be "
                                         r"positive$"):
        tsis.Scene.from_objects(bad)
    v, t = tetrahedron()
    bad[1] = tsis.Object(mesh="builtin:sphere", vertices=v, triangles=t)
    with pytest.raises(tsis.Error, match="^object 1: a mesh file and arrays: give one$"):
        tsis.Scene.from_objects(bad)
    with pytest.raises(tsis.Error, match="at least one object"):
        tsis.Scene.from_objects([])
    with pytest.raises(tsis.Error, match="object 1 is a str, not a tsis.Object"):
        tsis.Scene.from_objects([two_spheres()[0], "builtin:sphere"])
    with pytest.raises(tsis.Error, match="--mesh: the objects are the mesh"):
        tsis.Scene.from_objects(two_spheres(), mesh="builtin:cube")


def test_a_scene_of_objects_pickles_with_its_objects_and_renders_the_same_bytes():
    s = tsis.Scene.from_objects(two_spheres(), **OBJECT_SCENE)
    s.camera = tsis.Camera(eye=(0, 1, 14), fov=33)
    again = roundtrip(s)
    assert again.objects == s.objects and again.options() == s.options()
    assert tsis.Scene(mesh="builtin:sphere").objects == []
    r = tsis.Renderer()
    a, b, c = (r.render(x, **OBJECT_FRAME) for x in (s, again, copy.copy(s)))
    assert np.array_equal(a.image, b.image) and np.array_equal(a.radiance, b.radiance)
    assert np.array_equal(a.image, c.image)


# --- typed render settings -------------------------------------------------


def stub_annotations(cls_name):
    stub = pathlib.Path(__file__).resolve().parents[1] / "tsis" / "__init__.pyi"
    for node in ast.parse(stub.read_text()).body:
        if isinstance(node, ast.ClassDef) and node.name == cls_name:
            return {n.target.id: ast.unparse(n.annotation) for n in node.body
                    if isinstance(n, ast.AnnAssign)}
    raise AssertionError(cls_name + " not in the stub")


def test_render_settings_have_a_typed_property_per_option():
    typed = stub_annotations("RenderSettings")
    s = tsis.RenderSettings()
    names = {n for n in vars(tsis.RenderSettings) if not n.startswith("_")}
    assert names == set(typed)  # every option of the table, no other
    for name in names:
        value = getattr(s, name)
        assert type(value).__name__ in typed[name], (name, value, typed[name])
        assert getattr(tsis.RenderSettings, name).__doc__, name
    # Each option's help names what it does and its default.
    assert "default 16" in tsis.RenderSettings.mis_distance.__doc__


def test_render_settings_set_read_back_and_refuse_as_the_options_do():
    s = tsis.RenderSettings(method="mis", mis_distance=np.int64(8), exposure=np.float32(2.5),
                            tone="aces", no_specular=True, roughness="file")
    assert (s.method, s.mis_distance, s.exposure, s.tone, s.no_specular, s.roughness) == (
        "mis", 8, 2.5, "aces", True, "file")
    s.roughness = 0.5
    assert s.roughness == 0.5
    assert pickle.loads(pickle.dumps(s)) == s and copy.copy(s) == s
    assert eval(repr(s), {"tsis": tsis}) == s
    assert s != tsis.RenderSettings(method="mis")
    for bad, message in [(dict(width=-3), r"--width -3 is out of range \[1, 8192\]"),
                         (dict(no_specular=1), "is a flag: true or false, not '1'"),
                         (dict(tone="agx"), "agx"),
                         (dict(method="nope"), "unknown method 'nope'"),
                         (dict(mesh="builtin:plane"),
                          "RenderSettings: option --mesh is the scene's: set it on the Scene"),
                         (dict(wdth=3), "unknown option '--wdth'"),
                         (dict(width=[1, 2]), "expected a str, number or bool, not list")]:
        with pytest.raises(tsis.Error, match=message):
            tsis.RenderSettings(**bad)
    before = copy.copy(s)
    with pytest.raises(tsis.Error):
        s.width = 0
    assert s == before  # an error keeps the field


def test_a_frame_from_settings_is_the_frame_from_the_same_keywords():
    scene = tsis.Scene(mesh="builtin:sphere")
    kw = dict(method="tsis", samples=64, width=40, height=32, atlas_res=128, light_res=256,
              tone="aces", exposure=2.5)
    s = tsis.RenderSettings(**kw)
    r = tsis.Renderer()
    by_settings, by_keywords = r.render(scene, s), r.render(scene, **kw)
    assert np.array_equal(by_settings.image, by_keywords.image)
    assert np.array_equal(by_settings.radiance, by_keywords.radiance)
    # Keywords go on top of the settings, the settings unchanged.
    darker = r.render(scene, s, exposure=0)
    assert darker.image.mean() < by_settings.image.mean() and s.exposure == 2.5
    with pytest.raises(tsis.Error, match="option --mesh is the scene's"):
        r.render(scene, s, mesh="builtin:plane")
    s.method = "pyramid"  # samples is not pyramid's: there it would do nothing
    with pytest.raises(tsis.Error, match="--samples is a parameter of .*, not of pyramid"):
        r.render(scene, s)
    with pytest.raises(tsis.Error, match="settings must be a tsis.RenderSettings, not dict"):
        r.render(scene, kw)
    assert scene.render_settings == tsis.RenderSettings()

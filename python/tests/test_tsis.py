"""`import tsis`: scenes from options and arrays, frames as numpy arrays, the
CLI's errors as tsis.Error (run by CTest as python.tests)."""
import math

import numpy as np
import pytest

import tsis

SMALL = dict(width=40, height=32, atlas_res=128, light_res=256)


def tetrahedron():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int64)
    return v, t


def test_scene_from_options_has_the_presets_and_default_lights():
    s = tsis.Scene(mesh="builtin:sphere", material="marble", size_mm=20)
    assert s.material.name == "marble"
    assert s.material.eta == pytest.approx(1.5)
    assert len(s.lights) == 2 and s.lights[1].directional
    assert s.camera.fov == 35
    assert "skin1" in tsis.preset_materials()


def test_scene_from_numpy_arrays():
    v, t = tetrahedron()
    s = tsis.Scene.from_arrays(v, t, size_mm=5)
    assert s.triangle_count == 4 and s.vertex_count >= 4  # the atlas may split vertices
    with pytest.raises(tsis.Error, match="triangle 0 uses vertex 9"):
        tsis.Scene.from_arrays(v, np.array([[0, 1, 9]]))
    with pytest.raises(tsis.Error, match="N×3"):
        tsis.Scene.from_arrays(v.ravel(), t)
    f = tsis.render(s, **SMALL)
    assert (f.coverage > 0.5).any() and f.stats["mesh"] == "arrays"


def test_errors_are_the_clis_one_line():
    with pytest.raises(tsis.Error) as e:
        tsis.render(tsis.Scene(mesh="builtin:sphere"), method="tsis", samples=0)
    assert str(e.value) == "--samples 0 is out of range [1, 4194304]"
    with pytest.raises(tsis.Error, match="unknown option '--nope' for 'tsis render'"):
        tsis.Scene(nope=1)
    s = tsis.Scene(mesh="builtin:sphere")
    with pytest.raises(tsis.Error, match="negative intensity"):
        s.lights = [tsis.Light(position=(0, 10, 0), rgb=(-1, 1, 1))]
    assert len(s.lights) == 2  # kept


def test_render_returns_arrays_and_stats():
    s = tsis.Scene(mesh="builtin:sphere", material="skin1")
    s.lights = [tsis.Light(position=(0, 12, 6), rgb=(150, 150, 150))]
    s.camera = tsis.Camera(eye=(0, 0, 25))
    f = tsis.render(s, method="tsis", samples=64, **SMALL)
    assert f.image.shape == (32, 40, 3) and f.image.dtype == np.uint8
    assert f.radiance.shape == (32, 40, 3) and f.radiance.dtype == np.float32
    assert f.radiosity.shape == (32, 40, 3)
    assert f.coverage.shape == (32, 40, 1)
    assert f.flux_atlas.shape[:2] == (128, 128)
    covered = f.coverage[..., 0] > 0.5
    assert covered.any() and (f.radiance[covered] > 0).any()
    assert f.stats["material"] == "skin1" and "ms" in f.stats
    assert f.lavg > 0


def test_gl_platforms_give_the_same_frame():
    s = tsis.Scene(mesh="builtin:sphere")
    frames = {gl: tsis.Renderer(gl=gl).render(s, **SMALL) for gl in ("egl", "osmesa")}
    assert frames["egl"].stats["gl_platform"].startswith("egl-")
    assert frames["osmesa"].stats["gl_platform"] == "osmesa"
    assert np.array_equal(frames["egl"].image, frames["osmesa"].image)
    with pytest.raises(tsis.Error, match="--gl vulkan"):
        tsis.Renderer(gl="vulkan")


def test_material_changes_the_frame_and_compare_measures_it():
    r = tsis.Renderer()
    s = tsis.Scene(mesh="builtin:sphere")
    a = r.render(s, **SMALL)
    m = s.material
    m.sigma_a = [x * 4 for x in m.sigma_a]
    s.material = m
    b = r.render(s, **SMALL)
    same = tsis.compare(a.radiance, a.radiance, a.coverage)
    assert same["rmse"] == 0 and math.isinf(same["psnr"])
    diff = tsis.compare(b.radiance, a.radiance, mask=a.coverage)
    assert diff["rel_rmse"] > 0.01 and diff["pixels"] == int((a.coverage > 0.5).sum())
    with pytest.raises(tsis.Error):
        tsis.compare(a.radiance, a.coverage)

"""The library under misuse (README "Python", threads, fork and Ctrl-C): one
Renderer from several threads, fork() after a renderer was made, SIGINT during
a long frame, and arrays and values that must be refused before anything is
copied. What may crash or hang runs in a child interpreter with a timeout."""
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import threading

import numpy as np
import pytest

import tsis

SMALL = dict(width=40, height=32, atlas_res=128, light_res=256)


def run_child(code, timeout=120):
    """Runs `code` in a fresh interpreter; its last stdout line as JSON."""
    prelude = "import json, os, signal, sys, threading, time\nimport numpy as np\nimport tsis\n"
    prelude += f"SMALL = {SMALL!r}\n"
    with tempfile.TemporaryDirectory() as d:
        script = os.path.join(d, "child.py")  # a file: multiprocessing's spawn imports it
        with open(script, "w") as f:
            f.write(prelude + textwrap.dedent(code))
        p = subprocess.run([sys.executable, script], capture_output=True, text=True,
                           timeout=timeout)
    assert p.returncode == 0, f"exit {p.returncode}: {p.stderr[-2000:]}"
    return json.loads(p.stdout.strip().splitlines()[-1])


# --- threads -------------------------------------------------------------


@pytest.mark.parametrize("gl", ["osmesa", "egl"])
def test_one_renderer_from_two_threads_serialises_its_frames(gl):
    # Before: OSMesa aborted or segfaulted, EGL failed with "eglMakeCurrent
    # failed (EGL error 0x3002)" on the second thread.
    out = run_child(f"""
        r = tsis.Renderer(gl={gl!r})
        scenes = [tsis.Scene(mesh="builtin:sphere", material=m) for m in ("skin1", "marble")]
        refs = [r.render(s, **SMALL).image for s in scenes]
        same, errors = [], []
        def work(k):
            try:
                for _ in range(6):
                    same.append(bool(np.array_equal(r.render(scenes[k], **SMALL).image, refs[k])))
            except Exception as e:
                errors.append(repr(e))
        ts = [threading.Thread(target=work, args=(k,)) for k in (0, 1)]
        [t.start() for t in ts]
        [t.join() for t in ts]
        # Made on a thread that is gone, used from this one.
        made = []
        t = threading.Thread(target=lambda: made.append(tsis.Renderer(gl={gl!r})))
        t.start(); t.join()
        other = bool(np.array_equal(made[0].render(scenes[0], **SMALL).image, refs[0]))
        print(json.dumps(dict(same=same, errors=errors, other=other)))
    """)
    assert out["errors"] == []
    assert out["same"] == [True] * 12
    assert out["other"]


def test_a_frame_releases_the_gil():
    # Python runs on other threads while a frame renders: a counter there
    # moves. With the GIL held through the frame it would stay near 0.
    r = tsis.Renderer()
    s = tsis.Scene(mesh="builtin:sphere")
    r.render(s, **SMALL)
    count, done = [0], threading.Event()

    def spin():
        while not done.is_set():
            count[0] += 1

    t = threading.Thread(target=spin)
    t.start()
    try:
        before = count[0]
        r.render(s, method="volumetric", spp=4, **SMALL)
        during = count[0] - before
    finally:
        done.set()
        t.join()
    assert during > 10000


# --- fork ----------------------------------------------------------------


def test_fork_after_a_renderer_refuses_at_once_in_the_child():
    # Before: every render in the child (same, shared or new Renderer) hung.
    out = run_child("""
        r = tsis.Renderer()
        s = tsis.Scene(mesh="builtin:sphere")
        r.render(s, **SMALL)
        tsis.render(s, **SMALL)
        rd, wr = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(rd)
            said, t = {}, time.time()
            for name, f in [("same", lambda: r.render(s, **SMALL)),
                            ("shared", lambda: tsis.render(s, **SMALL)),
                            ("new", lambda: tsis.Renderer())]:
                try:
                    f()
                    said[name] = "rendered"
                except tsis.Error as e:
                    said[name] = str(e)
            said["seconds"] = time.time() - t
            del r  # the child's copy is leaked, not freed
            os.write(wr, json.dumps(said).encode())
            os.close(wr)
            sys.exit(0)  # through the interpreter's teardown: must not hang
        os.close(wr)
        said = json.loads(os.read(rd, 65536).decode())
        _, status = os.waitpid(pid, 0)
        said["status"] = status
        said["parent_again"] = bool(r.render(s, **SMALL).image.any())
        print(json.dumps(said))
    """, timeout=60)
    assert out["status"] == 0
    assert out["seconds"] < 5
    assert "forked child" in out["same"] and "spawn" in out["same"]
    assert "forked child" in out["shared"]
    assert "child forked after one was made" in out["new"] and "'spawn'" in out["new"]
    assert out["parent_again"]


@pytest.mark.parametrize("parent_renders", [False, True])
def test_multiprocessing_children_render(parent_renders):
    # Forked before any renderer (multiprocessing's default on Linux), or
    # spawned after one: the child's own renderer works.
    out = run_child(f"""
        import multiprocessing as mp

        def child(q):
            f = tsis.Renderer().render(tsis.Scene(mesh="builtin:sphere"), **SMALL)
            q.put(float(f.image.mean()))

        if __name__ == "__main__":
            s = tsis.Scene(mesh="builtin:sphere")
            mean = None
            if {parent_renders!r}:
                mean = float(tsis.Renderer().render(s, **SMALL).image.mean())
            ctx = mp.get_context("spawn" if {parent_renders!r} else "fork")
            q = ctx.Queue()
            p = ctx.Process(target=child, args=(q,))
            p.start()
            got = q.get(timeout=60)
            p.join(30)
            print(json.dumps(dict(got=got, mean=mean, code=p.exitcode)))
    """, timeout=120)
    assert out["code"] == 0 and out["got"] > 0
    if parent_renders:
        assert out["got"] == out["mean"]


# --- Ctrl-C --------------------------------------------------------------


@pytest.mark.parametrize("long", [
    dict(method="volumetric", time=60),
    dict(method="volumetric", time=60, estimator="light"),
    dict(method="reference", spacing=0.01, force=True),
])
def test_sigint_during_a_long_frame_raises_keyboard_interrupt_and_the_renderer_stays_usable(long):
    # Before: ignored for the whole frame (≥ 40 s).
    out = run_child(f"""
        r = tsis.Renderer()
        s = tsis.Scene(mesh="builtin:sphere")
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        t = time.time()
        try:
            r.render(s, **dict(SMALL, width=32, height=32), **{long!r})
            what = "finished"
        except KeyboardInterrupt:
            what = "KeyboardInterrupt"
        seconds = time.time() - t
        # The frame after: the same as a fresh renderer's, for two methods.
        same = [bool(np.array_equal(r.render(s, method=m, **SMALL).image,
                                    tsis.Renderer().render(s, method=m, **SMALL).image))
                for m in ("tsis", "volumetric")]
        print(json.dumps(dict(what=what, seconds=seconds, same=same)))
    """, timeout=100)
    assert out["what"] == "KeyboardInterrupt"
    assert out["seconds"] < 2.5
    assert out["same"] == [True, True]


def test_a_signal_handler_that_does_not_raise_lets_the_frame_finish():
    out = run_child("""
        seen = []
        signal.signal(signal.SIGINT, lambda *a: seen.append(1))
        threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        f = tsis.render(tsis.Scene(mesh="builtin:sphere"), method="volumetric", spp=64,
                        **dict(SMALL, width=24, height=24))
        print(json.dumps(dict(seen=len(seen), spp=f.stats["volumetric_spp"])))
    """, timeout=100)
    assert out == dict(seen=1, spp=64)


# --- sizes and values from Python ----------------------------------------


def tetrahedron():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int64)
    return v, t


@pytest.mark.parametrize("triangles, message", [
    (np.array([[0, 2, 1], [0, 1, 2**32 + 2]], dtype=np.int64), "index 4294967298, outside"),
    (np.array([[0, 2, 1], [0, 1, 2**40]], dtype=np.uint64), "index 1099511627776, outside"),
    (np.array([[0, -1, 1]], dtype=np.int32), "index -1, outside"),
    (np.array([[0, 2.7, 1]]), "index 2.7, not an integer"),
    (np.array([[0, np.nan, 1]]), "index nan, not an integer"),
    (np.array([[0, 1e300, 1]]), r"index 1e\+300, outside"),
    (np.array([[0, 1, 9]], dtype=np.uint8), "triangle 0 uses vertex 9"),
    (np.array([[True, False, True]]), "expected integer vertex indices, got dtype bool"),
    (np.array([["0", "1", "2"]]), "expected integer vertex indices, got dtype <U1"),
    (np.array([[0, 1, 2, 3]]), r"an M×3 array, got shape \(1, 4\)"),
    (np.arange(3), r"an M×3 array, got shape \(3,\)"),
    ("012", r"got shape \(\)"),
])
def test_triangle_indices_are_refused_naming_the_value(triangles, message):
    v, _ = tetrahedron()
    with pytest.raises(tsis.Error, match=message):
        tsis.Scene.from_arrays(v, triangles)


@pytest.mark.parametrize("bad, message", [
    (np.nan, "vertex 2 has nan"),
    (np.inf, "vertex 2 has inf"),
    (-1e300, "vertex 2 has -1e[+]300"),
])
def test_vertices_must_be_finite(bad, message):
    v, t = tetrahedron()
    v[2, 1] = bad
    with pytest.raises(tsis.Error, match=message):
        tsis.Scene.from_arrays(v, t)


def test_arrays_of_every_integer_and_float_kind_and_lists_are_accepted():
    v, t = tetrahedron()
    counts = set()
    for tv in (v, v.astype(np.float32), v.astype(np.int16), v.tolist()):
        for tt in (t, t.astype(np.uint32), t.astype(np.uint64), t.astype(np.float64), t.tolist()):
            counts.add(tsis.Scene.from_arrays(tv, tt, size_mm=5).triangle_count)
    assert counts == {4}
    with pytest.raises(tsis.Error, match="vertices: expected real numbers, got dtype complex"):
        tsis.Scene.from_arrays(v.astype(np.complex128), t)
    with pytest.raises(tsis.Error, match="vertices: not an array"):
        tsis.Scene.from_arrays([[0, 0], [1]], t)


@pytest.mark.parametrize("shape, message", [
    ((100000, 100000, 3), "past compare's limits"),   # 120 GB as float32 if copied
    ((8193, 8193), "past compare's limits"),
    ((70000, 2), "past compare's limits"),
    ((4, 4, 5), "past compare's limits"),
    ((4, 4, 0), "past compare's limits"),
    ((16,), r"H×W or H×W×C array, got shape \(16,\)"),
    ((2, 2, 2, 2), "H×W or H×W×C array"),
])
def test_compare_refuses_arrays_past_its_stated_limits_before_copying(shape, message):
    huge = np.broadcast_to(np.float64(0), shape)  # no memory behind it
    with pytest.raises(tsis.Error, match="image: .*" + message):
        tsis.compare(huge, np.zeros((4, 4, 3), np.float32))
    with pytest.raises(tsis.Error, match="mask: .*" + message):
        tsis.compare(np.zeros((4, 4, 3)), np.zeros((4, 4, 3)), mask=huge)


def test_compare_takes_any_real_dtype_and_refuses_others():
    a = np.arange(48, dtype=np.float64).reshape(4, 4, 3) + 1
    for b in (a, a.astype(np.float32), a.astype(np.int32), a.astype(np.uint16), a.tolist()):
        assert tsis.compare(a, b)["rmse"] == 0
    with pytest.raises(tsis.Error, match="reference: expected real numbers, got dtype bool"):
        tsis.compare(a, a > 3)


def test_numpy_scalars_are_accepted_where_python_numbers_are():
    s = tsis.Scene(mesh="builtin:sphere", size_mm=np.float32(10), atlas_res=np.int64(128))
    a = tsis.render(s, width=np.int64(40), height=np.int32(32), light_res=np.uint16(256),
                    atlas_res=np.int64(128), no_specular=np.bool_(True))
    b = tsis.render(s, width=40, height=32, light_res=256, atlas_res=128, no_specular=True)
    assert a.image.shape == (32, 40, 3)
    assert np.array_equal(a.image, b.image)
    # An integer is written exactly, not through a double.
    with pytest.raises(tsis.Error, match="--width 9007199254740993 "):
        tsis.render(s, width=2**53 + 1)
    with pytest.raises(tsis.Error, match="option --width: expected a str, number, bool or "
                                         "sequence, not NoneType"):
        tsis.render(s, width=None)


def test_a_scene_is_not_changed_while_another_thread_renders_it():
    import copy
    s = tsis.Scene(mesh="builtin:sphere")
    r = tsis.Renderer()
    t = threading.Thread(target=lambda: r.render(s, method="volumetric", time=3, **SMALL))
    t.start()
    refused = None
    while t.is_alive() and refused is None:
        try:
            s.camera = tsis.Camera(eye=(0, 0, 30))
        except tsis.Error as e:
            refused = str(e)
        threading.Event().wait(0.01)
    c = copy.copy(s)  # a copy is free to change meanwhile
    c.material = tsis.preset_material("marble")
    t.join()
    assert refused is not None and "being rendered on another thread" in refused
    s.camera = tsis.Camera(eye=(0, 0, 30))  # between frames
    assert s.camera.eye == [0, 0, 30] and c.material.name == "marble" and s.material.name != "marble"


def test_sigint_while_waiting_for_another_threads_frame_raises_keyboard_interrupt():
    out = run_child("""
        r = tsis.Renderer()
        s = tsis.Scene(mesh="builtin:sphere")
        other = threading.Thread(target=lambda: r.render(s, method="volumetric", time=4, **SMALL))
        other.start()
        time.sleep(0.5)  # the other thread's frame holds the renderer
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        t = time.time()
        try:
            r.render(s, **SMALL)
            what = "rendered"
        except KeyboardInterrupt:
            what = "KeyboardInterrupt"
        seconds = time.time() - t
        alive = other.is_alive()
        other.join()
        print(json.dumps(dict(what=what, seconds=seconds, alive=alive)))
    """, timeout=60)
    assert out["what"] == "KeyboardInterrupt" and out["seconds"] < 2.5
    assert out["alive"]  # it was waiting, not after the other frame

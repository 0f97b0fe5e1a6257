"""tsis.distributed: sweeps of tiny frames on two local worker processes (and
on Ray when it is installed): images and index lines, a rerun that skips what
is done, failures retried then recorded, a worker that dies replaced; a sweep on a two-node Ray cluster of this
machine."""
import json
import time

import numpy as np
import pytest

import tsis
from tsis import distributed

SCENE = dict(mesh="builtin:sphere", atlas_res=64)
RENDER = dict(method="tsis", width=24, height=24, atlas_res=64, light_res=256, samples=64)


def four_jobs():
    return distributed.grid(scene=dict(SCENE, material=["skin1", "marble"]),
                            render=dict(RENDER, samples=[32, 64]))


def index_of(out):
    with open(out / "index.jsonl") as f:
        return [json.loads(line) for line in f]


def test_grid_is_the_product_with_stable_ids():
    jobs = four_jobs()
    assert [(j["scene"]["material"], j["render"]["samples"]) for j in jobs] == [
        ("skin1", 32), ("skin1", 64), ("marble", 32), ("marble", 64)]
    assert len({j["id"] for j in jobs}) == 4 and jobs == four_jobs()
    assert jobs[0]["id"] == distributed.job_id(jobs[0]["scene"], dict(jobs[0]["render"]))
    # A tuple is one value; numpy scalars name the same job as Python's.
    (one,) = distributed.grid(scene=dict(eye=(0, 0, 25)), render=dict(samples=np.int64(64)))
    assert one["id"] == distributed.job_id({"eye": [0, 0, 25]}, {"samples": 64})
    with pytest.raises(ValueError, match="given twice"):
        distributed.sweep(jobs + jobs[:1], "unused", backend="local")
    # Typed settings name the job their options name.
    assert distributed.job_id(SCENE, tsis.RenderSettings(**RENDER)) == distributed.job_id(
        SCENE, RENDER)
    assert distributed.job_id(SCENE, tsis.RenderSettings()) == distributed.job_id(
        SCENE, {"method": "pyramid"})


def check_sweep(out, jobs, summary):
    assert summary["ok"] == 4 and summary["failed"] == 0 and summary["failed_ids"] == []
    lines = index_of(out)
    assert sorted(e["id"] for e in lines) == sorted(j["id"] for j in jobs)
    for e in lines:
        assert e["status"] == "ok" and e["error"] is None and e["attempts"] == 1
        assert e["stats"]["method"] == "tsis" and e["stats"]["width"] == 24
        assert e["seconds"] > 0 and ":" in e["worker"]
        assert tsis.read_image(out / (e["id"] + ".png")).shape == (24, 24, 3)
    # The image is the frame a Renderer here makes.
    job = jobs[3]
    here = tsis.Renderer().render(tsis.Scene(**job["scene"]), **job["render"]).image
    assert np.array_equal(np.round(tsis.read_image(out / (job["id"] + ".png")) * 255), here)
    # Run again: everything is done.
    t = time.perf_counter()
    again = distributed.sweep(jobs, out, workers=2, backend=summary["backend"])
    assert again["skipped"] == 4 and again["ok"] == 0 and len(index_of(out)) == 4
    assert time.perf_counter() - t < 2


def test_local_sweep_writes_images_and_index_and_resumes(tmp_path):
    jobs = four_jobs()
    summary = distributed.sweep(jobs, tmp_path, workers=2, backend="local")
    print(f"local sweep of 4 jobs on 2 workers: {summary['seconds']:.1f} s")
    assert summary["backend"] == "local" and summary["total"] == 4
    check_sweep(tmp_path, jobs, summary)
    # A job's render as tsis.RenderSettings: its options in the index, the same frame.
    typed = dict(jobs[3], render=tsis.RenderSettings(**jobs[3]["render"]))
    del typed["id"]
    out = tmp_path / "typed"
    assert distributed.sweep([typed], out, workers=1, backend="local")["ok"] == 1
    (entry,) = index_of(out)
    assert entry["id"] == jobs[3]["id"] and entry["render"] == jobs[3]["render"]
    assert np.array_equal(tsis.read_image(out / (entry["id"] + ".png")),
                          tsis.read_image(tmp_path / (jobs[3]["id"] + ".png")))


def test_failures_are_retried_then_recorded_and_a_dead_worker_is_replaced(tmp_path,
                                                                          monkeypatch):
    marker = tmp_path / "died"
    monkeypatch.setenv("TSIS_SWEEP_TEST_EXIT", f"dies:{marker}")
    jobs = [{"id": "good", "scene": SCENE, "render": RENDER},
            {"id": "bad", "scene": SCENE, "render": dict(RENDER, samples=0)},
            {"id": "dies", "scene": dict(SCENE, material="marble"), "render": RENDER},
            {"id": "not-scene", "scene": dict(SCENE, method="tsis"), "render": RENDER}]
    summary = distributed.sweep(jobs, tmp_path, workers=2, backend="local", retries=1)
    assert summary["ok"] == 2 and sorted(summary["failed_ids"]) == ["bad", "not-scene"]
    assert marker.exists()  # the worker did die once
    lines = {e["id"]: e for e in index_of(tmp_path)}
    assert lines["bad"]["status"] == "failed" and lines["bad"]["attempts"] == 2
    assert lines["bad"]["error"] == "--samples 0 is out of range [1, 4194304]"
    assert "is not the scene's" in lines["not-scene"]["error"]
    assert lines["dies"]["status"] == "ok" and lines["dies"]["attempts"] == 2
    assert not (tmp_path / "bad.png").exists() and (tmp_path / "dies.png").exists()
    # Run again: what failed is tried again, what is done is not.
    again = distributed.sweep(jobs, tmp_path, workers=2, backend="local", retries=0)
    assert again["skipped"] == 2 and sorted(again["failed_ids"]) == ["bad", "not-scene"]


def test_a_job_past_its_timeout_fails_and_the_next_runs(tmp_path):
    long = {k: v for k, v in RENDER.items() if k != "samples"}
    jobs = [{"id": "long", "scene": SCENE, "render": dict(long, method="volumetric", time=60)},
            {"id": "short", "scene": SCENE, "render": RENDER}]
    summary = distributed.sweep(jobs, tmp_path, workers=1, backend="local", retries=0,
                                timeout=3)
    assert summary["ok"] == 1 and summary["failed_ids"] == ["long"]
    (long,) = [e for e in index_of(tmp_path) if e["id"] == "long"]
    assert long["error"] == "no result after 3 s"


def test_ray_sweep(tmp_path, monkeypatch):
    ray = pytest.importorskip("ray")
    marker = tmp_path / "died"
    monkeypatch.setenv("TSIS_SWEEP_TEST_EXIT", f"dies:{marker}")  # before the workers start
    ray.init(num_cpus=2, include_dashboard=False)
    try:
        jobs = four_jobs()
        summary = distributed.sweep(jobs, tmp_path, workers=2, backend="ray")
        print(f"ray sweep of 4 jobs on 2 workers: {summary['seconds']:.1f} s")
        assert summary["backend"] == "ray"
        check_sweep(tmp_path, jobs, summary)
        dies = [{"id": "dies", "scene": SCENE, "render": RENDER}]
        summary = distributed.sweep(dies, tmp_path / "dies", workers=1, backend="ray")
        assert summary["ok"] == 1 and marker.exists()
        assert index_of(tmp_path / "dies")[0]["attempts"] == 2
    finally:
        ray.shutdown()


def test_render_split_gives_the_whole_frames_radiance():
    scene = tsis.Scene(**SCENE)
    opts = dict(width=24, height=24, atlas_res=64, light_res=256, aa=1)
    whole = tsis.Renderer().render(scene, method="volumetric", spp=5, **opts)
    split = distributed.render_split(scene, 5, 2, workers=2, backend="local", **opts)
    assert [b["volumetric_spp"] for b in split.stats["batches"]] == [3, 2]
    assert split.stats["volumetric_spp"] == 5 and split.image is None
    np.testing.assert_allclose(split.radiance, whole.radiance, rtol=1e-5, atol=1e-7)
    np.testing.assert_allclose(split.radiosity, whole.radiosity, rtol=1e-5, atol=1e-7)
    assert np.array_equal(split.coverage, whole.coverage)
    assert split.lavg == pytest.approx(whole.lavg, rel=1e-5)
    with pytest.raises(ValueError, match="volumetric only"):
        distributed.render_split(scene, 4, 2, method="tsis")
    with pytest.raises(ValueError, match="spp_offset is render_split's"):
        distributed.render_split(scene, 4, 2, spp_offset=3)
    with pytest.raises(tsis.Error, match="--width 0 is out of range"):
        distributed.render_split(scene, 4, 2, workers=1, backend="local", retries=0,
                                 **dict(opts, width=0))


def reread_ray_token():
    """This process's next ray.init reads RAY_AUTH_MODE and its token again (Ray
    keeps what it read first)."""
    try:
        from ray._raylet import AuthenticationTokenLoader, Config
        Config.initialize("")
        AuthenticationTokenLoader.instance().reset_cache()
    except (ImportError, AttributeError):
        pass


# After test_ray_sweep (pytest runs a file's tests in order): that one's local
# Ray is shut down before this cluster starts, and this one's is ended before
# any later test.
@pytest.fixture
def two_node_ray_cluster(tmp_path, monkeypatch):
    """A Ray cluster of two nodes of one CPU each on this machine (`ray start
    --head`, then `ray start --address=…`), its own temp dir and a fresh auth
    token; yields its address. Its processes (each `ray start` in a session of
    its own, which its daemons and workers keep) are ended at the end, and
    only they: `ray stop` would end every Ray of the machine."""
    import os
    import secrets
    import shutil
    import signal
    import socket
    import subprocess
    import sys
    import tempfile
    pytest.importorskip("ray")
    ray_exe = os.path.join(os.path.dirname(sys.executable), "ray")
    temp_dir = tempfile.mkdtemp(prefix="tsisray")  # short: Ray's socket paths go under it
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    # Ray 2.60 clusters check a token (RAY_AUTH_MODE=token): the nodes and this
    # process (the driver) get the same one, not ~/.ray's.
    token = secrets.token_hex(32)
    monkeypatch.setenv("RAY_AUTH_MODE", "token")
    monkeypatch.setenv("RAY_AUTH_TOKEN", token)
    reread_ray_token()
    env = dict(os.environ)  # PYTHONPATH too: the workers import tsis
    address = f"127.0.0.1:{port}"
    common = ["--num-cpus=1", f"--temp-dir={temp_dir}", "--disable-usage-stats"]
    sessions = []

    def start(*args):
        p = subprocess.Popen([ray_exe, "start", *args, *common], env=env, text=True,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             start_new_session=True)
        sessions.append(p.pid)
        out, _ = p.communicate(timeout=60)
        assert p.returncode == 0, out[-2000:]

    def ours():
        pids = []
        for name in os.listdir("/proc"):
            if not name.isdigit() or int(name) == os.getpid():
                continue
            try:
                with open(f"/proc/{name}/cmdline", "rb") as f:
                    cmdline = f.read()
                if os.getsid(int(name)) in sessions or temp_dir.encode() in cmdline:
                    pids.append(int(name))
            except OSError:
                pass
        return pids

    try:
        start("--head", f"--port={port}", "--include-dashboard=false")
        start(f"--address={address}")
        yield address
    finally:
        for sig in (signal.SIGTERM, signal.SIGKILL):
            for pid in ours():
                try:
                    os.kill(pid, sig)
                except OSError:
                    pass
            deadline = time.monotonic() + (2 if sig == signal.SIGTERM else 5)
            while ours() and time.monotonic() < deadline:
                time.sleep(0.2)
        left = ours()
        reread_ray_token()
        if not left:
            shutil.rmtree(temp_dir, ignore_errors=True)
        assert not left, f"processes of the test's Ray cluster left: {left}"


def test_ray_sweep_on_a_two_node_cluster(tmp_path, two_node_ray_cluster):
    import ray
    assert not ray.is_initialized()
    ray.init(address=two_node_ray_cluster)
    try:
        nodes = [n for n in ray.nodes() if n["Alive"]]
        assert len(nodes) == 2 and all(n["Resources"].get("CPU") == 1 for n in nodes)
    finally:
        ray.shutdown()
    jobs = four_jobs()
    summary = distributed.sweep(jobs, tmp_path, workers=2, backend="ray",
                                address=two_node_ray_cluster)
    print(f"ray sweep of 4 jobs on a two-node cluster: {summary['seconds']:.1f} s")
    assert summary["backend"] == "ray" and not ray.is_initialized()
    check_sweep(tmp_path, jobs, summary)
    # Both workers took jobs (each is given one at the start).
    assert len({e["worker"] for e in index_of(tmp_path)}) == 2

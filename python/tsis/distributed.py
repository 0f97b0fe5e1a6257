"""Many frames on many workers (docs/python.md "Sweeps").

    from tsis import distributed
    jobs = distributed.grid(scene={"mesh": ["builtin:sphere"], "material": ["skin1", "marble"]},
                            render={"method": ["tsis"], "samples": [256, 1024]})
    summary = distributed.sweep(jobs, "out", workers=4)

A job is a dict {"id": str (optional), "scene": {scene options}, "render":
{render options} or a tsis.RenderSettings}, the options as tsis.Scene and
tsis.Renderer.render take them (settings are written to the index as the
options that differ from the defaults). Each worker is a process with one long-lived tsis.Renderer: a Ray actor
(backend "ray") or a process of this machine started by spawning (backend
"local"; never forked: README "Threads, fork and Ctrl-C"). Each job writes
out_dir/<id>.png and one line of out_dir/index.jsonl; a job that fails (an
error, or its worker dying) is tried again, on another worker when there is
one, up to `retries` times, then recorded as failed. A sweep run again skips
the jobs the index already has as "ok". render_split renders one volumetric
frame as batches of its paths on the workers.
"""
import collections
import copy
import hashlib
import importlib.util
import itertools
import json
import multiprocessing
import multiprocessing.connection
import os
import socket
import tempfile
import time

from ._tsis import RenderSettings

__all__ = ["grid", "job_id", "render_split", "sweep"]

INDEX = "index.jsonl"


def _plain(value):
    """`value` as JSON has it: tuples as lists, numpy scalars and arrays as
    Python numbers and lists."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if hasattr(value, "tolist"):  # numpy
        return _plain(value.tolist())
    return value


def _render_options(render):
    """A job's render options as a dict: a tsis.RenderSettings as its method
    and the settings off their defaults (what it pickles as)."""
    if isinstance(render, RenderSettings):
        return render.__getstate__()
    return render or {}


def job_id(scene=None, render=None):
    """A stable name for the job of these options (render: a dict or a
    tsis.RenderSettings): the first 12 hex digits of the SHA-256 of their JSON
    (keys sorted), the same in every process and run."""
    text = json.dumps({"scene": _plain(scene or {}), "render": _plain(_render_options(render))},
                      sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def grid(scene=None, render=None):
    """The jobs of every combination of the values given: each option name maps
    to a list of values (anything but a list is the only value:
    eye=(0, 0, 25) is one)."""
    def combinations(options):
        options = options or {}
        values = [v if isinstance(v, list) else [v] for v in options.values()]
        return [dict(zip(options, combo)) for combo in itertools.product(*values)]

    return [{"id": job_id(s, r), "scene": s, "render": r}
            for s in combinations(scene) for r in combinations(render)]


def _normalised(jobs):
    out, seen = [], set()
    for job in jobs:
        extra = set(job) - {"id", "scene", "render"}
        if extra:
            raise ValueError(f"a job has keys id, scene and render, not {sorted(extra)}")
        scene = _plain(job.get("scene") or {})
        render = _plain(_render_options(job.get("render")))
        jid = str(job.get("id") or job_id(scene, render))
        if not jid or jid.startswith(".") or any(c in jid for c in "/\\\0"):
            raise ValueError(f"job id {jid!r}: not a file name")
        if jid in seen:
            raise ValueError(f"job id {jid!r} is given twice")
        seen.add(jid)
        out.append({"id": jid, "scene": scene, "render": render})
    return out


def _done_ids(out_dir):
    """The ids the index has as ok whose image is there (a line cut short by a
    crash is skipped)."""
    done = set()
    try:
        with open(os.path.join(out_dir, INDEX)) as f:
            for line in f:
                try:
                    entry = json.loads(line)
                except ValueError:
                    continue
                if entry.get("status") == "ok":
                    done.add(entry["id"])
                else:
                    done.discard(entry.get("id"))
    except FileNotFoundError:
        pass
    return {i for i in done if os.path.exists(os.path.join(out_dir, i + ".png"))}


# --- in each worker process -----------------------------------------------


class _Worker:
    """A worker's Renderer and the jobs it runs (in a local process, or as a
    Ray actor). Notes go to the index, not to warnings."""

    def __init__(self):
        import tsis
        tsis.set_quiet(True)
        self.name = f"{socket.gethostname()}:{os.getpid()}"
        self.renderer, self.error = None, None
        try:
            self.renderer = tsis.Renderer()
        except tsis.Error as e:
            self.error = f"this worker cannot render: {e}"
        self._scene_key, self._scene = None, None

    def ping(self):
        """This worker's name, once its Renderer is made (or failed)."""
        return self.name

    def run(self, job):
        """The job's result: status, error, stats, notes, seconds, worker and
        the frame as PNG bytes (the caller writes it where it belongs)."""
        import tsis
        start = time.perf_counter()
        result = {"status": "failed", "error": None, "stats": None, "notes": [], "png": None,
                  "worker": self.name}
        try:
            _test_exit(job)
            if self.error:
                raise RuntimeError(self.error)
            key = json.dumps(job["scene"], sort_keys=True)
            if key != self._scene_key:  # the same scene again: its mesh loaded once
                self._scene_key, self._scene = None, tsis.Scene(**job["scene"])
                self._scene_key = key
            frame = self.renderer.render(self._scene, **job["render"])
            with tempfile.TemporaryDirectory() as d:
                path = os.path.join(d, "frame.png")
                tsis.write_image(path, frame.image)
                with open(path, "rb") as f:
                    result["png"] = f.read()
            result.update(status="ok", stats=frame.stats, notes=list(self._scene.notes))
        except Exception as e:  # recorded, and tried again by the caller
            result["error"] = _error_text(e)
        result["seconds"] = round(time.perf_counter() - start, 3)
        return result

    def frame(self, scene, options):
        """{"status", "error", "frame"}: a tsis.Frame of `scene` (pickled as its
        options), or the error."""
        try:
            if self.error:
                raise RuntimeError(self.error)
            frame = self.renderer.render(scene, **options)
            return {"status": "ok", "error": None, "frame": frame, "worker": self.name}
        except Exception as e:
            return {"status": "failed", "error": _error_text(e), "frame": None,
                    "worker": self.name}


def _error_text(e):
    """A tsis.Error's one line as it is; another exception with its type."""
    import tsis
    return str(e) if isinstance(e, tsis.Error) else f"{type(e).__name__}: {e}"


def _test_exit(job):
    # Tests kill a worker in the middle of a job: TSIS_SWEEP_TEST_EXIT="ID:MARKER"
    # makes the first worker that takes job ID create the file MARKER and exit.
    jid, _, marker = os.environ.get("TSIS_SWEEP_TEST_EXIT", "").partition(":")
    if jid == job["id"] and marker and not os.path.exists(marker):
        open(marker, "w").close()
        os._exit(70)


def _local_worker(conn):
    """A local worker process: calls of _Worker's methods in, their results
    out, until None or the pipe closes."""
    worker = _Worker()
    try:
        while (call := conn.recv()) is not None:
            method, args = call
            conn.send(getattr(worker, method)(*args))
    except (EOFError, KeyboardInterrupt):
        pass


# --- the pools: workers by slot, their results as they come --------------


class _LocalPool:
    """Processes of this machine, started by spawning."""

    def __init__(self, workers):
        self._ctx = multiprocessing.get_context("spawn")
        self._slots = [self._spawn() for _ in range(workers)]
        for k in range(workers):  # all starting at once
            self._ready(k)

    def _spawn(self):
        conn, child = self._ctx.Pipe()
        process = self._ctx.Process(target=_local_worker, args=(child,), daemon=True,
                                    name="tsis-sweep-worker")
        process.start()
        child.close()
        return process, conn

    def _ready(self, k):
        """Waits for slot k's worker to make its Renderer (a job's time counts
        from then)."""
        process, conn = self._slots[k]
        try:
            conn.send(("ping", ()))
            conn.recv()
        except (EOFError, OSError):
            process.join(5)
            raise RuntimeError(f"a worker process did not start (exit code {process.exitcode})")

    def submit(self, k, method, args):
        try:
            self._slots[k][1].send((method, args))
        except OSError:  # died while idle: a new one takes the call
            self.restart(k)
            self._slots[k][1].send((method, args))

    def wait(self, busy, timeout):
        """[(slot, result)] of the busy slots that finished within timeout s."""
        conns = {self._slots[k][1]: k for k in busy}
        out = []
        for conn in multiprocessing.connection.wait(list(conns), timeout):
            k = conns[conn]
            try:
                out.append((k, conn.recv()))
            except (EOFError, OSError):
                out.append((k, self.restart(k)))
        return out

    def restart(self, k, why=None):
        """Ends slot k's process and starts another: the failure of its job."""
        process, conn = self._slots[k]
        process.kill()
        process.join()
        conn.close()
        self._slots[k] = self._spawn()
        self._ready(k)
        return _failure(why or f"the worker died (exit code {process.exitcode})",
                        f"{socket.gethostname()}:{process.pid}")

    def close(self):
        for process, conn in self._slots:
            try:
                conn.send(None)
            except OSError:
                pass
        for process, conn in self._slots:
            process.join(5)
            if process.is_alive():
                process.kill()
                process.join()
            conn.close()


class _RayPool:
    """Ray actors, one Renderer each, on the cluster ray.init connects to."""

    def __init__(self, workers, address):
        import ray
        self._ray = ray
        self.started_ray = not ray.is_initialized()
        if self.started_ray:
            ray.init(address=address)
        self._actor = ray.remote(_Worker)
        self._slots = [self._actor.remote() for _ in range(workers)]
        ray.get([a.ping.remote() for a in self._slots])  # a job's time counts from then
        self._refs = {}  # the running job's result → slot

    def submit(self, k, method, args):
        self._refs[getattr(self._slots[k], method).remote(*args)] = k

    def wait(self, busy, timeout):
        if not self._refs:
            return []
        done, _ = self._ray.wait(list(self._refs), num_returns=1, timeout=timeout)
        out = []
        for ref in done:
            k = self._refs.pop(ref)
            try:
                out.append((k, self._ray.get(ref)))
            except self._ray.exceptions.RayActorError as e:
                first = (str(e).strip().splitlines() or [""])[0]
                out.append((k, self.restart(k, f"the worker died ({first})")))
        return out

    def restart(self, k, why=None):
        self._refs = {r: s for r, s in self._refs.items() if s != k}
        self._ray.kill(self._slots[k], no_restart=True)
        self._slots[k] = self._actor.remote()
        self._ray.get(self._slots[k].ping.remote())
        return _failure(why or "the worker died", f"ray worker {k}")

    def close(self):
        for actor in self._slots:
            self._ray.kill(actor, no_restart=True)
        if self.started_ray:
            self._ray.shutdown()


def _failure(error, worker):
    return {"status": "failed", "error": error, "stats": None, "notes": [], "png": None,
            "worker": worker, "seconds": None}


# --- the sweep ------------------------------------------------------------


def sweep(jobs, out_dir, *, workers=2, backend="auto", retries=2, address=None, timeout=None):
    """Renders `jobs` on `workers` workers into out_dir (created): <id>.png and
    one line of index.jsonl per job: {id, scene, render, status ("ok" or
    "failed"), error, stats, attempts, seconds, worker, notes}. backend "ray"
    (address: ray.init's, an existing cluster; out_dir is written here),
    "local" (processes of this machine) or "auto" (Ray when it is installed).
    A job that fails, its worker dying included, or runs past `timeout`
    seconds, is tried again up to `retries` times. Returns {"total", "ok",
    "failed", "skipped", "failed_ids", "seconds", "backend"}."""
    backend = _backend(backend, workers, retries)
    jobs = _normalised(jobs)
    os.makedirs(out_dir, exist_ok=True)
    done = _done_ids(out_dir)
    todo = collections.deque(j for j in jobs if j["id"] not in done)
    summary = {"total": len(jobs), "ok": 0, "failed": 0, "skipped": len(jobs) - len(todo),
               "failed_ids": [], "backend": backend}
    start = time.perf_counter()
    if todo:
        with open(os.path.join(out_dir, INDEX), "a") as index:
            _schedule(backend, workers, address, [(j["id"], "run", (j,)) for j in todo],
                      retries, timeout,
                      lambda task, result, attempts: _record(index, out_dir, task[2][0], result,
                                                             attempts, summary))
    summary["seconds"] = round(time.perf_counter() - start, 3)
    return summary


def _backend(backend, workers, retries):
    if backend == "auto":
        backend = "ray" if importlib.util.find_spec("ray") else "local"
    if backend not in ("ray", "local"):
        raise ValueError(f"backend {backend!r}: 'auto', 'ray' or 'local'")
    if workers < 1 or retries < 0:
        raise ValueError("workers must be at least 1 and retries at least 0")
    return backend


def _schedule(backend, workers, address, tasks, retries, timeout, done):
    """Runs tasks (key, method of _Worker, args) on a pool of at most `workers`:
    a failed one again (on another worker when one is free) up to `retries`
    times; done(task, result, attempts) gets each task's last result."""
    slots = min(workers, len(tasks))
    pool = _RayPool(slots, address) if backend == "ray" else _LocalPool(slots)
    todo = collections.deque(tasks)
    attempts = collections.Counter()
    last_worker = {}  # key → the slot that last tried it
    running = {}  # slot → (task, when it started)
    try:
        while todo or running:
            for k in set(range(slots)) - set(running):
                if not todo:
                    break
                task = next((t for t in todo if last_worker.get(t[0]) != k), todo[0])
                todo.remove(task)
                pool.submit(k, task[1], task[2])
                running[k] = (task, time.monotonic())
            finished = pool.wait(list(running), 1.0 if timeout else None)
            if timeout:  # past its time: the worker is ended, the task fails
                now = time.monotonic()
                finished += [(k, pool.restart(k, f"no result after {timeout} s"))
                             for k, (_, t) in running.items() if now - t > timeout
                             and k not in {f[0] for f in finished}]
            for k, result in finished:
                task, _ = running.pop(k)
                attempts[task[0]] += 1
                last_worker[task[0]] = k
                if result["status"] != "ok" and attempts[task[0]] <= retries:
                    todo.append(task)
                else:
                    done(task, result, attempts[task[0]])
    finally:
        pool.close()


def _record(index, out_dir, job, result, attempts, summary):
    """Writes the job's image (whole, or not at all) and then its index line."""
    if result["status"] == "ok":
        path = os.path.join(out_dir, job["id"] + ".png")
        with open(path + ".part", "wb") as f:
            f.write(result["png"])
        os.replace(path + ".part", path)
        summary["ok"] += 1
    else:
        summary["failed"] += 1
        summary["failed_ids"].append(job["id"])
    entry = dict(job, status=result["status"], error=result["error"], stats=result["stats"],
                 attempts=attempts, seconds=result["seconds"], worker=result["worker"],
                 notes=result["notes"])
    index.write(json.dumps(entry) + "\n")
    index.flush()


# --- one frame in batches --------------------------------------------------


def render_split(scene, spp, batches, workers=2, *, backend="auto", retries=2, address=None,
                 **render_options):
    """The volumetric frame of `scene` with `spp` paths per pixel, rendered as
    `batches` batches (--spp-offset 0, n, 2n, …) on `workers` workers and
    combined: radiance and radiosity are the batches' spp-weighted means (the
    whole frame's, to float rounding); position, normal, coverage and
    flux_atlas the first batch's; lavg recomputed from the radiance (over the
    pixels: the renderer's own with aa=1, not over --aa's samples); stats the
    first batch's with the whole spp and each batch's under "batches". image
    is None: the tone curve runs on the GPU over the frame's samples, and a
    mean of tone-mapped batches is not the frame's. A batch that fails is
    tried again up to `retries` times, then its tsis.Error is raised."""
    import numpy as np
    import tsis
    if render_options.get("method", "volumetric") != "volumetric":
        raise ValueError("render_split renders method volumetric only")
    for name in ("spp_offset", "time"):
        if name in render_options:
            raise ValueError(f"render_split: {name} is render_split's to set")
    if not 1 <= batches <= spp:
        raise ValueError(f"batches {batches}: between 1 and spp ({spp})")
    backend = _backend(backend, workers, retries)
    sizes = [spp // batches + (i < spp % batches) for i in range(batches)]
    tasks = [(i, "frame", (scene, dict(render_options, method="volumetric", spp=n,
                                       spp_offset=sum(sizes[:i]))))
             for i, n in enumerate(sizes)]
    results = {}
    _schedule(backend, workers, address, tasks, retries, None,
              lambda task, result, attempts: results.__setitem__(task[0], result))
    failed = [r["error"] for r in results.values() if r["status"] != "ok"]
    if failed:
        raise tsis.Error(failed[0])
    frames = [results[i]["frame"] for i in range(batches)]
    out = copy.copy(frames[0])
    weights = np.asarray(sizes, np.float64) / spp
    for name in ("radiance", "radiosity"):
        mean = sum(w * getattr(f, name).astype(np.float64) for w, f in zip(weights, frames))
        setattr(out, name, mean.astype(np.float32))
    # Reinhard's log-average over the covered pixels (Rec. 709 luminance), as
    # the renderer's own.
    covered = out.coverage[..., 0] > 0
    y = out.radiance[covered].astype(np.float64) @ np.array([0.2126, 0.7152, 0.0722])
    out.lavg = float(np.exp(np.log(1e-12 + np.maximum(y, 0)).mean())) if y.size else 1.0
    out.image = None
    out.stats = dict(frames[0].stats, volumetric_spp=spp,
                     batches=[dict(f.stats, worker=results[i]["worker"])
                              for i, f in enumerate(frames)])
    return out

"""Many frames on many workers (docs/python.md "Sweeps").

    from tsis import distributed
    jobs = distributed.grid(scene={"mesh": ["builtin:sphere"], "material": ["skin1", "marble"]},
                            render={"method": ["tsis"], "samples": [256, 1024]})
    summary = distributed.sweep(jobs, "out", workers=4)

A job is a dict {"id": str (optional), "scene": {scene options}, "render":
{render options}}, the options as tsis.Scene and tsis.Renderer.render take
them. Each worker is a process with one long-lived tsis.Renderer: a Ray actor
(backend "ray") or a process of this machine started by spawning (backend
"local"; never forked: README "Threads, fork and Ctrl-C"). Each job writes
out_dir/<id>.png and one line of out_dir/index.jsonl; a job that fails (an
error, or its worker dying) is tried again, on another worker when there is
one, up to `retries` times, then recorded as failed. A sweep run again skips
the jobs the index already has as "ok".
"""
import collections
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

__all__ = ["grid", "job_id", "sweep"]

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


def job_id(scene=None, render=None):
    """A stable name for the job of these options: the first 12 hex digits of
    the SHA-256 of their JSON (keys sorted), the same in every process and run."""
    text = json.dumps({"scene": _plain(scene or {}), "render": _plain(render or {})},
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
        scene, render = _plain(job.get("scene") or {}), _plain(job.get("render") or {})
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
            result["error"] = str(e) if isinstance(e, tsis.Error) else f"{type(e).__name__}: {e}"
        result["seconds"] = round(time.perf_counter() - start, 3)
        return result


def _test_exit(job):
    # Tests kill a worker in the middle of a job: TSIS_SWEEP_TEST_EXIT="ID:MARKER"
    # makes the first worker that takes job ID create the file MARKER and exit.
    jid, _, marker = os.environ.get("TSIS_SWEEP_TEST_EXIT", "").partition(":")
    if jid == job["id"] and marker and not os.path.exists(marker):
        open(marker, "w").close()
        os._exit(70)


def _local_worker(conn):
    """A local worker process: jobs in, results out, until None or the pipe closes."""
    worker = _Worker()
    try:
        while (job := conn.recv()) is not None:
            conn.send(worker.run(job))
    except (EOFError, KeyboardInterrupt):
        pass


# --- the pools: workers by slot, their results as they come --------------


class _LocalPool:
    """Processes of this machine, started by spawning."""

    def __init__(self, workers):
        self._ctx = multiprocessing.get_context("spawn")
        self._slots = [self._start() for _ in range(workers)]

    def _start(self):
        conn, child = self._ctx.Pipe()
        process = self._ctx.Process(target=_local_worker, args=(child,), daemon=True,
                                    name="tsis-sweep-worker")
        process.start()
        child.close()
        return process, conn

    def submit(self, k, job):
        try:
            self._slots[k][1].send(job)
        except OSError:  # died while idle: a new one takes the job
            self.restart(k)
            self._slots[k][1].send(job)

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
        self._slots[k] = self._start()
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
        self._refs = {}  # the running job's result → slot

    def submit(self, k, job):
        self._refs[self._slots[k].run.remote(job)] = k

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
    if backend == "auto":
        backend = "ray" if importlib.util.find_spec("ray") else "local"
    if backend not in ("ray", "local"):
        raise ValueError(f"backend {backend!r}: 'auto', 'ray' or 'local'")
    if workers < 1 or retries < 0:
        raise ValueError("workers must be at least 1 and retries at least 0")
    jobs = _normalised(jobs)
    os.makedirs(out_dir, exist_ok=True)
    done = _done_ids(out_dir)
    todo = collections.deque(j for j in jobs if j["id"] not in done)
    summary = {"total": len(jobs), "ok": 0, "failed": 0, "skipped": len(jobs) - len(todo),
               "failed_ids": [], "backend": backend}
    start = time.perf_counter()
    if todo:
        slots = min(workers, len(todo))
        pool = _RayPool(slots, address) if backend == "ray" else _LocalPool(slots)
        try:
            _run(pool, slots, todo, retries, timeout, out_dir, summary)
        finally:
            pool.close()
    summary["seconds"] = round(time.perf_counter() - start, 3)
    return summary


def _run(pool, slots, todo, retries, timeout, out_dir, summary):
    attempts = collections.Counter()
    last_worker = {}  # job id → the slot that last tried it
    running = {}  # slot → (job, when it started)
    with open(os.path.join(out_dir, INDEX), "a") as index:
        while todo or running:
            for k in set(range(slots)) - set(running):
                if not todo:
                    break
                # A job tried before goes to another worker when one is free.
                job = next((j for j in todo if last_worker.get(j["id"]) != k), todo[0])
                todo.remove(job)
                pool.submit(k, job)
                running[k] = (job, time.monotonic())
            finished = pool.wait(list(running), 1.0 if timeout else None)
            if timeout:  # past its time: the worker is ended, the job fails
                now = time.monotonic()
                finished += [(k, pool.restart(k, f"no result after {timeout} s"))
                             for k, (_, t) in running.items() if now - t > timeout
                             and k not in {f[0] for f in finished}]
            for k, result in finished:
                job, _ = running.pop(k)
                attempts[job["id"]] += 1
                last_worker[job["id"]] = k
                if result["status"] != "ok" and attempts[job["id"]] <= retries:
                    todo.append(job)
                    continue
                _record(index, out_dir, job, result, attempts[job["id"]], summary)


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

"""Issue 40's "library under misuse" cases, run against one build's `import
tsis` (MODULE_DIR holds tsis.*.so): one line per case with what happened and
the wall time. Each case runs in a child interpreter with a timeout and an
address-space limit, so a crash, a hang or a runaway copy is a line too.
bench/hardening_repro.sh TSIS lib runs it for TSIS's build (before/after).

Usage: /usr/bin/python3 bench/hardening_python.py MODULE_DIR [TIMEOUT_S [SUBSTRING]]
(SUBSTRING: only the cases whose label holds it)
"""
import os
import resource
import signal
import subprocess
import sys
import textwrap
import time

module_dir = os.path.abspath(sys.argv[1])
timeout = float(sys.argv[2]) if len(sys.argv) > 2 else 30
only = sys.argv[3] if len(sys.argv) > 3 else ""

PRELUDE = """
import os, signal, sys, threading, time
import numpy as np
import tsis
SMALL = dict(width=40, height=32, atlas_res=128, light_res=256)
S = tsis.Scene(mesh="builtin:sphere")
V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
T = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int64)
def attempt(f):
    try:
        return "ok: " + str(f())
    except Exception as e:  # KeyboardInterrupt is not an Exception
        return f"{type(e).__name__}: {(str(e).splitlines() or [''])[0]}"
"""

THREADS = """
r = tsis.Renderer(gl="{gl}")
ref = r.render(S, **SMALL).image
said = []
def work():
    for _ in range(8):
        said.append(attempt(lambda: bool(np.array_equal(r.render(S, **SMALL).image, ref))))
ts = [threading.Thread(target=work) for _ in range(2)]
[t.start() for t in ts]; [t.join() for t in ts]
bad = [x for x in said if x != "ok: True"]
print(f"{{said.count('ok: True')}} of 16 frames whole;", (bad or ["no error"])[0][:120])
"""

CASES = [
    ("one Renderer, two threads (osmesa)", THREADS.format(gl="osmesa")),
    ("one Renderer, two threads (egl)", THREADS.format(gl="egl")),
    ("Renderer made on another thread (egl)", """
        made = []
        t = threading.Thread(target=lambda: made.append(tsis.Renderer(gl="egl"))); t.start(); t.join()
        print(attempt(lambda: made[0].render(S, **SMALL).image.shape))
    """),
    ("fork after a render: the same Renderer in the child", """
        r = tsis.Renderer(); r.render(S, **SMALL)
        pid = os.fork()
        if pid == 0:
            print(attempt(lambda: r.render(S, **SMALL).image.shape), flush=True); os._exit(0)
        os.waitpid(pid, 0)
    """),
    ("fork after a render: a new Renderer in the child", """
        tsis.Renderer().render(S, **SMALL)
        pid = os.fork()
        if pid == 0:
            print(attempt(lambda: tsis.Renderer().render(S, **SMALL).image.shape), flush=True)
            os._exit(0)
        os.waitpid(pid, 0)
    """),
    ("fork before any Renderer: render in the child", """
        pid = os.fork()
        if pid == 0:
            print(attempt(lambda: tsis.Renderer().render(S, **SMALL).image.shape), flush=True)
            os._exit(0)
        os.waitpid(pid, 0)
    """),
    ("fork after import, the child ends with sys.exit", """
        pid = os.fork()
        if pid == 0:
            sys.exit(0)
        _, status = os.waitpid(pid, 0)
        print("child exited", status)
    """),
    ("SIGINT 1 s into volumetric time=60", """
        r = tsis.Renderer()
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        t = time.time()
        try:
            r.render(S, method="volumetric", time=60, **SMALL)
            print(f"finished after {time.time() - t:.1f} s")
        except KeyboardInterrupt:
            print(f"KeyboardInterrupt after {time.time() - t:.2f} s; next frame",
                  attempt(lambda: r.render(S, **SMALL).image.shape))
    """),
    ("from_arrays, int64 index 2^32+2", """
        t = T.copy(); t[1, 2] = 2**32 + 2
        print(attempt(lambda: tsis.Scene.from_arrays(V, t).triangle_count))
    """),
    ("from_arrays, float index 2.7", """
        print(attempt(lambda: tsis.Scene.from_arrays(V, np.array([[0, 2.7, 1]])).triangle_count))
    """),
    ("from_arrays, NaN vertex", """
        v = V.copy(); v[2, 1] = np.nan
        print(attempt(lambda: tsis.Scene.from_arrays(v, T).triangle_count))
    """),
    ("compare on a 100000x100000x3 view (no memory behind it)", """
        huge = np.broadcast_to(np.float64(0), (100000, 100000, 3))
        print(attempt(lambda: tsis.compare(huge, huge)["rmse"]))
    """),
    ("width=np.int64(32)", """
        print(attempt(lambda: tsis.render(S, **dict(SMALL, width=np.int64(32))).image.shape))
    """),
]


def limit_memory():
    gb = 8 << 30
    resource.setrlimit(resource.RLIMIT_AS, (gb, gb))


env = dict(os.environ, PYTHONPATH=module_dir, TSIS_PROGRESS="0")
for label, code in CASES:
    if only not in label:
        continue
    t = time.time()
    # A session of its own: a hung case's forked child is killed with it.
    p = subprocess.Popen([sys.executable, "-c", PRELUDE + textwrap.dedent(code)], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         preexec_fn=limit_memory, start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
        lines = [x for x in out.splitlines() if x.strip()]
        said = f"rc={p.returncode} | {lines[-1][:200] if lines else ''}"
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        said = f"hung: killed after {timeout:.0f} s"
    print(f"lib {label}: {said} ({time.time() - t:.1f} s)", flush=True)

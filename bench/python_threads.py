"""Two Python threads rendering with two Renderers, against the same frames one
after another on one thread, and two threads sharing one Renderer (whose
frames run one at a time: README "Python", threads). The GIL is released
during a frame, so the two renderers' frames overlap as far as the cores let
them (llvmpipe and PoCL already spread one frame over every core).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_threads.py [FRAMES] [SIZE] [METHOD]
"""
import os
import sys
import threading
import time

import tsis

frames = int(sys.argv[1]) if len(sys.argv) > 1 else 8
size = int(sys.argv[2]) if len(sys.argv) > 2 else 128
method = sys.argv[3] if len(sys.argv) > 3 else "tsis"
opts = dict(width=size, height=size, atlas_res=256, light_res=512, method=method)
scenes = [tsis.Scene(mesh="builtin:sphere", material=m) for m in ("skin1", "marble")]


def frames_on(renderer, scene, n, lights):
    for i in range(n):
        # A light that moves: every frame draws its light views and B again.
        scene.lights = [tsis.Light(position=(10 * (i % 5 - 2) + lights, 12, 6),
                                   rgb=(150, 150, 150))]
        renderer.render(scene, **opts)


def timed(target_args):
    threads = [threading.Thread(target=frames_on, args=a) for a in target_args]
    t = time.perf_counter()
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    return time.perf_counter() - t


renderers = [tsis.Renderer(), tsis.Renderer()]
for r, s in zip(renderers, scenes):  # warm: programs, tables, light maps
    frames_on(r, s, 2, 0)

t = time.perf_counter()
for k in (0, 1):
    frames_on(renderers[k], scenes[k], frames, k)
serial = time.perf_counter() - t
parallel = timed([(renderers[k], scenes[k], frames, k) for k in (0, 1)])
shared = timed([(renderers[0], scenes[k], frames, k) for k in (0, 1)])

print(f"{os.cpu_count()} cores, {2 * frames} frames of {size}² ({method}), "
      f"stats {renderers[0].render(scenes[0], **opts).stats['gl_platform']}")
print(f"one thread, two renderers one after another: {serial:6.2f} s")
print(f"two threads, a renderer each:                {parallel:6.2f} s  "
      f"(speed-up {serial / parallel:.2f}x)")
print(f"two threads, one shared renderer:            {shared:6.2f} s  "
      f"({serial / shared:.2f}x: its frames run one at a time)")

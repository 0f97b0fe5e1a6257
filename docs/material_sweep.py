# %% [markdown]
# # A material sweep with `import tsis`
#
# Notebook-style (cells marked `# %%`; runs as a script too):
# `PYTHONPATH=build/python /usr/bin/python3 docs/material_sweep.py` (or after
# `./setup.sh python`, plain `/usr/bin/python3 docs/material_sweep.py`) writes
# docs/material_sweep.png: the default object in five preset materials, then
# skin1 with its coefficients σs' and σa scaled by k — the same as making the
# object 1/k times as large in diffusion lengths — and how much of the back
# light reaches the front.

# %%
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import tsis

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "material_sweep.png")
renderer = tsis.Renderer()
options = dict(width=192, height=192, method="pyramid")

# %% Five presets, the same object and lights
presets = ["marble", "skin1", "ketchup", "wholemilk", "apple"]
scene = tsis.Scene(mesh="builtin:default", size_mm=10)
images = {}
t0 = time.time()
for name in presets:
    scene.material = tsis.preset_material(name)
    images[name] = renderer.render(scene, **options).image
print(f"{len(presets)} presets in {time.time() - t0:.1f} s")

# %% skin1 with σs' and σa scaled by k
skin = tsis.preset_material("skin1")
ks = [0.125, 0.25, 0.5, 1, 2, 4, 8]
front = []
for k in ks:
    m = tsis.Material(f"skin1×{k}", sigma_s=[k * s for s in skin.sigma_s],
                      sigma_a=[k * a for a in skin.sigma_a], eta=skin.eta)
    scene.material = m
    f = renderer.render(scene, **options)
    covered = f.coverage[..., 0] > 0.5
    front.append(f.radiance[covered].mean(axis=0))
    if k in (0.25, 4):
        images[f"skin1, k = {k}"] = f.image
front = np.array(front)
for k, rgb in zip(ks, front):
    print(f"k = {k:6.3f}: mean radiance R {rgb[0]:.4f} G {rgb[1]:.4f} B {rgb[2]:.4f}")

# %% The figure
fig = plt.figure(figsize=(14, 5.6))
grid = fig.add_gridspec(2, len(images), height_ratios=[2.3, 3], wspace=0.05)
for i, (title, img) in enumerate(images.items()):
    ax = fig.add_subplot(grid[0, i])
    ax.imshow(img)
    ax.set_title(title, fontsize=10)
    ax.axis("off")
ax = fig.add_subplot(grid[1, 1:-1])
for c, colour in enumerate(["tab:red", "tab:green", "tab:blue"]):
    ax.plot(ks, front[:, c], "o-", color=colour, label="RGB"[c])
ax.set_xscale("log", base=2)
ax.set_xlabel("k: σs' and σa of skin1 scaled by k (the object k× as many diffusion lengths across)")
ax.set_ylabel("mean radiance over the object")
ax.legend()
ax.grid(alpha=0.3)
fig.savefig(OUT, dpi=80, bbox_inches="tight")
print("wrote", OUT)

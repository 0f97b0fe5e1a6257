# EEVEE's real-time viewport on tsis' scene, timed (issue 25). Run with a UI,
# under Xvfb (the viewport needs a window; `blender -b` has none):
#
#   tsis dipole --material skin1 --json > dipole.json
#   xvfb-run -a -s "-screen 0 620x603x24" blender --factory-startup \
#       --python bench/blender_viewport.py -- --mesh data/meshes/cow.off \
#       --dipole dipole.json [OPTIONS]
#
# bench/eevee_side_by_side.sh runs it beside tsis. Written for Blender 3.4
# (Debian 12's `blender`). The scene follows `tsis render --mesh M --material
# MAT --size-mm S` (host/cli/scene_options.cpp): the mesh centred on its
# bounding box and scaled so that the box's diagonal is S (1 Blender unit =
# 1 mm), tsis' y-up turned to Blender's z-up; a Principled BSDF with
# subsurface (radius per RGB = the mean free path 1/σt′ of the material, colour
# = the dipole's total diffuse reflectance, both as `tsis dipole --json`
# prints them, GGX roughness 0.3, IOR η); tsis'
# default lights (a point light behind and above with irradiance ≈ 1 at the
# centre, a directional fill 0.12 from the front: a sun) and camera (35°
# vertical field of view from the front and a little above, as a viewport
# view, not a camera object). EEVEE: one viewport sample (taa_samples 1),
# soft shadows on (the default), screen-space reflections off, subsurface
# translucency on, overlays and gizmos off, shading RENDERED.
#
# The region: the factory layout's 3D view with its headers, toolbar and
# sidebar hidden is its whole area, and an Xvfb screen of 620×603 makes that
# 512×512 (Blender 3.4, factory settings). Maximising the area instead
# (screen.screen_full_area from a timer) crashes Blender 3.4 more often than
# not, and screen.area_move's poll refuses a timer's context. The region
# obtained is reported, and --expect WxH makes any other size an error.
#
# After the material shaders compiled (bpy.app.is_job_running) and --warmup
# unmeasured frames per case, it times --frames redraws, each one
# `wm.redraw_timer` of one iteration (default DRAW_SWAP: the 3D view's region
# drawn and the window composited and swapped, which llvmpipe finishes; the
# other editors keep their last drawing), in three cases: static (nothing
# changes; with one viewport sample EEVEE renders every redraw anyway), light
# moving (every light turned about the vertical axis one step per frame, as
# `tsis animate --orbit`, the depsgraph evaluated inside the timed frame) and
# camera moving (the view orbits its target one step per frame), and with
# --env a fourth, env rotating (the world's Mapping turned one step a frame,
# as `tsis animate --orbit` turns --env). Prints one
# line (also written to --out):
#
#   EEVEE static_ms=… light_moving_ms=… camera_moving_ms=… [env_rotating_ms=…] frames=N
#   region=WxH blender=3.4.1 renderer=<GL renderer>
#
# medians of the per-frame milliseconds, then quits Blender.
import argparse
import json
import math
import os
import statistics
import sys
import time

import bpy
import gpu
from mathutils import Quaternion, Vector

def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="blender_viewport.py")
    p.add_argument("--mesh", required=True, help="an ASCII .off file (data/meshes/cow.off)")
    p.add_argument("--dipole", required=True,
                   help="the material: `tsis dipole --material M --json`'s output (a file)")
    p.add_argument("--size-mm", type=float, default=10.0)
    p.add_argument("--fov", type=float, default=35.0, help="vertical field of view, degrees")
    p.add_argument("--frames", type=int, default=30, help="timed frames per case")
    p.add_argument("--warmup", type=int, default=5, help="unmeasured frames per case")
    p.add_argument("--expect", default="", help="WxH: fail when the region is not this size")
    p.add_argument("--translucency", default="on", choices=["on", "off"],
                   help="EEVEE's subsurface translucency (light through thin parts)")
    p.add_argument("--soft-shadows", default="on", choices=["on", "off"])
    p.add_argument("--redraw", default="DRAW_SWAP", choices=["DRAW_SWAP", "DRAW_WIN_SWAP"],
                   help="wm.redraw_timer's type: the viewport region drawn and the window "
                   "presented (default), or every region of the window drawn")
    p.add_argument("--env", default="",
                   help="a lat-long map (tsis --env's) as the world, beside the lights; adds the "
                   "env_rotating case (the world's Mapping turned one step a frame)")
    p.add_argument("--env-intensity", type=float, default=1.0,
                   help="the world's strength (tsis --env-intensity)")
    p.add_argument("--out", default="", help="also write the result line to this file")
    p.add_argument("--screenshot", default="", help="save the viewport's first frame (PNG)")
    p.add_argument("--compile-timeout", type=float, default=600.0,
                   help="seconds to wait for EEVEE's shaders")
    return p.parse_args(argv)


ARGS = parse_args()


def log(*a):
    print("blender_viewport:", *a, file=sys.stderr, flush=True)


def fail(msg):
    log("error:", msg)
    if ARGS.out:
        with open(ARGS.out, "w") as f:
            f.write("EEVEE error=" + msg.replace(" ", "_") + "\n")
    os._exit(1)


# --- The scene -------------------------------------------------------------

def read_off(path):
    """Vertices and polygons of an ASCII OFF ([C][N]OFF; only x y z are used)."""
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                tokens.append(line)
    head = tokens[0]
    if not head[0].endswith("OFF"):
        fail(f"{path}: not an OFF file")
    counts = head[1:] if len(head) > 1 else tokens[1]
    first = 1 if len(head) > 1 else 2
    nv, nf = int(counts[0]), int(counts[1])
    verts = [tuple(float(t) for t in tokens[first + i][:3]) for i in range(nv)]
    faces = []
    for line in tokens[first + nv:first + nv + nf]:
        k = int(line[0])
        faces.append(tuple(int(t) for t in line[1:1 + k]))
    return verts, faces


def y_up_to_z_up(v):
    # tsis' (x, y, z), y up, camera looking along -z, to Blender's z up: a
    # rotation of +90° about x (x, y, z) -> (x, -z, y).
    return Vector((v[0], -v[2], v[1]))


def build_scene():
    scene = bpy.context.scene
    for ob in list(bpy.data.objects):  # the startup cube, camera and light
        bpy.data.objects.remove(ob, do_unlink=True)

    verts, faces = read_off(ARGS.mesh)
    lo = [min(v[i] for v in verts) for i in range(3)]
    hi = [max(v[i] for v in verts) for i in range(3)]
    centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
    scale = ARGS.size_mm / math.dist(lo, hi)
    verts = [y_up_to_z_up([(v[i] - centre[i]) * scale for i in range(3)]) for v in verts]
    mesh = bpy.data.meshes.new("object")
    mesh.from_pydata(verts, [], faces)
    mesh.validate()
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    mesh.use_auto_smooth = True  # tsis' --crease 60
    mesh.auto_smooth_angle = math.radians(60)
    obj = bpy.data.objects.new("object", mesh)
    scene.collection.objects.link(obj)

    with open(ARGS.dipole) as f:
        dipole = json.load(f)
    eta = dipole["eta"]
    mat = bpy.data.materials.new(dipole["material"])
    mat.use_nodes = True
    mat.use_sss_translucency = ARGS.translucency == "on"
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.subsurface_method = "BURLEY"
    colour = list(dipole["total_reflectance"]) + [1.0]
    bsdf.inputs["Base Color"].default_value = colour
    bsdf.inputs["Subsurface Color"].default_value = colour
    bsdf.inputs["Subsurface"].default_value = 1.0
    # The mean free path ℓ = 1/σt′ per channel, in mm (= Blender units here).
    bsdf.inputs["Subsurface Radius"].default_value = dipole["mean_free_path"]
    bsdf.inputs["Subsurface IOR"].default_value = eta
    bsdf.inputs["IOR"].default_value = eta
    bsdf.inputs["Specular"].default_value = ((eta - 1) / (eta + 1)) ** 2 / 0.08
    bsdf.inputs["Roughness"].default_value = 0.3
    mesh.materials.append(mat)

    # tsis' default lights (defaultLights): a point light behind and above,
    # irradiance ≈ 1 at the centre, and a directional fill of 0.12.
    s = ARGS.size_mm
    back = Vector((-0.45, 0.75, -1.0)) * (1.3 * s)
    point = bpy.data.lights.new("back", "POINT")
    point.energy = 4 * math.pi * back.length_squared  # W: E = P / (4π d²) = 1
    point.use_shadow = True
    point_ob = bpy.data.objects.new("back", point)
    point_ob.location = y_up_to_z_up(back)
    scene.collection.objects.link(point_ob)
    sun = bpy.data.lights.new("fill", "SUN")
    sun.energy = 0.12
    sun.use_shadow = True
    sun_ob = bpy.data.objects.new("fill", sun)
    travel = y_up_to_z_up((0.6, -0.4, -1.0)).normalized()  # the light travels along it
    sun_ob.rotation_euler = travel.to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(sun_ob)

    world = scene.world or bpy.data.worlds.new("world")
    scene.world = world
    if ARGS.env:
        build_world(world)
    else:
        world.use_nodes = False
        world.color = (0, 0, 0)  # tsis has no ambient light

    scene.render.engine = "BLENDER_EEVEE"
    ee = scene.eevee
    ee.taa_samples = 1  # viewport samples: one per redraw
    ee.use_taa_reprojection = False
    ee.use_ssr = False
    ee.use_soft_shadows = ARGS.soft_shadows == "on"
    ee.use_gtao = False
    ee.use_bloom = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.exposure = 3.3  # tsis --exposure default
    return [point_ob, sun_ob]


WORLD = {}


def build_world(world):
    """--env as the world: its map through a Mapping node (turned about Z) at
    --env-intensity. Blender's equirectangular lookup puts the map's centre
    column at +X, tsis' at -z (Blender's +Y here): a Mapping turn of 90° is
    tsis' --env-rotate 0 (docs/guide/environment.md, "Orientation")."""
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    coord = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    tex = nodes.new("ShaderNodeTexEnvironment")
    tex.image = bpy.data.images.load(os.path.abspath(ARGS.env))
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = ARGS.env_intensity
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(coord.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], tex.inputs["Vector"])
    links.new(tex.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], out.inputs["Surface"])
    mapping.inputs["Rotation"].default_value[2] = math.radians(90)
    WORLD["mapping"] = mapping


# --- The window ------------------------------------------------------------

def view3d():
    win = bpy.context.window_manager.windows[0]
    for area in win.screen.areas:
        if area.type == "VIEW_3D":
            region = next(r for r in area.regions if r.type == "WINDOW")
            return win, area, region
    fail("no VIEW_3D area")


def setup_view(area):
    space = area.spaces.active
    space.show_region_header = False
    space.show_region_tool_header = False
    space.show_region_toolbar = False
    space.show_region_ui = False
    space.show_region_hud = False
    space.show_gizmo = False
    space.overlay.show_overlays = False
    space.shading.type = "RENDERED"
    space.shading.use_scene_lights_render = True
    space.shading.use_scene_world_render = True
    # The viewport's lens is against a 72 mm sensor (zoom 2 on 36 mm): the
    # square region's field of view is 2·atan(36 / lens).
    space.lens = 36 / math.tan(math.radians(ARGS.fov) / 2)
    space.clip_start = 0.01 * ARGS.size_mm
    space.clip_end = 100 * ARGS.size_mm
    r3d = space.region_3d
    r3d.view_perspective = "PERSP"
    r3d.view_location = (0, 0, 0)
    # defaultCamera: distance 0.5·S / sin(fov/2) · 1.05, from (0, 0.35, 1) (y up).
    r3d.view_distance = 0.5 * ARGS.size_mm / math.sin(math.radians(ARGS.fov) / 2) * 1.05
    eye = y_up_to_z_up((0, 0.35, 1)).normalized()
    r3d.view_rotation = eye.to_track_quat("Z", "Y")  # the view looks along -eye


def draw(ctx):
    with bpy.context.temp_override(**ctx):
        bpy.ops.wm.redraw_timer(type=ARGS.redraw, iterations=1)


def shaders_compiling():
    try:
        return bpy.app.is_job_running("SHADER_COMPILATION")
    except (AttributeError, TypeError):
        return False


STATE = {"step": "scene", "t0": 0.0}
LIGHTS = []


def tick():
    """The state machine, one step per timer call, so that the UI is up."""
    step = STATE["step"]
    win, area, region = view3d()
    ctx = dict(window=win, screen=win.screen, area=area, region=region)
    if step == "scene":
        LIGHTS.extend(build_scene())
        STATE["step"] = "setup"
        return 0.2
    if step == "setup":
        setup_view(area)
        STATE["step"] = "compile"
        STATE["t0"] = time.perf_counter()
        return 0.2
    if step == "compile":
        draw(ctx)  # EEVEE compiles the materials' shaders in a job
        waited = time.perf_counter() - STATE["t0"]
        if shaders_compiling() or waited < 2.0:
            if waited > ARGS.compile_timeout:
                fail(f"EEVEE's shaders still compiling after {waited:.0f} s")
            return 0.5
        log(f"shaders ready after {waited:.1f} s")
        STATE["step"] = "measure"
        return 0.2
    measure(ctx, win, area, region)
    bpy.ops.wm.quit_blender()
    return None


def measure(ctx, win, area, region):
    size = f"{region.width}x{region.height}"
    renderer = gpu.platform.renderer_get()
    log(f"region {size}, window {win.width}x{win.height}, GL {renderer} "
        f"{gpu.platform.version_get()}")
    if ARGS.expect and size != ARGS.expect:
        fail(f"the VIEW_3D region is {size}, not {ARGS.expect} (window "
             f"{win.width}x{win.height}): change the Xvfb screen by the difference")
    if ARGS.screenshot:
        draw(ctx)
        with bpy.context.temp_override(**ctx):
            bpy.ops.screen.screenshot_area(filepath=ARGS.screenshot)
    r3d = area.spaces.active.region_3d
    view_layer = bpy.context.view_layer
    n = ARGS.frames + ARGS.warmup
    turn = 2 * math.pi / n

    def timed(change):
        ms = []
        for f in range(n):
            t = time.perf_counter()
            change(f)
            draw(ctx)
            if f >= ARGS.warmup:
                ms.append(1000 * (time.perf_counter() - t))
        return statistics.median(ms)

    static = timed(lambda f: None)

    base = [(ob.location.copy(), ob.rotation_euler.to_quaternion()) for ob in LIGHTS]

    def move_lights(f):
        rot = Quaternion((0, 0, 1), turn * (f + 1))
        for ob, (loc, q) in zip(LIGHTS, base):
            ob.location = rot @ loc
            ob.rotation_euler = (rot @ q).to_euler()
        view_layer.update()  # evaluates the depsgraph; EEVEE hears of the change

    light = timed(move_lights)
    for ob, (loc, q) in zip(LIGHTS, base):
        ob.location, ob.rotation_euler = loc, q.to_euler()
    view_layer.update()

    start = r3d.view_rotation.copy()

    def move_camera(f):
        r3d.view_rotation = Quaternion((0, 0, 1), turn * (f + 1)) @ start

    camera = timed(move_camera)
    r3d.view_rotation = start
    env = ""
    if WORLD:
        rotation = WORLD["mapping"].inputs["Rotation"]
        base_z = rotation.default_value[2]

        def turn_world(f):
            rotation.default_value[2] = base_z + turn * (f + 1)
            view_layer.update()

        env = f"env_rotating_ms={timed(turn_world):.1f} "
    line = (f"EEVEE static_ms={static:.1f} light_moving_ms={light:.1f} "
            f"camera_moving_ms={camera:.1f} {env}frames={ARGS.frames} region={size} "
            f"blender={bpy.app.version_string} renderer={renderer}")
    print(line, flush=True)
    if ARGS.out:
        with open(ARGS.out, "w") as f:
            f.write(line + "\n")


def guarded_tick():
    try:
        return tick()
    except Exception as e:  # a failure must end Blender, not leave it waiting
        import traceback
        traceback.print_exc()
        fail(f"{type(e).__name__}: {e}")


if bpy.app.background:
    fail("the viewport needs a window: run Blender with its UI under xvfb-run, not -b")
bpy.context.preferences.view.show_splash = False  # it would draw over the viewport
bpy.app.timers.register(guarded_tick, first_interval=0.5)

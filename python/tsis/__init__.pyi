# Type stubs of `import tsis` (the extension tsis._tsis, python/tsis_module.cpp).
# Kept whole: test_stub_covers_the_module checks that every public name of the
# package, and every public member of its classes, is here.
from os import PathLike
from typing import Any, Sequence, SupportsFloat, SupportsIndex

import numpy as np
import numpy.typing as npt

from . import distributed as distributed

Vec3 = Sequence[SupportsFloat]  # three numbers (numpy scalars and arrays too)
# An option's value: str as typed, a number, a flag, or a sequence (x,y,z; a
# list of lights).
OptionValue = str | SupportsFloat | SupportsIndex | bool | Sequence[Any]

class Error(RuntimeError): ...
class NoteWarning(UserWarning): ...

def set_quiet(quiet: bool = True) -> bool: ...

class Material:
    name: str
    sigma_s: list[float]  # setting it (or sigma_a) drops albedo and mfp_mm
    sigma_a: list[float]
    eta: float
    @property
    def albedo(self) -> list[float] | None: ...
    @property
    def mfp_mm(self) -> list[float] | None: ...
    @property
    def albedo_texture(self) -> str: ...  # an image file; "" none
    @albedo_texture.setter
    def albedo_texture(self, path: str | PathLike[str]) -> None: ...
    def __init__(self, name: str = "custom", *, sigma_s: Vec3 | None = None,
                 sigma_a: Vec3 | None = None, albedo: Vec3 | None = None,
                 mfp_mm: Vec3 | None = None, eta: float = 1.3,
                 albedo_texture: str | PathLike[str] | None = None) -> None: ...
    @staticmethod
    def preset(name: str) -> Material: ...

def preset_material(name: str) -> Material: ...
def preset_materials() -> list[str]: ...

class Light:
    directional: bool
    vec: list[float]  # point: position (mm); directional: direction
    rgb: list[float]
    def __init__(self, *, position: Vec3 | None = None, direction: Vec3 | None = None,
                 rgb: Vec3 = (1, 1, 1)) -> None: ...

class Environment:
    path: str  # the file; with pixels, only the map's name
    pixels: npt.NDArray[np.float32] | None  # H×W×3 (2:1, row 0 the zenith), None: a file's
    rotate_deg: float
    intensity: float
    def __init__(self, path: str | PathLike[str] | None = None, *,
                 pixels: npt.ArrayLike | None = None, rotate_deg: float = 0.0,
                 intensity: float = 1.0) -> None: ...

class Camera:
    eye: list[float]
    target: list[float]
    up: list[float]
    fov: float
    def __init__(self, eye: Vec3, target: Vec3 = (0, 0, 0), up: Vec3 = (0, 1, 0),
                 fov: float = 35.0) -> None: ...

class Transform:
    scale: float
    rotate_deg: list[float]  # degrees about x, then y, then z
    translate_mm: list[float]
    def __init__(self, *, scale: float = 1, rotate_deg: Vec3 = (0, 0, 0),
                 translate_mm: Vec3 = (0, 0, 0)) -> None: ...

class Object:
    @property
    def mesh(self) -> str | None: ...  # a file or builtin:NAME; None: arrays
    @mesh.setter
    def mesh(self, mesh: str | PathLike[str] | None) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float32] | None: ...  # N×3 (mm)
    @vertices.setter
    def vertices(self, vertices: npt.ArrayLike | None) -> None: ...
    @property
    def triangles(self) -> npt.NDArray[np.uint32] | None: ...  # M×3
    @triangles.setter
    def triangles(self, triangles: npt.ArrayLike | None) -> None: ...
    transform: Transform
    material: Material | None  # None: the file's, else the scene's
    def __init__(self, *, mesh: str | PathLike[str] | None = None,
                 vertices: npt.ArrayLike | None = None, triangles: npt.ArrayLike | None = None,
                 transform: Transform | None = None, material: Material | None = None) -> None: ...

class Scene:
    material: Material | None  # None: the mesh file's own materials apply
    lights: list[Light]
    environment: Environment | None
    camera: Camera
    @property
    def materials(self) -> list[Material]: ...
    @property
    def notes(self) -> list[str]: ...
    @property
    def render_settings(self) -> RenderSettings: ...  # its frames' defaults
    @property
    def mesh_name(self) -> str: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...
    @property
    def objects(self) -> list[Object]: ...  # [] unless made by from_objects
    def __init__(self, **options: OptionValue) -> None: ...
    @staticmethod
    def from_arrays(vertices: npt.ArrayLike, triangles: npt.ArrayLike,
                    **options: OptionValue) -> Scene: ...
    @staticmethod
    def from_objects(objects: Sequence[Object], **options: OptionValue) -> Scene: ...
    def options(self) -> dict[str, str | bool | list[str]]: ...
    def __copy__(self) -> Scene: ...
    def __deepcopy__(self, memo: dict[int, Any]) -> Scene: ...

class Frame:
    image: npt.NDArray[np.uint8]  # H×W×3, row 0 = top
    radiance: npt.NDArray[np.float32]  # H×W×3
    radiosity: npt.NDArray[np.float32]
    position: npt.NDArray[np.float32]
    normal: npt.NDArray[np.float32]
    coverage: npt.NDArray[np.float32]  # H×W×1
    flux_atlas: npt.NDArray[np.float32]
    lavg: float
    stats: dict[str, Any]

class RenderSettings:
    # One property per render option of `tsis render` (its keyword of
    # render()); set as typed, checked as the option is.
    method: str
    width: int
    height: int
    samples: int
    seed: int
    spacing: float
    epsilon: float
    pyramid_epsilon: float
    pyramid_stride: int
    pyramid_cache: str
    rp_bound: float
    rp_k: float
    rd_part: str
    model: str
    profile: str
    energy: str
    transport: str
    exit: str
    single_scatter: bool
    ltsm_rings: int
    ltsm_per_ring: int
    mis_distance: int
    tsm_radius: float
    spp: int
    spp_offset: int
    max_scatterings: int
    min_scatterings: int
    estimator: str
    time: float
    atlas_res: int
    light_res: int
    light_lod: int
    exposure: float
    auto_exposure: bool
    key: float
    tone: str
    background: str
    roughness: float | str  # "file": each object's own
    no_specular: bool
    aa: int
    aa_method: str
    force: bool
    no_reuse_lighting: bool
    def __init__(self, **settings: OptionValue) -> None: ...
    def __eq__(self, other: object) -> bool: ...

class Renderer:
    def __init__(self, cl_device: str = "", gl: str = "") -> None: ...
    def render(self, scene: Scene, settings: RenderSettings | None = None,
               **options: OptionValue) -> Frame: ...

def render(scene: Scene, settings: RenderSettings | None = None,
           **options: OptionValue) -> Frame: ...
def compare(image: npt.ArrayLike, reference: npt.ArrayLike,
            mask: npt.ArrayLike | None = None) -> dict[str, float | int]: ...
def write_image(path: str | PathLike[str], image: npt.ArrayLike) -> None: ...
def read_image(path: str | PathLike[str]) -> npt.NDArray[np.float32]: ...
def option_help() -> str: ...

"""tsis: translucent materials rendered with the dipole BSSRDF (README, docs/python.md).

The classes and functions are the extension's (tsis._tsis, python/tsis_module.cpp);
tsis.distributed renders many frames on many workers."""
from ._tsis import *  # noqa: F401,F403  (what the extension adds later comes along)
from ._tsis import (Camera, Environment, Error, Frame, Light, Material, NoteWarning, Object,
                    Renderer, RenderSettings, Scene, Transform, compare, option_help, preset_material,
                    preset_materials, read_image, render, set_quiet, write_image)
from . import distributed

__all__ = ["Camera", "Environment", "Error", "Frame", "Light", "Material", "NoteWarning",
           "Object", "Renderer", "RenderSettings", "Scene", "Transform", "compare", "distributed", "option_help",
           "preset_material", "preset_materials", "read_image", "render", "set_quiet",
           "write_image"]

"""ScrewBender for Blender: smooth an object's keyed motion through its poses by screw
subdivision (the Python package ``screwbender``, bundled as a wheel), and move motions between
Blender and ScrewBender's files.

* ``operators``: *Smooth motion*, *Export motion*, *Import motion*;
* ``panel``: the sidebar panel and the scene's settings;
* ``keys``: an object's keys as control poses, and poses back into an action.
"""

import bpy

from . import operators, panel

CLASSES = operators.CLASSES + panel.CLASSES


def register():
    """Registers the operators, the panel and ``Scene.screwbender``."""
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.screwbender = bpy.props.PointerProperty(type=panel.ScrewBenderSettings)


def unregister():
    """Removes what ``register`` added."""
    del bpy.types.Scene.screwbender
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)

"""The sidebar panel (3-D view, N panel, tab *ScrewBender*) and the scene's motion settings that
its buttons start the operators with."""

import bpy
from bpy.props import IntProperty

from . import keys
from .operators import MotionOptions


class ScrewBenderSettings(MotionOptions, bpy.types.PropertyGroup):
    """The motion options the panel's buttons use (``scene.screwbender``)."""

    step: IntProperty(name="Step", description="A key every this many frames", default=1, min=1, max=100)


class VIEW3D_PT_screwbender(bpy.types.Panel):
    """Smooth, export and import ScrewBender motions."""

    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "ScrewBender"
    bl_label = "ScrewBender"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.screwbender
        obj = context.active_object
        if obj is not None:
            frames = keys.key_frames(obj)
            layout.label(text=f"{obj.name}: {len(frames)} keyed poses", icon="KEYFRAME")
        column = layout.column(align=True)
        column.prop(settings, "scheme")
        column.prop(settings, "rules")
        column.prop(settings, "levels")
        column.prop(settings, "step")
        column.prop(settings, "cycle")
        layout.operator("screwbender.smooth_motion", icon="IPO_EASE_IN_OUT")
        row = layout.row(align=True)
        row.operator("screwbender.export_motion", icon="EXPORT")
        row.operator("screwbender.import_motion", icon="IMPORT")


CLASSES = (ScrewBenderSettings, VIEW3D_PT_screwbender)

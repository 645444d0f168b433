"""The extension's operators: *Smooth motion*, *Export motion*, *Import motion*.

Each reports bad input in Blender's report area (an ``ERROR`` report naming the object and what
is wrong) and changes nothing then. *Smooth motion* registers for undo and for the
adjust-last-operation panel, so changing its options there redoes it at once: the live preview.
"""

import bpy
import numpy as np
from bpy.props import BoolProperty, EnumProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper

from . import keys

SCHEMES = [
    ("fourpoint", "4-point", "Interpolating: passes through every key"),
    ("jarek", "Jarek", "Between 4-point and B-spline"),
    ("bspline", "B-spline", "Approximating, the smoothest: stays near the keys"),
]
RULES = [
    ("direct", "Direct", "The revised paper's rules"),
    ("split", "Split then tweak", "The first version's rules"),
]


def motion_options(op):
    """The ``screwbender.Motion`` keyword arguments of an operator's (or the settings') options."""
    return {"closed": op.cycle, "scheme": op.scheme, "rules": op.rules, "levels": op.levels}


class MotionOptions:
    """The motion's options, shared by the operators and the sidebar's settings."""

    scheme: EnumProperty(name="Scheme", items=SCHEMES, default="fourpoint")
    rules: EnumProperty(name="Rules", items=RULES, default="direct")
    levels: IntProperty(name="Levels", description="Subdivision steps (0: screws between the keys)", default=5, min=0, max=10)
    cycle: BoolProperty(name="Cycle", description="Join the last key back to the first", default=False)


def copy_options(source, target):
    """Copies the motion options (and ``step`` where both have it) from one holder to another."""
    for name in ("scheme", "rules", "levels", "cycle", "step"):
        if hasattr(source, name) and hasattr(target, name):
            setattr(target, name, getattr(source, name))


def targets(context):
    """The selected objects, else the active one."""
    chosen = list(context.selected_objects)
    if not chosen and context.active_object is not None:
        chosen = [context.active_object]
    return chosen


def smooth(obj, options, step):
    """Smooths one object's keyed motion into a new action; returns it. Raises ``keys.BadKeys``
    or ``ValueError`` (from ``screwbender``, naming the element)."""
    import screwbender as sb

    frames, rows = keys.control_poses(obj)
    rows, knot_frames = keys.knots(frames, rows, options["closed"])
    motion = sb.Motion(rows, **options)
    out = keys.output_frames(knot_frames, step)
    poses = keys.continuous(motion.poses_at(keys.parameters(out, knot_frames)))
    source = obj.animation_data.action
    source.use_fake_user = True
    action = keys.write_action(obj, f"{source.name} smoothed", out, poses)
    action["screwbender_source"] = source.name
    return action


class SCREWBENDER_OT_smooth_motion(MotionOptions, bpy.types.Operator):
    """Smooth the keyed motion of the selected objects through their keys by screw subdivision (a new action; the original one is kept)"""

    bl_idname = "screwbender.smooth_motion"
    bl_label = "Smooth motion"
    bl_options = {"REGISTER", "UNDO"}

    step: IntProperty(name="Step", description="A key every this many frames", default=1, min=1, max=100)

    @classmethod
    def poll(cls, context):
        return bool(targets(context))

    def invoke(self, context, event):
        copy_options(context.scene.screwbender, self)
        return self.execute(context)

    def execute(self, context):
        objects = targets(context)
        # Every object is checked before any is changed: bad input changes nothing.
        try:
            for obj in objects:
                keys.control_poses(obj)
        except keys.BadKeys as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        done = []
        for obj in objects:
            try:
                done.append(smooth(obj, motion_options(self), self.step).name)
            except ValueError as error:
                self.report({"ERROR"}, f"{obj.name}: {error}")
                return {"CANCELLED"}
        self.report({"INFO"}, f"smoothed: {', '.join(done)}")
        return {"FINISHED"}


class SCREWBENDER_OT_export_motion(MotionOptions, bpy.types.Operator, ExportHelper):
    """Write the active object's selected keys (all keys when none is selected) as a ScrewBender motion document (.json)"""

    bl_idname = "screwbender.export_motion"
    bl_label = "Export motion"

    filename_ext = ".json"
    filter_glob: StringProperty(default="*.json", options={"HIDDEN"})

    @classmethod
    def poll(cls, context):
        return context.active_object is not None

    def invoke(self, context, event):
        copy_options(context.scene.screwbender, self)
        return ExportHelper.invoke(self, context, event)

    def execute(self, context):
        import screwbender as sb

        obj = context.active_object
        fps = context.scene.render.fps / context.scene.render.fps_base
        try:
            frames, rows = keys.control_poses(obj, selected_only=True)
            rows, knot_frames = keys.knots(frames, rows, self.cycle)
            motion = sb.Motion(rows, times=knot_frames / fps, name=obj.name, **motion_options(self))
        except ValueError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        with open(self.filepath, "w", encoding="utf-8") as out:
            out.write(motion.to_json())
        self.report({"INFO"}, f"{obj.name}: {len(rows)} control poses written to {self.filepath}")
        return {"FINISHED"}


class SCREWBENDER_OT_import_motion(bpy.types.Operator, ImportHelper):
    """Key a ScrewBender motion's control poses (.json, .glb, .gltf) on the active object (a new empty when none is active)"""

    bl_idname = "screwbender.import_motion"
    bl_label = "Import motion"
    bl_options = {"REGISTER", "UNDO"}

    filter_glob: StringProperty(default="*.json;*.glb;*.gltf", options={"HIDDEN"})

    def execute(self, context):
        import screwbender as sb

        try:
            motion = sb.Motion.load(self.filepath)
        except (ValueError, OSError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        rows = np.asarray(motion.poses)
        fps = context.scene.render.fps / context.scene.render.fps_base
        times = motion.times
        count = len(rows) + (1 if motion.closed else 0)
        frames = np.asarray(times, dtype=float) * fps if times else np.arange(count) * fps + context.scene.frame_start
        if motion.closed:
            rows = np.vstack([rows, rows[:1]])
        obj = context.active_object
        if obj is None:
            obj = bpy.data.objects.new(motion.name or "motion", None)
            context.collection.objects.link(obj)
            context.view_layer.objects.active = obj
        elif obj.animation_data is not None and obj.animation_data.action is not None:
            obj.animation_data.action.use_fake_user = True
        keys.write_action(obj, motion.name or "motion", frames, keys.continuous(rows))
        # A motion document says whether it is a cycle (not how to smooth it): the panel's
        # *Cycle* follows, so that *Smooth motion* closes what the file closed.
        context.scene.screwbender.cycle = motion.closed
        self.report({"INFO"}, f"{obj.name}: {len(rows)} keys from {self.filepath}")
        return {"FINISHED"}


CLASSES = (SCREWBENDER_OT_smooth_motion, SCREWBENDER_OT_export_motion, SCREWBENDER_OT_import_motion)

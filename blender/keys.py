"""An object's keyframes as ScrewBender control poses, and poses back into a new action.

Control poses are the object's local transform (location and rotation, any rotation mode) at
each frame where its location or rotation is keyed; their frames are the timing. Rows are
``x y z qw qx qy qz`` (quaternion scalar first), as everywhere in ScrewBender.

Blender 4.4 keeps an action's F-curves per slot (``action_get_channelbag_for_slot``); 4.2 and
4.3 on the action itself: ``fcurves_of`` reads either, so the extension runs on 4.2 LTS and
later.
"""

import bpy
import numpy as np
from mathutils import Euler, Quaternion

#: Scale within this of 1 counts as unscaled (Blender stores transforms as float32).
SCALE_TOLERANCE = 1e-5
#: A last key within this of the first (origin distance plus rotation angle) closes a cycle.
SAME_POSE_TOLERANCE = 1e-5


class BadKeys(ValueError):
    """Bad input, with a message naming the object and what is wrong (shown in Blender's report area)."""


def fcurves_of(obj):
    """The F-curves of the object's action (an empty list when it has none)."""
    anim = obj.animation_data
    if anim is None or anim.action is None:
        return []
    action = anim.action
    slot = getattr(anim, "action_slot", None)
    if hasattr(action, "layers") and slot is not None:
        from bpy_extras import anim_utils

        bag = anim_utils.action_get_channelbag_for_slot(action, slot)
        return list(bag.fcurves) if bag is not None else []
    return list(action.fcurves)


def rotation_path(obj):
    """The data path of the object's rotation in its rotation mode."""
    if obj.rotation_mode == "QUATERNION":
        return "rotation_quaternion"
    if obj.rotation_mode == "AXIS_ANGLE":
        return "rotation_axis_angle"
    return "rotation_euler"


def key_frames(obj, selected_only=False):
    """The sorted frames where the object's location or rotation is keyed (only selected keys
    when ``selected_only`` and any key is selected)."""
    paths = {"location", rotation_path(obj)}
    points = [kp for fc in fcurves_of(obj) if fc.data_path in paths for kp in fc.keyframe_points]
    if selected_only and any(kp.select_control_point for kp in points):
        points = [kp for kp in points if kp.select_control_point]
    return sorted({round(kp.co[0], 6) for kp in points})


def check_unscaled(obj):
    """Refuses a scaled object (a rigid motion keeps its size): raises ``BadKeys``."""
    scales = [tuple(obj.scale)]
    for fc in fcurves_of(obj):
        if fc.data_path == "scale":
            scales += [(kp.co[1],) for kp in fc.keyframe_points]
    if any(abs(s - 1) > SCALE_TOLERANCE for t in scales for s in t):
        shown = ", ".join(f"{s:g}" for s in obj.scale)
        raise BadKeys(
            f"{obj.name}: scaled ({shown}): ScrewBender moves rigid bodies; apply the scale "
            "(Object > Apply > Scale) or key it at 1 first"
        )


def control_poses(obj, selected_only=False):
    """``(frames, rows)``: the object's keyed frames and its pose rows ``(n, 7)`` at them.

    Raises ``BadKeys`` for fewer than two keyed frames, a scaled object or a zero rotation.
    """
    check_unscaled(obj)
    frames = key_frames(obj, selected_only)
    if len(frames) < 2:
        raise BadKeys(
            f"{obj.name}: {len(frames)} keyed frame{'' if len(frames) == 1 else 's'} of location or "
            f"rotation ({rotation_path(obj)}): a motion needs at least 2"
        )
    curves = {(fc.data_path, fc.array_index): fc for fc in fcurves_of(obj)}
    path = rotation_path(obj)
    rows = []
    for f in frames:
        def value(data_path, index, f=f):
            fc = curves.get((data_path, index))
            return fc.evaluate(f) if fc is not None else getattr(obj, data_path)[index]

        location = [value("location", i) for i in range(3)]
        if path == "rotation_quaternion":
            q = Quaternion([value(path, i) for i in range(4)])
        elif path == "rotation_axis_angle":
            angle, *axis = (value(path, i) for i in range(4))
            q = Quaternion(axis, angle) if any(axis) else Quaternion()
        else:
            q = Euler([value(path, i) for i in range(3)], obj.rotation_mode).to_quaternion()
        if q.magnitude < 1e-9:
            raise BadKeys(f"{obj.name}: frame {f:g}: zero rotation quaternion")
        q.normalize()
        rows.append(location + list(q))
    return np.array(frames, dtype=float), np.array(rows, dtype=float)


def same_pose(a, b):
    """Whether two rows are the same pose (either quaternion sign) within ``SAME_POSE_TOLERANCE``."""
    dot = min(1.0, abs(float(np.dot(a[3:], b[3:]))))
    return float(np.linalg.norm(a[:3] - b[:3])) + 2 * np.arccos(dot) <= SAME_POSE_TOLERANCE


def knots(frames, rows, closed):
    """``(rows, knot_frames)``: the control poses and the frame of each parameter ``u = i``.

    Open: one knot per key. A cycle: a last key repeating the first (Blender's usual way to key a
    loop) is dropped and its frame closes the cycle; otherwise the cycle closes one mean key
    spacing after the last key.
    """
    frames = np.asarray(frames, dtype=float)
    if not closed:
        return rows, frames
    if len(rows) > 2 and same_pose(rows[0], rows[-1]):
        return rows[:-1], frames
    return rows, np.append(frames, frames[-1] + (frames[-1] - frames[0]) / (len(frames) - 1))


def parameters(frames_out, knot_frames):
    """The motion parameter ``u`` at each output frame: linear in the frame between knots (knot
    ``i`` at ``u = i``)."""
    return np.interp(frames_out, knot_frames, np.arange(len(knot_frames), dtype=float))


def output_frames(knot_frames, step):
    """Every ``step``-th frame from the first knot to the last, the last one included."""
    first, last = float(knot_frames[0]), float(knot_frames[-1])
    out = np.arange(first, last + 1e-9, step)
    return out if abs(out[-1] - last) < 1e-9 else np.append(out, last)


def continuous(rows):
    """The rows with each quaternion's sign chosen nearest the previous one (no flips between
    keys, which Blender's channel-by-channel interpolation would turn into a spin)."""
    rows = np.array(rows, dtype=float)
    for k in range(1, len(rows)):
        if np.dot(rows[k, 3:], rows[k - 1, 3:]) < 0:
            rows[k, 3:] *= -1
    return rows


def write_action(obj, name, frames, rows):
    """A new action ``name`` on the object, quaternion keys (``LINEAR``) of ``rows`` at
    ``frames``; the object's rotation mode becomes ``QUATERNION``. Returns the action."""
    action = bpy.data.actions.new(name)
    anim = obj.animation_data_create()
    anim.action = action
    obj.rotation_mode = "QUATERNION"
    obj.location = rows[0, :3]
    obj.rotation_quaternion = rows[0, 3:]
    # The first keys through keyframe_insert (which makes the F-curves, and on 4.4+ the slot),
    # the rest written in bulk.
    obj.keyframe_insert("location", frame=frames[0])
    obj.keyframe_insert("rotation_quaternion", frame=frames[0])
    column = {"location": 0, "rotation_quaternion": 3}
    for fc in fcurves_of(obj):
        values = rows[:, column[fc.data_path] + fc.array_index]
        points = fc.keyframe_points
        points.add(len(frames) - 1)
        co = np.empty(2 * len(frames))
        co[0::2] = frames
        co[1::2] = values
        points.foreach_set("co", co)
        for kp in points:
            kp.interpolation = "LINEAR"
        fc.update()
    return action

"""The Blender extension (blender/) in Blender itself, headless: `bpy` from PyPI.

The extension's zip (scripts/build-blender-extension.sh) is installed as a user would, through
Blender's extension installer, into a throwaway user folder; Blender installs its bundled wheel,
whose `screwbender` is also the reference here. Then:

* a cube keyed at 5 poses (Euler keys) is smoothed: `matrix_world` at every frame is the
  package's `poses_at` at the frame's parameter within 1e-5, no quaternion sign flips between
  keys, the original action kept unchanged; a cycle likewise;
* export then import gives the same keys;
* bad input (a single key, a scaled object) is reported naming the object, and nothing changes;
* the CLI's `.glb` exports of three presets imported by Blender's own glTF importer: the
  farthest vertex of the object at every sampled frame within 1e-4 of the CLI's samples;
* blender/tools/readme-pictures.py, at a tiny size: its pictures written, the corner path it
  draws after smoothing through the keyed positions and without the kinks it has before.

Undo is not checked: `bpy.ops.ed.undo` needs a window, which headless Blender has not (its poll
fails); the operator registers for undo and keeps the original action, which is checked.

    SCREWBENDER_BLENDER_ZIP=artifacts/blender/screwbender-0.1.0.zip SCREWBENDER_CLI=target/debug/screwbender \\
      .venv-blender/bin/python -m pytest tests/blender
"""

import importlib.util
import json
import os
import pathlib
import subprocess
import tempfile

# Blender reads its user folder at import: a throwaway one, so that the test installs nothing
# into the user's own Blender.
USER = tempfile.mkdtemp(prefix="screwbender-blender-")
os.environ["BLENDER_USER_RESOURCES"] = USER

import bpy  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from mathutils import Euler, Matrix, Quaternion, Vector  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
ZIP = pathlib.Path(os.environ.get("SCREWBENDER_BLENDER_ZIP", ROOT / "artifacts/blender/screwbender-0.1.0.zip"))
TOL = 1e-5

# Five key poses at frames 1, 11, …, 41: location and an Euler rotation (XYZ, radians) with
# turns past a half turn between keys, where channel-by-channel quaternions would flip.
KEYS = [
    ((0, 0, 0), (0, 0, 0)),
    ((4, 0, 1), (0.3, 0, 2.0)),
    ((4, 3, 0), (0, 0.8, 3.6)),
    ((0, 3, 2), (1.2, 0, 5.0)),
    ((-2, 1, 0), (0, 0.4, 6.0)),
]
FRAMES = [1, 11, 21, 31, 41]


@pytest.fixture(scope="module", autouse=True)
def extension():
    assert ZIP.exists(), f"{ZIP}: build it with scripts/build-blender-extension.sh"
    done = bpy.ops.extensions.package_install_files(filepath=str(ZIP), repo="user_default", enable_on_install=True)
    assert done == {"FINISHED"}
    assert "bl_ext.user_default.screwbender" in bpy.context.preferences.addons
    yield


@pytest.fixture
def scene():
    """An empty scene (objects and actions removed), 24 frames per second."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for action in list(bpy.data.actions):
        bpy.data.actions.remove(action)
    s = bpy.context.scene
    s.render.fps, s.render.fps_base = 24, 1.0
    bpy.context.view_layer.update()
    return s


def keyed_cube(scene, keys=KEYS, frames=FRAMES, name="Cube"):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], [], [])
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    obj.rotation_mode = "XYZ"
    for (location, euler), f in zip(keys, frames):
        obj.location = location
        obj.rotation_euler = euler
        obj.keyframe_insert("location", frame=f)
        obj.keyframe_insert("rotation_euler", frame=f)
    select_only(obj)
    return obj


def select_only(obj):
    for other in bpy.context.scene.objects:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def key_rows(keys=KEYS):
    return np.array([list(loc) + list(Euler(e, "XYZ").to_quaternion()) for loc, e in keys])


def matrix(row):
    return np.array(Matrix.LocRotScale(row[:3], Quaternion(row[3:]), None))


def fcurves(obj):
    from bpy_extras import anim_utils

    anim = obj.animation_data
    return list(anim_utils.action_get_channelbag_for_slot(anim.action, anim.action_slot).fcurves)


def keyed_values(obj, path):
    """``(frames, values)``: the keys of ``path``'s F-curves, one column per channel."""
    curves = sorted((fc for fc in fcurves(obj) if fc.data_path == path), key=lambda fc: fc.array_index)
    frames = [kp.co[0] for kp in curves[0].keyframe_points]
    return np.array(frames), np.array([[kp.co[1] for kp in fc.keyframe_points] for fc in curves]).T


def snapshot(action):
    return [(fc.data_path, fc.array_index, [tuple(kp.co) for kp in fc.keyframe_points]) for fc in action.fcurves]


def check_smoothed(scene, obj, motion, knot_frames):
    count = int(knot_frames[-1] - knot_frames[0]) + 1
    frames = np.arange(count) + knot_frames[0]
    u = np.interp(frames, knot_frames, np.arange(len(knot_frames)))
    expected = motion.poses_at(u)
    worst = 0.0
    for f, row in zip(frames, expected):
        scene.frame_set(int(f))
        worst = max(worst, float(np.abs(np.array(obj.matrix_world) - matrix(row)).max()))
    assert worst <= TOL, f"matrix_world differs from poses_at by {worst:.3g}"
    key_frames, q = keyed_values(obj, "rotation_quaternion")
    assert list(key_frames) == list(frames), "a key at every frame"
    dots = np.einsum("ij,ij->i", q[1:], q[:-1])
    assert dots.min() > 0, f"quaternion sign flip between keys (dot {dots.min():.3g})"
    return worst


def test_smooth_motion_is_poses_at_at_every_frame(scene):
    import screwbender as sb

    obj = keyed_cube(scene)
    source = obj.animation_data.action
    before = snapshot(source)
    done = bpy.ops.screwbender.smooth_motion(scheme="fourpoint", levels=4, cycle=False, step=1)
    assert done == {"FINISHED"}
    assert obj.animation_data.action is not source and obj.animation_data.action["screwbender_source"] == source.name
    assert source.use_fake_user and snapshot(source) == before, "the original action is kept as it was"
    assert "UNDO" in bpy.types.SCREWBENDER_OT_smooth_motion.bl_options
    motion = sb.Motion(key_rows(), closed=False, scheme="fourpoint", levels=4)
    worst = check_smoothed(scene, obj, motion, np.array(FRAMES, float))
    print(f"open: largest difference {worst:.2e}")


def test_a_cycle_closes_on_a_repeated_first_key(scene):
    import screwbender as sb

    keys = KEYS[:4] + [KEYS[0]]
    obj = keyed_cube(scene, keys=[(k[0], k[1]) for k in keys[:4]] + [((0, 0, 0), (0, 0, 2 * np.pi))])
    assert bpy.ops.screwbender.smooth_motion(scheme="jarek", levels=3, cycle=True) == {"FINISHED"}
    motion = sb.Motion(key_rows(keys[:4]), closed=True, scheme="jarek", levels=3)
    worst = check_smoothed(scene, obj, motion, np.array(FRAMES, float))
    print(f"cycle: largest difference {worst:.2e}")


def test_export_then_import_gives_the_same_keys(scene, tmp_path):
    obj = keyed_cube(scene)
    path = tmp_path / "cube.json"
    assert bpy.ops.screwbender.export_motion(filepath=str(path), cycle=False, levels=4) == {"FINISHED"}
    doc = json.loads(path.read_text())
    assert len(doc["poses"]) == 5
    other = keyed_cube(scene, keys=KEYS[:2], frames=[100, 200], name="Other")
    assert bpy.ops.screwbender.import_motion(filepath=str(path)) == {"FINISHED"}
    frames, location = keyed_values(other, "location")
    _, rotation = keyed_values(other, "rotation_quaternion")
    assert list(frames) == FRAMES
    rows = key_rows()
    signs = np.sign(np.einsum("ij,ij->i", rotation, rows[:, 3:]))[:, None]
    assert np.abs(location - rows[:, :3]).max() < 1e-6
    assert np.abs(rotation - signs * rows[:, 3:]).max() < 1e-6
    assert bpy.context.scene.screwbender.cycle is False


def refused(match):
    before = {a.name: snapshot(a) for a in bpy.data.actions}
    with pytest.raises(RuntimeError, match=match):
        bpy.ops.screwbender.smooth_motion()
    assert {a.name: snapshot(a) for a in bpy.data.actions} == before, "nothing changed"


def test_a_single_key_is_reported(scene):
    keyed_cube(scene, keys=KEYS[:1], frames=[1], name="Lonely")
    refused(r"Lonely: 1 keyed frame of location or rotation .*at least 2")


def test_a_scaled_object_is_reported(scene):
    obj = keyed_cube(scene, name="Tall")
    obj.scale = (1, 1, 2)
    refused(r"Tall: scaled \(1, 1, 2\)")


@pytest.mark.parametrize("preset", ["l_cycle_rotated", "helix_open", "bunny6"])
def test_blenders_gltf_importer_plays_the_clis_glb(scene, tmp_path, preset):
    cli = os.environ.get("SCREWBENDER_CLI", str(ROOT / "target/debug/screwbender"))

    def run(*args):
        return subprocess.run([cli, *args], capture_output=True, text=True, check=True).stdout

    doc = tmp_path / "motion.json"
    doc.write_text(run("preset", preset))
    glb, csv = tmp_path / "motion.glb", tmp_path / "motion.csv"
    run("export", "--format", "glb", "--fps", "24", "-o", str(glb), str(doc))
    run("export", "--format", "csv", "--fps", "24", "-o", str(csv), str(doc))
    assert bpy.ops.import_scene.gltf(filepath=str(glb)) == {"FINISHED"}
    [obj] = [o for o in scene.objects if o.type == "MESH"]
    vertices = np.array([v.co for v in obj.data.vertices])
    far = vertices[np.argmax(np.linalg.norm(vertices, axis=1))]
    samples = np.loadtxt(csv, delimiter=",", skiprows=1)
    worst = 0.0
    for t, _u, x, y, z, qw, qx, qy, qz in samples:
        frame = t * 24
        scene.frame_set(int(np.floor(frame)), subframe=float(frame - np.floor(frame)))
        got = np.array(obj.matrix_world @ Vector(far.tolist()))
        # The CLI's pose is glTF's Y-up frame; Blender's importer turns it Z-up: (x, y, z) -> (x, -z, y).
        local = np.array([far[0], far[2], -far[1]])
        world = np.array(Quaternion((qw, qx, qy, qz)).to_matrix()) @ local + (x, y, z)
        want = np.array([world[0], -world[2], world[1]])
        worst = max(worst, float(np.abs(got - want).max()))
    assert len(samples) > 24 and worst <= 1e-4, f"{preset}: farthest vertex off by {worst:.3g}"
    print(f"{preset}: {len(samples)} samples, largest difference {worst:.2e}")


def velocity_changes(points, every):
    """The length of the second difference of every ``every``-th point: at each inner sample,
    how much the path's velocity per step changes there."""
    p = np.array([tuple(v) for v in points])[::every]
    return np.linalg.norm(p[2:] - 2 * p[1:-1] + p[:-2], axis=1)


def test_the_readme_pictures_script_draws_the_smoothed_path(scene, tmp_path):
    """blender/tools/readme-pictures.py (run by hand for blender/README.md) at a tiny size: its
    three pictures are written, and the box corner's path after *Smooth motion* passes through
    the keyed positions as before, without the kinks that Blender's linear keys have there."""
    path = ROOT / "blender/tools/readme-pictures.py"
    spec = importlib.util.spec_from_file_location("readme_pictures", path)
    pictures = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(pictures)
    before, after = pictures.make(tmp_path, width=32, height=18, samples=1)
    for name in ("smooth-before.png", "smooth-after.png", "smooth-paths.png"):
        assert (tmp_path / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
    at_keys = [(f - pictures.FRAMES[0]) * pictures.PATH_SAMPLES for f in pictures.FRAMES]
    off = max((before[i] - after[i]).length for i in at_keys)
    assert off < 1e-4, f"the smoothed path misses a keyed corner position by {off:.3g}"
    # At whole frames (what Blender plays): Blender's interpolation changes the corner's
    # velocity at once at a key; after smoothing, the change there is less than half of that.
    change_before = velocity_changes(before, pictures.PATH_SAMPLES)
    change_after = velocity_changes(after, pictures.PATH_SAMPLES)
    inner = [f - pictures.FRAMES[0] - 1 for f in pictures.FRAMES[1:-1]]
    ratios = change_after[inner] / change_before[inner]
    assert ratios.max() < 0.5, f"velocity change at the keys, after / before: {ratios.round(2)}"
    print(f"pictures: velocity change at the keys after / before: {ratios.round(2)}")

"""The pictures of blender/README.md: a keyed box's motion before and after *Smooth motion*,
rendered by Blender (Cycles, on the CPU) from the extension's own result.

Headless Blender (``bpy``) has no window, so its user interface cannot be captured: the
pictures show what the operator does to a motion, not the panel. A box is keyed at five poses
(Euler rotation keys with linear interpolation, so Blender's motion has a corner at every key);
the extension's zip is installed with Blender's own installer, as the tests do, and its
*Smooth motion* runs on the box with the panel's settings (4-point, 5 levels), as the panel's
button runs it. Every ghost and curve drawn is the box as Blender evaluates its action at a
frame: nothing is computed here but the camera and the colours.

* ``smooth-before.png``: the keyed motion as Blender interpolates it: a ghost of the box every
  other frame (the keys opaque and grey) and the path of one corner of the box (orange);
* ``smooth-after.png``: the same after *Smooth motion* (blue);
* ``smooth-paths.png``: the two paths of that corner over each other, with the keyed poses.

The pictures are quantised with pngquant when it is installed (Debian: pngquant).

Run with the Blender environment's Python (scripts/blender-env.sh) after building the zip
(scripts/build-blender-extension.sh), from the repository's root::

    .venv-blender/bin/python blender/tools/readme-pictures.py \\
        [--zip artifacts/blender/screwbender-0.1.0.zip] [--out blender/docs] \\
        [--width 960] [--height 540] [--samples 24]
"""

import argparse
import os
import pathlib
import shutil
import subprocess
import tempfile

# Blender reads its user folder at import: a throwaway one, so that installing the extension
# leaves the user's own Blender alone.
os.environ.setdefault("BLENDER_USER_RESOURCES", tempfile.mkdtemp(prefix="screwbender-pictures-"))

import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]

#: The key poses: location and Euler rotation (XYZ, radians) at frames 1, 11, …, 41; turns of up
#: to two radians between keys, about changing axes, so that the kinks are plain to see.
KEYS = [
    ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
    ((3.0, 0.0, 1.0), (0.3, 0.0, 2.0)),
    ((3.0, 2.5, 0.3), (0.0, 0.8, 3.6)),
    ((0.0, 2.5, 1.4), (1.2, 0.0, 5.0)),
    ((-2.0, 1.0, 0.4), (0.0, 0.4, 6.0)),
]
FRAMES = [1, 11, 21, 31, 41]
#: The box's half sizes, and the body point whose path is drawn (a corner).
HALF = (0.7, 0.25, 0.12)
CORNER = Vector(HALF)
#: A ghost every this many frames.
GHOST_EVERY = 2
#: Path samples per frame (Blender evaluates the action at sub-frames).
PATH_SAMPLES = 4
KEY_GREY = (0.25, 0.25, 0.27, 1.0)
BEFORE = (0.95, 0.30, 0.02, 1.0)
AFTER = (0.02, 0.25, 0.90, 1.0)


def material(name, colour, alpha=1.0):
    """A Principled BSDF material of one colour (``alpha`` < 1: see-through ghosts)."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = colour
    bsdf.inputs["Alpha"].default_value = alpha
    bsdf.inputs["Roughness"].default_value = 0.6
    return mat


def clear_scene():
    """Removes every object, collection, action, material, mesh and curve (the start-up file's
    and an earlier ``make``'s)."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for block in (bpy.data.collections, bpy.data.actions, bpy.data.materials, bpy.data.meshes, bpy.data.curves):
        for item in list(block):
            block.remove(item)


def keyed_box(scene):
    """The box, keyed at ``KEYS`` with linear interpolation, selected and active."""
    hx, hy, hz = HALF
    mesh = bpy.data.meshes.new("Box")
    corners = [(x, y, z) for x in (-hx, hx) for y in (-hy, hy) for z in (-hz, hz)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh.from_pydata(corners, [], faces)
    obj = bpy.data.objects.new("Box", mesh)
    scene.collection.objects.link(obj)
    obj.rotation_mode = "XYZ"
    for (location, euler), frame in zip(KEYS, FRAMES):
        obj.location = location
        obj.rotation_euler = euler
        obj.keyframe_insert("location", frame=frame)
        obj.keyframe_insert("rotation_euler", frame=frame)
    for fc in fcurves(obj):
        for kp in fc.keyframe_points:
            kp.interpolation = "LINEAR"
    for other in scene.objects:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    return obj


def fcurves(obj):
    """The F-curves of the object's action (Blender 4.4 keeps them per slot)."""
    from bpy_extras import anim_utils

    anim = obj.animation_data
    return list(anim_utils.action_get_channelbag_for_slot(anim.action, anim.action_slot).fcurves)


def poses(scene, obj, frames):
    """The object's world matrix at each frame (float: sub-frames too), as Blender evaluates it."""
    out = []
    for f in frames:
        whole = int(f // 1)
        scene.frame_set(whole, subframe=float(f - whole))
        out.append(obj.matrix_world.copy())
    return out


def path_frames():
    count = (FRAMES[-1] - FRAMES[0]) * PATH_SAMPLES + 1
    return [FRAMES[0] + i / PATH_SAMPLES for i in range(count)]


def ghosts(scene, obj, name, colour, collection):
    """Copies of the box at every ``GHOST_EVERY`` frames: see-through in
    ``colour`` between the keys, opaque grey at them."""
    between = material(f"{name} ghost", colour, alpha=0.45)
    keyed = material(f"{name} key", KEY_GREY)
    frames = range(FRAMES[0], FRAMES[-1] + 1, GHOST_EVERY)
    for frame, matrix in zip(frames, poses(scene, obj, frames)):
        ghost = bpy.data.objects.new(f"{name} {frame}", obj.data.copy())
        ghost.data.materials.append(keyed if frame in FRAMES else between)
        ghost.matrix_world = matrix
        collection.objects.link(ghost)


def key_poses(scene, obj, collection):
    """Opaque grey copies of the box at its keys."""
    keyed = material("key", KEY_GREY)
    for frame, matrix in zip(FRAMES, poses(scene, obj, FRAMES)):
        ghost = bpy.data.objects.new(f"key {frame}", obj.data.copy())
        ghost.data.materials.append(keyed)
        ghost.matrix_world = matrix
        collection.objects.link(ghost)


def corner_path(scene, obj, name, colour, collection, radius=0.045):
    """A thin tube through the box's ``CORNER`` at every sample of ``path_frames``."""
    points = [m @ CORNER for m in poses(scene, obj, path_frames())]
    curve = bpy.data.curves.new(name, type="CURVE")
    curve.dimensions = "3D"
    curve.bevel_depth = radius
    curve.bevel_resolution = 3
    spline = curve.splines.new("POLY")
    spline.points.add(len(points) - 1)
    for point, p in zip(spline.points, points):
        point.co = (p.x, p.y, p.z, 1.0)
    curve.materials.append(material(name, colour))
    path = bpy.data.objects.new(name, curve)
    collection.objects.link(path)
    return points


def stage(scene):
    """Floor, lights, camera and Cycles' settings."""
    floor_mesh = bpy.data.meshes.new("Floor")
    s = 30.0
    floor_mesh.from_pydata([(-s, -s, 0), (s, -s, 0), (s, s, 0), (-s, s, 0)], [], [(0, 1, 2, 3)])
    floor_mesh.materials.append(material("Floor", (0.8, 0.8, 0.78, 1.0)))
    floor = bpy.data.objects.new("Floor", floor_mesh)
    floor.location.z = -1.0
    scene.collection.objects.link(floor)

    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", type="SUN"))
    sun.data.energy = 3.0
    sun.data.angle = 0.2
    sun.rotation_euler = (0.5, 0.2, 0.6)
    scene.collection.objects.link(sun)

    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.8
    scene.world = world

    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    camera.data.lens = 40
    target = Vector((0.5, 1.2, 0.4))
    camera.location = target + Vector((3.2, -9.0, 6.5))
    camera.rotation_euler = (target - camera.location).to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(camera)
    scene.camera = camera

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    import _cycles  # Cycles' own module: says whether this build has OpenImageDenoise

    scene.cycles.use_denoising = bool(getattr(_cycles, "with_openimagedenoise", False))
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "8"
    scene.render.image_settings.compression = 100


def render(scene, collection, path):
    """Renders with only ``collection`` of the drawn things visible; writes ``path``."""
    for other in bpy.data.collections:
        other.hide_render = other is not collection
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    optimise(path)
    print(f"wrote {path} ({path.stat().st_size} B)")


def optimise(path):
    """Quantises the picture to a palette with pngquant (Debian: pngquant): a fraction of the
    size of Blender's own PNG with no difference to see; without pngquant it is left as it is."""
    if shutil.which("pngquant") is None:
        print("pngquant not found: the picture is Blender's PNG, not quantised")
        return
    subprocess.run(
        ["pngquant", "--quality", "80-95", "--speed", "1", "--strip", "--force", "--ext", ".png", str(path)],
        check=True,
    )


def make(out, width=960, height=540, samples=24):
    """Builds the scene, smooths the box with the installed extension and writes the three
    pictures into ``out``. Returns the two corner paths (before, after) as lists of vectors."""
    scene = bpy.context.scene
    clear_scene()
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.cycles.samples = samples
    stage(scene)
    obj = keyed_box(scene)
    obj.hide_render = True

    def drawn(name):
        collection = bpy.data.collections.new(name)
        scene.collection.children.link(collection)
        return collection

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    before, after, both = drawn("before"), drawn("after"), drawn("paths")
    ghosts(scene, obj, "before", BEFORE, before)
    path_before = corner_path(scene, obj, "path before", BEFORE, before)
    corner_path(scene, obj, "path before, over", BEFORE, both)
    key_poses(scene, obj, both)

    # The panel's button: the operator invoked with the scene's settings.
    done = bpy.ops.screwbender.smooth_motion("INVOKE_DEFAULT")
    if done != {"FINISHED"} or not obj.animation_data.action.get("screwbender_source"):
        raise RuntimeError(f"Smooth motion did not smooth the box: {done}")

    ghosts(scene, obj, "after", AFTER, after)
    path_after = corner_path(scene, obj, "path after", AFTER, after)
    corner_path(scene, obj, "path after, over", AFTER, both)

    render(scene, before, out / "smooth-before.png")
    render(scene, after, out / "smooth-after.png")
    render(scene, both, out / "smooth-paths.png")
    return path_before, path_after


def install(zip_path):
    """Installs and enables the extension's zip with Blender's own installer."""
    done = bpy.ops.extensions.package_install_files(filepath=str(zip_path), repo="user_default", enable_on_install=True)
    if done != {"FINISHED"}:
        raise RuntimeError(f"{zip_path}: Blender did not install it: {done}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--zip", default=ROOT / "artifacts/blender/screwbender-0.1.0.zip", type=pathlib.Path)
    parser.add_argument("--out", default=ROOT / "blender/docs", type=pathlib.Path)
    parser.add_argument("--width", type=int, default=960)
    parser.add_argument("--height", type=int, default=540)
    parser.add_argument("--samples", type=int, default=24)
    args = parser.parse_args()
    if not args.zip.exists():
        parser.error(f"{args.zip}: build it with scripts/build-blender-extension.sh")
    install(args.zip)
    make(args.out, args.width, args.height, args.samples)


if __name__ == "__main__":
    main()

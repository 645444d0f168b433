"""ScrewBender: smooth rigid-body motions by screw subdivision, on numpy arrays.

Control poses (a cycle or an open sequence) are smoothed by Split&Tweak subdivision on screws
(A. Powell and J. Rossignac, *ScrewBender: Polyscrew Subdivision for Smoothing Interpolating
Motions*): cubic B-spline, 4-point and Jarek schemes, the revised paper's ``"direct"`` rules and
the first version's split-then-tweak rules (id ``"split"``), and the J_s family (parameter
``s``). :func:`compare_methods` measures the other methods of the comparison on the same poses,
as ``screwbender compare --json``; :func:`method_poses` evaluates one of them. :func:`fit`
fits a smooth motion to many measured poses, as ``screwbender fit``; :func:`measure_fit` measures
any motion against them.

Poses are numpy arrays: ``(n, 7)`` rows ``x y z qw qx qy qz`` (quaternions scalar first) or
``(n, 4, 4)`` homogeneous matrices, accepted everywhere a pose array is (so ``modern_robotics``,
``spatialmath`` (``.A``) and ``pytransform3d`` matrices pass straight in). Angles are radians,
frames right-handed; ``screw(a, t, b)`` is the pose after the fraction ``t`` of the screw motion
from ``a`` to ``b``.

>>> import numpy as np, screwbender as sb
>>> m = sb.Motion.from_preset("circle4", levels=3)
>>> m.subdivide().shape
(32, 7)

Bad input raises ``ValueError`` (wrong values, wrong shapes) or ``TypeError`` (wrong types)
whose message names the element (``poses[3].rotation: zero quaternion``); a ``Motion`` that
refused a change keeps its previous state. The notebook figure is :class:`Figure` (needs
``anywidget``).
"""

from typing import TYPE_CHECKING

from ._screwbender import (
    MAX_REFINED_POSES,
    Motion,
    __version__,
    compare_methods,
    fit,
    measure_fit,
    method_poses,
    preset_descriptions,
    preset_display,
    presets,
    screw,
)

__all__ = [
    "MAX_REFINED_POSES",
    "Figure",
    "Motion",
    "__version__",
    "compare_methods",
    "fit",
    "measure_fit",
    "method_poses",
    "preset_descriptions",
    "preset_display",
    "presets",
    "screw",
]

if TYPE_CHECKING:
    from ._figure import Figure


def __getattr__(name: str):
    # The figure imports anywidget (and with it ipywidgets): only when it is asked for, so the
    # math works without the notebook packages installed.
    if name == "Figure":
        from ._figure import Figure

        return Figure
    raise AttributeError(f"module 'screwbender' has no attribute {name!r}")

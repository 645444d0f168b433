"""The options the notebook figure shares with the ``<screw-bender>`` element, as traitlets
synchronised with its front end (which reads the same list, python/widget/figure.js).

Written by scripts/element-api.mjs from the element's declarations
(www/js/element/features.js and the files it names): edit those, not this file.
"""

from __future__ import annotations

import anywidget
import traitlets


class FigureOptions(anywidget.AnyWidget):
    """The element's options that :class:`~screwbender.Figure` synchronises (checked by the figure)."""

    #: ``webgl2`` skips WebGPU (mount() only; without it WebGPU where the browser has a usable
    #: adapter, else WebGL2).
    backend = traitlets.Enum([None, "webgl2"], None, allow_none=True).tag(sync=True)

    #: The subdivision scheme.
    scheme = traitlets.Unicode(None, allow_none=True).tag(sync=True)

    #: The J_s parameter ``s``, -4 to 4 (implies scheme ``j``).
    s = traitlets.Float(None, allow_none=True).tag(sync=True)

    #: The rule set: ``direct``, or the first version's split-then-tweak (``split``).
    rules = traitlets.Unicode("direct").tag(sync=True)

    #: Subdivision levels, 0 to 19.
    levels = traitlets.Int(None, allow_none=True).tag(sync=True)

    #: Copies of the object drawn along the motion, 0 to 20000.
    strobe = traitlets.Int(None, allow_none=True).tag(sync=True)

    #: Layers shown, space separated: strobe control trajectories polyscrew polygon triads grid.
    show = traitlets.Unicode(None, allow_none=True).tag(sync=True)

    #: The figure's chrome: none, minimal (play, scrub, time) or full (plus scheme, levels, frame).
    controls = traitlets.Unicode(None, allow_none=True).tag(sync=True)

    #: Colours of the chrome, frame and 3-D view.
    theme = traitlets.Unicode(None, allow_none=True).tag(sync=True)

    #: Select and drag poses with the gizmo (off: orbit, play and scrub only).
    editable = traitlets.Bool(True).tag(sync=True)

    #: ``iso``, ``front``, ``side``, ``top``, ``"yaw pitch [distance]"`` or ``"yaw pitch distance tx
    #: ty tz"`` (degrees, scene units; the last three the point looked at) as an attribute; as a
    #: property, the camera as state (radians, scene units).
    camera = traitlets.Unicode(None, allow_none=True).tag(sync=True)

    #: Play from the start.
    autoplay = traitlets.Bool(False).tag(sync=True)

"""The notebook figure :class:`Figure`: an anywidget whose front end is the project's own viewer
(the ``<screw-bender>`` element's figure: WebGPU, with the WebGL2 fallback), bundled into
``static/figure.js`` with the renderer's WebAssembly modules.

The bundle (one self-contained ES module, about 5.2 MB with the wasm inlined) is what a figure
needs in the browser; what each figure carries is small:

* live, each figure's own ES module is ``static/loader.js``, which imports the bundle from one
  asset model per kernel (:class:`_Assets`) that every figure references: the bundle crosses the
  comm once per kernel, a saved widget state holds it once, and a page evaluates it once (one
  wasm instance and one WebGPU device for every figure);
* in static pages (the figures' ``text/html`` copies, nbconvert), the first figure shown in a
  kernel carries the bundle and the others start from it: an executed notebook and its HTML
  export hold it once. :meth:`Figure.to_html` always carries it (a fragment that stands alone).

Both work unchanged wherever the widget is shown (JupyterLab, Notebook 7, VS Code) and from
``file://``, with no server, CDN or network.
"""

from __future__ import annotations


import json
import pathlib
import uuid
from typing import Any, Optional, Union

import ipywidgets
import numpy as np
import traitlets

from ._figure_options import FigureOptions
from ._screwbender import Motion

_STATIC = pathlib.Path(__file__).parent / "static"
_BUNDLE = _STATIC / "figure.js"
_LOADER = _STATIC / "loader.js"


def _poses_to_json(value: Any, widget: Any) -> Any:
    return None if value is None else np.asarray(value, dtype=np.float64).tolist()


def _poses_from_json(value: Any, widget: Any) -> Any:
    return None if value is None else np.asarray(value, dtype=np.float64).reshape(-1, 7)


def _bundle() -> str:
    if not _BUNDLE.exists():
        raise RuntimeError(
            f"{_BUNDLE} is missing: this build of screwbender has no notebook figure "
            "(build it with python/build-figure.sh before the wheel)"
        )
    return _BUNDLE.read_text(encoding="utf-8")


class _Assets(ipywidgets.Widget):
    """The viewer bundle (``static/figure.js``) as a widget model without a view: one per kernel
    (:func:`_shared_assets`), referenced by every :class:`Figure`."""

    code = traitlets.Unicode("").tag(sync=True)


_assets: Optional[_Assets] = None


def _shared_assets() -> Optional[_Assets]:
    """The kernel's asset model (made again if it was closed), ``None`` without a bundle."""
    global _assets
    if not _BUNDLE.exists():
        return None
    if _assets is None or _assets.comm is None:
        _assets = _Assets(code=_bundle())
    return _assets


def _execution() -> tuple:
    """``(cell id, request id)`` of the code the kernel is running (``None`` where unknown:
    outside a kernel, or a client that does not name its cells)."""
    try:
        from IPython import get_ipython

        kernel = getattr(get_ipython(), "kernel", None)
        parent = kernel.get_parent() if kernel is not None else {}
    except Exception:  # no IPython, or a kernel without get_parent: nothing is known
        parent = {}
    return (parent.get("metadata") or {}).get("cellId"), (parent.get("header") or {}).get("msg_id")


class _StaticCopies:
    """Which figure output carries the bundle in its static copy: the first one shown in the
    kernel, and again the next one of the same cell run anew (its new outputs replace the old)."""

    #: ``(cell id, request id)`` of the output that carries it, ``None`` before the first.
    carrier: Optional[tuple] = None

    @classmethod
    def take(cls) -> bool:
        """Whether the figure being shown now carries the bundle (and then it is the carrier)."""
        cell, request = _execution()
        if cls.carrier is None or (cell is not None and cls.carrier[0] == cell and cls.carrier[1] != request):
            cls.carrier = (cell, request)
            return True
        return False


class Figure(FigureOptions):
    """A live 3-D figure of a motion in a notebook, with two-way sync.

    ``Figure(m_or_P, editable=True, scheme=..., levels=..., show=..., strobe=..., camera=...)``:
    ``m_or_P`` is a :class:`Motion` (its poses and options) or a pose array (``(n, 7)`` or
    ``(n, 4, 4)``). Setting ``fig.poses`` or an option from Python redraws the figure; dragging
    a control pose in an ``editable`` figure updates ``fig.poses`` in the kernel and fires
    ``fig.observe(callback, names="poses")``. ``fig.motion`` is the :class:`Motion` of what the
    figure shows. Bad values raise ``ValueError`` / ``TypeError`` naming the option or pose, and
    the figure keeps its state.

    Options: ``closed``; ``scheme`` (``"bspline"``, ``"fourpoint"``, ``"jarek"``) or ``s`` (the
    J_s family); ``levels`` (0 to 19, as everywhere); ``rules`` (``"direct"``,
    ``"split"``); ``show`` (layers: ``"strobe control trajectories polyscrew polygon
    triads grid"``); ``strobe`` (copies of the object); ``camera`` (``"iso"``, ``"front"``,
    ``"side"``, ``"top"`` or ``"yaw pitch [distance]"`` in degrees); ``autoplay``;
    ``controls`` (``"none"``, ``"minimal"``, ``"full"``); ``theme`` (``"light"``, ``"dark"``);
    ``height`` in pixels; ``backend`` ``"webgl2"`` to skip WebGPU.

    Exported pages: the figure's display data carries a static copy (``text/html``, as
    :meth:`to_html`), which ``jupyter nbconvert --to html`` uses when the notebook has no saved
    widget state: the exported page draws the figure live from ``file://`` with no kernel and no
    network (orbit, play, drag). The first figure shown in a kernel carries the viewer (about
    5.2 MB) in its copy and the others a few kilobytes that start from it; set
    ``Figure.embed_static = False`` to leave the copies out.
    """

    # The module's text, not its path: a path makes anywidget watch the file for changes.
    _esm = _LOADER.read_text(encoding="utf-8") if _LOADER.exists() else "export default { render() {} };"
    #: The kernel's one asset model holding the viewer bundle (see the module doc).
    _assets = traitlets.Instance(_Assets, allow_none=True).tag(sync=True, **ipywidgets.widget_serialization)

    #: Whether the display data carries the static copy of the figure (see the class doc).
    embed_static = True

    poses = traitlets.Any(None, allow_none=True).tag(
        sync=True, to_json=_poses_to_json, from_json=_poses_from_json
    )
    # The element's options (scheme, s, levels, rules, show, strobe, camera, editable, autoplay,
    # controls, theme, backend) are FigureOptions' traitlets; these are the notebook's own.
    closed = traitlets.Bool(True).tag(sync=True)
    name = traitlets.Unicode(None, allow_none=True).tag(sync=True)
    height = traitlets.Int(420).tag(sync=True)

    def __init__(
        self,
        m_or_P: Union[Motion, Any],
        *,
        editable: bool = True,
        scheme: Optional[str] = None,
        levels: Optional[int] = None,
        show: Optional[str] = None,
        strobe: Optional[int] = None,
        camera: Optional[str] = None,
        closed: Optional[bool] = None,
        rules: Optional[str] = None,
        s: Optional[float] = None,
        **kwargs: Any,
    ) -> None:
        if isinstance(m_or_P, Motion):
            m = m_or_P.copy()
            if closed is not None:
                m.closed = closed
        else:
            m = Motion(m_or_P, closed=True if closed is None else closed)
        if scheme is not None:
            m.scheme = scheme
        if s is not None:
            m.s = s
        if rules is not None:
            m.rules = rules
        if levels is not None:
            m.levels = levels
        if strobe is not None and (isinstance(strobe, bool) or not isinstance(strobe, (int, np.integer)) or not 0 <= strobe <= 20000):
            raise ValueError(f"strobe: {strobe!r} is out of range (expected a whole number 0 to 20000)")
        self.errors: list = []
        super().__init__(
            _assets=_shared_assets(),
            poses=m.poses,
            closed=m.closed,
            name=m.name,
            scheme=None if m.scheme == "j" else m.scheme,
            s=m.s if m.scheme == "j" else None,
            levels=m.levels,
            rules=m.rules,
            editable=editable,
            show=show,
            strobe=strobe,
            camera=camera,
            **kwargs,
        )
        self.on_msg(self._on_front_end_message)

    # ---- validation: every change is checked as a Motion before it is taken ------------------

    def _motion_with(self, **change: Any) -> Motion:
        state = dict(
            poses=self.poses, closed=self.closed, scheme=self.scheme, s=self.s,
            levels=self.levels, rules=self.rules,
        )
        state.update(change)
        if state["poses"] is None:
            raise ValueError("poses: a figure needs control poses")
        if state["s"] is not None:
            state["scheme"] = None
        return Motion(
            state["poses"], closed=state["closed"], scheme=state["scheme"], s=state["s"],
            levels=state["levels"], rules=state["rules"], name=self.name,
        )

    @traitlets.validate("poses")
    def _valid_poses(self, proposal: Any) -> Any:
        if self.poses is None:  # the constructor's value, checked there
            return Motion(proposal["value"], closed=self.closed).poses
        return self._motion_with(poses=proposal["value"]).poses

    @traitlets.validate("scheme", "s", "levels", "rules", "closed")
    def _valid_option(self, proposal: Any) -> Any:
        if self.poses is not None:
            name = proposal["trait"].name
            change = {name: proposal["value"]}
            if name == "scheme" and proposal["value"] is not None:
                change["s"] = None
            m = self._motion_with(**change)
            if name == "rules":
                # The id the Motion reports (an alias such as "split-then-tweak" becomes
                # "split"), so that the figure and its page hold one name per rule set.
                return m.rules
        return proposal["value"]

    @traitlets.observe("scheme")
    def _scheme_clears_s(self, change: Any) -> None:
        if change["new"] is not None and self.s is not None:
            self.s = None

    # ---- what the figure shows -----------------------------------------------------------------

    @property
    def motion(self) -> Motion:
        """The :class:`Motion` of the figure's poses and options (a copy)."""
        return self._motion_with()

    def _on_front_end_message(self, widget: Any, content: Any, buffers: Any) -> None:
        if isinstance(content, dict) and content.get("type") == "error":
            self.errors.append(content)

    # ---- static pages --------------------------------------------------------------------------

    def _state_for_page(self) -> dict:
        keys = ["closed", "name", "scheme", "s", "levels", "rules", "editable", "show",
                "strobe", "camera", "autoplay", "controls", "theme", "height", "backend"]
        state = {k: getattr(self, k) for k in keys}
        state["poses"] = _poses_to_json(self.poses, self)
        return state

    def to_html(self) -> str:
        """A self-contained HTML fragment that draws this figure live in any page, with no
        kernel and no network (opened from ``file://`` too): the figure's bundle and wasm
        (about 5.2 MB) and its current poses and options. Changes in it stay in the page."""
        return self._static_copy(with_bundle=True)

    def _static_copy(self, with_bundle: bool) -> str:
        """The figure as HTML, starting from the page's bundle: its own copy (``with_bundle``),
        or one that another figure's copy in the same page brings, before or after it."""
        fig_id = f"screwbender-{uuid.uuid4().hex}"
        state = json.dumps(self._state_for_page()).replace("</", "<\\/")
        bundle = ""
        if with_bundle:
            code = _bundle().replace("</script", "<\\/script")
            bundle = f'<script type="module">{code}\n</script>\n'
        return (
            f'<div id="{fig_id}" class="screwbender-static" style="width:100%"></div>\n'
            f"{bundle}"
            '<script type="module">\n'
            f"const state = {state};\n"
            f"const el = document.getElementById({json.dumps(fig_id)});\n"
            "const listeners = {};\n"
            "const model = {\n"
            "  get: (k) => state[k],\n"
            "  set: (k, v) => { state[k] = v; },\n"
            "  save_changes() {}, send() {},\n"
            "  on: (e, f) => { (listeners[e] ??= []).push(f); },\n"
            "  off() {},\n"
            "};\n"
            "const render = globalThis[Symbol.for('screwbender.figure.render')];\n"
            "if (render) render({ model, el });\n"
            "else {\n"
            "  let started = false;\n"
            "  (globalThis[Symbol.for('screwbender.figure.waiting')] ??= []).push((r) => { started = true; r({ model, el }); });\n"
            "  addEventListener('load', () => {\n"
            "    if (!started) el.textContent = 'This figure draws with the viewer that the first figure of the notebook '\n"
            "      + 'brings, and this page has none: run the notebook again before exporting it.';\n"
            "  });\n"
            "}\n"
            "</script>\n"
        )

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        bundle = super()._repr_mimebundle_(**kwargs)
        if not self.embed_static:
            return bundle
        data, metadata = bundle if isinstance(bundle, tuple) else (bundle, {})
        data = dict(data)
        data["text/html"] = self._static_copy(with_bundle=_StaticCopies.take())
        return data, metadata

    def __repr__(self) -> str:
        n = 0 if self.poses is None else len(self.poses)
        return f"Figure({n} poses, closed={self.closed}, levels={self.levels}, editable={self.editable})"


__all__ = ["Figure"]


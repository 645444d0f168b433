"""The notebook figure in marimo: the example notebook (examples/notebooks/screw-figure.py) runs
headless in marimo's runtime (`marimo export html`), its cells reading the figure's poses, and
marimo's anywidget host carries the figure's state both ways.

Not checked here: the figure drawing inside marimo's page (marimo's exported page loads marimo's
front end from a CDN, which the tests cannot reach); the figure's drawing itself is checked in
static pages and JupyterLab (test_figure.py, test_jupyterlab.py)."""

import subprocess
import sys

import numpy as np
import pytest

import screwbender as sb
from conftest import ROOT

# marimo is in .venv (python/requirements-dev.txt), where this file runs; the clean venvs of the
# wheel's CPython checks leave this file out (scripts/test.d/python.sh).
mo = pytest.importorskip("marimo")

NOTEBOOK = ROOT / "examples" / "notebooks" / "screw-figure.py"


def test_the_marimo_notebook_runs_headless(tmp_path):
    out = tmp_path / "screw-figure.html"
    done = subprocess.run(
        [sys.executable, "-m", "marimo", "export", "html", str(NOTEBOOK), "-o", str(out)],
        capture_output=True, text=True, timeout=600, check=False,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    page = out.read_text(encoding="utf-8")
    assert "marimo-anywidget" in page, "the figure's cell shows marimo's anywidget element"
    # The last cell's text, computed from the figure's poses: as the package computes it.
    path = sb.Motion.from_preset("l_cycle_rotated", levels=4).subdivide()[:, :3]
    length = float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum())
    assert f"origin travels {length:.3f} units" in page


def test_marimos_anywidget_host_carries_the_state_both_ways():
    motion = sb.Motion.from_preset("l_cycle_rotated", levels=3)
    figure = mo.ui.anywidget(sb.Figure(motion, editable=True))
    state = figure.value
    assert np.array_equal(np.asarray(state["poses"]), motion.poses)
    assert state["levels"] == 3 and state["editable"] is True
    # A drag in the front end arrives as a state update (what marimo's element sends).
    moved = np.array(motion.poses)
    moved[1, :3] += (0.5, -0.25, 0.125)
    figure._convert_value({"poses": moved.tolist()})
    assert isinstance(figure.widget.poses, np.ndarray) and figure.widget.poses.shape == moved.shape
    assert np.array_equal(figure.widget.poses, moved)
    assert np.array_equal(np.asarray(figure.value["poses"]), moved)

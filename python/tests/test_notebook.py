"""The course notebook (examples/notebooks/screw-course.ipynb) runs top to bottom in a kernel
(nbclient), and its nbconvert HTML export draws the figure from file:// with no network.

The notebook is executed without storing the widget state, as JupyterLab saves a notebook by
default: then nbconvert exports the figure's static copy (`text/html`). With a stored widget
state nbconvert would use the widget view instead, whose page loads the widget manager from a
CDN (python/README.md says how to export such a notebook)."""

import json

import nbformat
import pytest
from nbclient import NotebookClient
from nbconvert import HTMLExporter

from conftest import ROOT
from test_figure import SHOTS, WASM, needs_bundle, run_static_page

NOTEBOOK = ROOT / "examples" / "notebooks" / "screw-course.ipynb"


@pytest.fixture(scope="module")
def executed():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3", store_widget_state=False, resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    return nb


def test_the_course_notebook_runs(executed):
    outputs = [o for c in executed.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.output_type == "error"]
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "largest difference from ScrewTrajectory" in text
    # A former name (e.g. `kinematics` for `kinematics_at`) warns on the cell's line, which a
    # kernel prints to the cell's stderr: the course teaches the current names only.
    assert "DeprecationWarning" not in text
    assert any("image/png" in o.get("data", {}) for o in outputs), "the speed plot"
    assert any("application/vnd.jupyter.widget-view+json" in o.get("data", {}) for o in outputs), "the figure"


@needs_bundle
def test_its_html_export_draws_offline(executed, tmp_path):
    body, _ = HTMLExporter().from_notebook_node(executed)
    page = tmp_path / "screw-course.html"
    page.write_text(body, encoding="utf-8")
    SHOTS.mkdir(parents=True, exist_ok=True)
    result = run_static_page(page, "webgl2", SHOTS / "nbconvert-webgl2.png")
    assert result["problems"] == []
    # nbconvert's page links its own fonts and require.js from a CDN: those fail offline and
    # change nothing; the figure itself needs none of them.
    assert result["figures"] == 1 and result["nonBackground"] > 0.05
    print(f"exported page: {page.stat().st_size / 1e6:.1f} MB")


THREE_FIGURES = [
    "import screwbender as sb",
    "sb.Figure(sb.Motion.from_preset('circle4', levels=3), camera='iso', height=300)",
    "sb.Figure(sb.Motion.from_preset('l_cycle_rotated', levels=3), camera='iso', height=300)",
    "sb.Figure(sb.Motion.from_preset('l_cycle_parallel', levels=3), camera='iso', height=300)",
]


def run_cells(cells, store_widget_state):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in cells]
    NotebookClient(nb, timeout=300, kernel_name="python3", store_widget_state=store_widget_state).execute()
    assert not [o for c in nb.cells for o in c.outputs if o.output_type == "error"]
    return nb


@needs_bundle
def test_three_figures_hold_the_viewer_once(tmp_path):
    one, three = run_cells(THREE_FIGURES[:2], True), run_cells(THREE_FIGURES, True)
    sizes = {}
    for name, nb in [("1 figure", one), ("3 figures", three)]:
        state = json.dumps(nb.metadata["widgets"])
        text = nbformat.writes(nb)
        # The saved widget state holds the viewer (two wasm modules) once, in the asset model; the
        # outputs once more, in the first figure's static copy.
        assert state.count(WASM) == 2 and text.count(WASM) == 4, name
        sizes[name] = (len(text), len(state))
    # Two more figures add their poses and options, not another viewer.
    assert sizes["3 figures"][0] - sizes["1 figure"][0] < 100e3, sizes
    plain = run_cells(THREE_FIGURES, False)
    body, _ = HTMLExporter().from_notebook_node(plain)
    assert body.count(WASM) == 2
    page = tmp_path / "three.html"
    page.write_text(body, encoding="utf-8")
    result = run_static_page(page, "webgl2", SHOTS / "nbconvert-three-webgl2.png")
    assert result["problems"] == [] and result["figures"] == 3 and result["ready"], result
    assert all(f["nonBackground"] > 0.05 for f in result["each"]), result
    print(f"notebook with widget state (bytes, of which the state): {sizes}; "
          f"without: {len(nbformat.writes(plain))}; HTML export: {len(body)}")

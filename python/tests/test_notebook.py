"""The course notebook (examples/notebooks/screw-course.ipynb) runs top to bottom in a kernel
(nbclient), and its nbconvert HTML export draws the figure from file:// with no network.

The notebook is executed without storing the widget state, as JupyterLab saves a notebook by
default: then nbconvert exports the figure's static copy (`text/html`). With a stored widget
state nbconvert would use the widget view instead, whose page loads the widget manager from a
CDN (python/README.md says how to export such a notebook)."""

import nbformat
import pytest
from nbclient import NotebookClient
from nbconvert import HTMLExporter

from conftest import ROOT
from test_figure import SHOTS, needs_bundle, run_static_page

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

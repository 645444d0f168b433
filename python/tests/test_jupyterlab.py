"""The figure in a real JupyterLab (pip `jupyterlab`, started here on 127.0.0.1 with a token and
stopped after the test) driven by one headless Chromium (browser/jupyterlab.mjs): a notebook
runs, its three figures (WebGPU, WebGL2, and a third sharing the first one's viewer) show
non-blank pixels with no page error, setting `fig.poses` in Python changes the picture, and a real
mouse drag in the figure moves the pose that Python reads."""

import json
import os
import pathlib
import secrets
import shutil
import socket
import subprocess
import sys
import time
import urllib.request

import nbformat
import pytest

from test_figure import SHOTS, needs_bundle

NOTEBOOK_CELLS = [
    "import numpy as np, screwbender as sb\n"
    "P = np.array([[0, 0, 0, 1, 0, 0, 0], [3, 0, 0, 0.9239, 0, 0, 0.3827], [3, 3, 0, 0.7071, 0, 0, 0.7071],\n"
    "              [0, 3, 0, 0.3827, 0, 0, 0.9239]])\n"
    "fig = sb.Figure(P, levels=4, camera='iso', height=360)\n"
    "moves = []\n"
    "fig.observe(lambda c: moves.append(c['new']), names='poses')\n"
    "fig",
    "gl = sb.Figure(P, levels=4, camera='iso', height=360, backend='webgl2', editable=False)\ngl",
    "sb.Figure(sb.Motion.from_preset('l_cycle_rotated', levels=3), camera='iso', height=300, editable=False)",
]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@needs_bundle
def test_the_figure_in_jupyterlab(tmp_path):
    node = shutil.which("node")
    assert node, "node is needed to drive Chromium"
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in NOTEBOOK_CELLS]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    (tmp_path / "work").mkdir()
    nbformat.write(nb, tmp_path / "work" / "figure.ipynb")
    port, token = free_port(), secrets.token_hex(16)
    env = dict(os.environ)
    for var, sub in [("JUPYTER_CONFIG_DIR", "config"), ("JUPYTER_RUNTIME_DIR", "runtime"), ("JUPYTERLAB_WORKSPACES_DIR", "workspaces")]:
        env[var] = str(tmp_path / sub)
    lab = subprocess.Popen(
        [sys.executable, "-m", "jupyterlab", "--no-browser", "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}",
         "--ServerApp.port_retries=0", f"--IdentityProvider.token={token}", "--LabApp.expose_app_in_browser=True",
         f"--ServerApp.root_dir={tmp_path / 'work'}", "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
         "--ServerApp.allow_root=True"],
        env=env, stdout=subprocess.DEVNULL, stderr=open(tmp_path / "lab.log", "w"),
    )
    try:
        base = f"http://127.0.0.1:{port}"
        deadline = time.time() + 120
        while True:
            try:
                urllib.request.urlopen(f"{base}/api/status?token={token}", timeout=5)
                break
            except OSError:
                if time.time() > deadline or lab.poll() is not None:
                    pytest.fail("JupyterLab did not start: " + (tmp_path / "lab.log").read_text()[-2000:])
                time.sleep(0.5)
        SHOTS.mkdir(parents=True, exist_ok=True)
        done = subprocess.run(
            [node, str(pathlib.Path(__file__).parent / "browser" / "jupyterlab.mjs"), f"{base}/lab/tree/figure.ipynb?token={token}", str(SHOTS)],
            capture_output=True, text=True, timeout=600, check=False,
        )
        assert done.returncode == 0, done.stderr[-3000:]
        seen = json.loads(done.stdout.strip().splitlines()[-1])
    finally:
        lab.terminate()
        try:
            lab.wait(timeout=20)
        except subprocess.TimeoutExpired:
            lab.kill()
    assert seen["backends"] == ["WebGPU", "WebGL2", "WebGPU"], seen
    assert min(seen["nonBackground"]) > 0.05, seen
    # Python -> figure: the figure's motion has the new pose and the picture changed.
    assert seen["setPoses"].strip() == "set"
    assert abs(seen["figurePose2"][2] - 2.5) < 1e-9, seen["figurePose2"]
    assert seen["pictureChanged"] > 0.002, seen
    # Figure -> Python: the drag moved control pose 1 in the kernel and fired the observer.
    moved = sum((a - b) ** 2 for a, b in zip(seen["after"][:3], seen["before"][:3])) ** 0.5
    assert moved > 0.05, seen
    assert int(seen["observed"]) >= 2, seen  # the Python change and the drag
    # Any page error fails the test, among them anywidget's "Failed to initialize model." (a
    # figure's module that took longer than anywidget waits to load).
    assert seen["problems"] == [], seen

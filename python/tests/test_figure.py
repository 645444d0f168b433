"""The notebook figure: two-way state with validation, the display data, and the static page
(`Figure.to_html`) drawing from file:// with the network cut off, on both backends."""

import json
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import screwbender as sb
from conftest import ROOT
from test_inputs import P

BUNDLE = pathlib.Path(sb.__file__).parent / "static" / "figure.js"
SHOTS = ROOT / "artifacts" / "python"
needs_bundle = pytest.mark.skipif(not BUNDLE.exists(), reason="the wheel was built without the figure bundle")


def run_static_page(html: pathlib.Path, backend: str, shot: pathlib.Path) -> dict:
    node = shutil.which("node")
    assert node, "node is needed for the browser checks"
    done = subprocess.run(
        [node, str(pathlib.Path(__file__).parent / "browser" / "static_page.mjs"), str(html), backend, str(shot)],
        capture_output=True, text=True, timeout=240, check=False,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_a_figure_takes_a_motions_state():
    m = sb.Motion(P, closed=False, s=0.25, levels=3, rules="direct", name="walk")
    fig = sb.Figure(m, camera="top", strobe=8)
    assert np.array_equal(fig.poses, m.poses)
    assert (fig.closed, fig.scheme, fig.s, fig.levels, fig.name) == (False, None, 0.25, 3, "walk")
    assert np.array_equal(fig.motion.subdivide(), m.subdivide())
    fig2 = sb.Figure(P, scheme="bspline", levels=2)
    assert fig2.closed and fig2.motion.scheme == "bspline"
    assert sb.Figure(sb.Motion.from_preset("circle4")).name == "circle4"


def test_python_changes_are_checked_and_observed():
    fig = sb.Figure(P, levels=3)
    seen = []
    fig.observe(lambda c: seen.append(c["name"]), names=["poses", "scheme", "levels"])
    moved = P.copy()
    moved[2, :3] += [0.5, 0, 0]
    fig.poses = moved
    assert np.array_equal(fig.poses, moved) and seen == ["poses"]
    fig.scheme = "bspline"
    fig.levels = 4
    assert seen == ["poses", "scheme", "levels"]
    before = (fig.poses.copy(), fig.scheme, fig.levels)
    with pytest.raises(ValueError, match=r"poses\[1\].rotation: zero quaternion"):
        fig.poses = np.vstack([P[:1], np.zeros((1, 7)), P[2:]])
    with pytest.raises(ValueError, match="scheme: unknown value 'cubic'"):
        fig.scheme = "cubic"
    with pytest.raises(ValueError, match="levels: 30 is out of range"):
        fig.levels = 30
    with pytest.raises(ValueError, match="levels: the result would have"):
        fig.levels = 19
    with pytest.raises(ValueError, match="strobe"):
        sb.Figure(P, strobe=-1)
    assert np.array_equal(fig.poses, before[0]) and (fig.scheme, fig.levels) == before[1:]
    assert seen == ["poses", "scheme", "levels"]


def test_a_figure_holds_the_rule_set_id():
    # The id the page and the element use, whichever accepted name came in.
    assert sb.Figure(P, rules="split-then-tweak").rules == "split"
    assert sb.Figure(sb.Motion(P, rules="split-then-tweak")).rules == "split"
    fig = sb.Figure(P)
    fig.rules = "split-then-tweak"
    assert fig.rules == "split" and fig.motion.rules == "split"
    with pytest.raises(ValueError, match="rules: unknown value 'v3'"):
        fig.rules = "v3"
    assert fig.rules == "split"


def test_front_end_poses_arrive_as_an_array():
    fig = sb.Figure(P)
    rows = (P + [0.25, 0, 0, 0, 0, 0, 0]).tolist()
    # What the widget manager does with a front-end `poses` update.
    fig.set_state({"poses": rows})
    assert fig.poses.shape == (6, 7) and abs(fig.poses[0, 0] - 0.25) < 1e-15


#: Base64 of the WebAssembly magic number, which opens each of the bundle's two inlined modules.
WASM = "AGFzbQ"


@needs_bundle
def test_display_data_carries_the_widget_and_a_static_copy():
    from screwbender._figure import _StaticCopies

    _StaticCopies.carrier = None  # as in a fresh kernel
    first, second = sb.Figure(P), sb.Figure(P, levels=2)
    data, _ = first._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in data
    assert data["text/html"].count('<script type="module">') == 2
    assert data["text/html"].count(WASM) == 2 and len(data["text/html"]) < 8e6
    # The second figure's copy starts from the first one's bundle.
    data, _ = second._repr_mimebundle_()
    assert data["text/html"].count('<script type="module">') == 1
    assert WASM not in data["text/html"] and len(data["text/html"]) < 5e3
    assert WASM in second.to_html()  # a fragment stands alone
    sb.Figure.embed_static = False
    try:
        data, _ = first._repr_mimebundle_()
        assert "text/html" not in data
    finally:
        sb.Figure.embed_static = True


@needs_bundle
def test_figures_share_one_asset_model():
    figures = [sb.Figure(P), sb.Figure(P, levels=2), sb.Figure(sb.Motion.from_preset("circle4"))]
    states = [f.get_state() for f in figures]
    assert len({s["_assets"] for s in states}) == 1 and states[0]["_assets"].startswith("IPY_MODEL_")
    # Each figure's own module is the loader: the bundle is in the asset model alone.
    assert all(len(s["_esm"]) < 4e3 and WASM not in s["_esm"] for s in states)
    assert figures[0]._assets.get_state()["code"].count(WASM) == 2


@needs_bundle
@pytest.mark.parametrize("backend", ["webgpu", "webgl2"])
def test_the_static_page_draws_offline_from_file(tmp_path, backend):
    fig = sb.Figure(sb.Motion.from_preset("l_cycle_rotated", levels=4), camera="iso")
    page = tmp_path / "figure.html"
    page.write_text(f"<!doctype html><meta charset=utf-8><title>figure</title><body>{fig.to_html()}</body>")
    SHOTS.mkdir(parents=True, exist_ok=True)
    result = run_static_page(page, backend, SHOTS / f"static-{backend}.png")
    assert result["requests"] == [] and result["problems"] == []
    assert result["backend"] == ("WebGPU" if backend == "webgpu" else "WebGL2")
    assert result["nonBackground"] > 0.05 and result["colours"] > 20


@needs_bundle
def test_three_static_copies_share_one_bundle_in_any_order(tmp_path):
    from screwbender._figure import _StaticCopies

    _StaticCopies.carrier = None
    figures = [sb.Figure(sb.Motion.from_preset(name, levels=3), camera="iso", height=300)
               for name in ["circle4", "l_cycle_rotated", "l_cycle_parallel"]]
    # Shown in the order 2, 1, 3: the copy that carries the bundle is the middle one of the page.
    html = {i: figures[i]._repr_mimebundle_()[0]["text/html"] for i in (1, 0, 2)}
    body = "".join(html[i] for i in range(3))
    assert body.count(WASM) == 2
    page = tmp_path / "three.html"
    page.write_text(f"<!doctype html><meta charset=utf-8><title>three</title><body>{body}</body>")
    result = run_static_page(page, "webgl2", SHOTS / "static-three.png")
    assert result["requests"] == [] and result["problems"] == []
    assert result["figures"] == 3 and result["ready"], result
    assert all(f["nonBackground"] > 0.05 for f in result["each"]), result

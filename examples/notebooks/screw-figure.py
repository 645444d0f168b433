# /// script
# requires-python = ">=3.9"
# dependencies = ["marimo", "screwbender[notebook]"]
# ///
"""The ScrewBender figure in a marimo notebook: drag a control pose in the figure and the cells
that read the figure's poses run again (marimo hosts anywidget widgets as they are).

    marimo edit examples/notebooks/screw-figure.py
"""

import marimo

app = marimo.App()


@app.cell
def _():
    import marimo as mo
    import numpy as np

    import screwbender as sb

    return mo, np, sb


@app.cell
def _(mo):
    mo.md(
        """
        # A screw motion in marimo

        Four poses of an L-shaped body, smoothed by four levels of 4-point screw subdivision.
        Drag a pose in the figure: the table below follows.
        """
    )
    return


@app.cell
def _(mo, sb):
    motion = sb.Motion.from_preset("l_cycle_rotated", levels=4)
    figure = mo.ui.anywidget(sb.Figure(motion, editable=True, camera="iso", height=360))
    figure
    return figure, motion


@app.cell
def _(figure, motion, np, sb):
    # The figure's poses as the front end left them: a change there runs this cell again.
    poses = np.asarray(figure.widget.poses)
    edited = sb.Motion(poses, closed=motion.closed, scheme=motion.scheme, levels=motion.levels)
    path = edited.subdivide()[:, :3]
    length = float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum())
    return edited, length, poses


@app.cell
def _(length, mo, poses):
    mo.md(
        f"{len(poses)} control poses; the origin travels {length:.3f} units along the "
        "smoothed cycle.\n\n"
        + "| pose | x | y | z |\n|---|---|---|---|\n"
        + "\n".join(f"| {i} | {p[0]:.3f} | {p[1]:.3f} | {p[2]:.3f} |" for i, p in enumerate(poses))
    )
    return


if __name__ == "__main__":
    app.run()

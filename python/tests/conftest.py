"""Shared fixtures: the repository root and the `screwbender` command-line tool (the reference
the package is checked against bit for bit)."""

import json
import os
import pathlib
import shutil
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _cli_path() -> pathlib.Path:
    given = os.environ.get("SCREWBENDER_CLI")
    if given:
        return pathlib.Path(given)
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    built = target / "release" / "screwbender"
    if not built.exists():
        cargo = shutil.which("cargo")
        if cargo is None:
            pytest.skip("no cargo to build the CLI and SCREWBENDER_CLI not set")
        subprocess.run(
            [cargo, "build", "--release", "-q", "-p", "screwbender-cli"], cwd=ROOT, check=True
        )
    return built


@pytest.fixture(scope="session")
def cli():
    """Runs the CLI: `cli(args, stdin=None)` returns its standard output (exit 0 asserted)."""
    path = _cli_path()

    def run(args, stdin=None):
        done = subprocess.run(
            [str(path), *args], input=stdin, capture_output=True, text=True, check=False
        )
        assert done.returncode == 0, done.stderr
        return done.stdout

    return run


def cli_poses(text: str):
    """The `poses` of a CLI document as a list of 7-number rows."""
    doc = json.loads(text)
    return [p["origin"] + p["rotation"] for p in doc["poses"]]

"""Shared fixtures: the repository root and the `screwbender` command-line tool (the reference
the package is checked against bit for bit). And on CI (`CI=true`) a skipped test fails the run:
a test that skips where what it needs is missing (the figure bundle, the CLI, a package) passes
nowhere it matters unless CI has what it needs, so there a skip is a failure, named."""

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


_SKIPPED = []


def pytest_runtest_logreport(report):
    """Remembers every skipped test (a skip in setup, as `skipif` makes, or in the test itself)."""
    if report.skipped and not hasattr(report, "wasxfail"):
        reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else str(report.longrepr)
        _SKIPPED.append(f"{report.nodeid}: {reason}")


def _on_ci() -> bool:
    return os.environ.get("CI", "").lower() in ("true", "1")


def pytest_terminal_summary(terminalreporter):
    """On CI, names the skipped tests that fail the run."""
    if _on_ci() and _SKIPPED:
        terminalreporter.section("skipped on CI (CI=true), which fails the run")
        for line in _SKIPPED:
            terminalreporter.write_line(line)


def pytest_sessionfinish(session):
    """On CI, a run with a skipped test fails."""
    if _on_ci() and _SKIPPED and session.exitstatus == pytest.ExitCode.OK:
        session.exitstatus = pytest.ExitCode.TESTS_FAILED

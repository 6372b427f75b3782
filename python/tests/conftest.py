"""Shared fixtures: the `brine` command the bindings are compared with."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def brine_cli():
    """Runs `brine ARGS…` and returns its standard output parsed as JSON.

    The command is `$BRINE_BIN` (CI sets it), else the workspace's release build.
    """
    path = pathlib.Path(os.environ.get("BRINE_BIN", ROOT / "target" / "release" / "brine"))
    if not path.exists():
        if "BRINE_BIN" in os.environ:
            pytest.fail(f"BRINE_BIN = {path} does not exist")
        pytest.skip(f"{path} not built (cargo build --release)")

    def run(*args: str, stdin: str | None = None):
        out = subprocess.run([str(path), *args], input=stdin, capture_output=True, text=True, check=True)
        return json.loads(out.stdout)

    run.path = path
    return run

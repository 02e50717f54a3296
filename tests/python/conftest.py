"""Shared fixtures: the rbsim program of this build and the source tree (set by ctest)."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("RBSIM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENES = SOURCE / "assets" / "scenes"


@pytest.fixture
def rbsim_binary():
    path = os.environ.get("RBSIM_BINARY")
    if not path:
        pytest.fail("RBSIM_BINARY is not set: run these tests through ctest")
    return path


def run_cli(binary, *args):
    """The rbsim program's exit code and standard error."""
    done = subprocess.run([binary, *args], capture_output=True, text=True, timeout=600)
    return done.returncode, done.stderr

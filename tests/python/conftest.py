"""Shared fixtures of the Python module's tests (run by ctest: tests/CMakeLists.txt).

The shared data (real CTs, the JTML knee, the wrist) is found in $FM_DATA_DIR, by default
../shared/data beside the checkout. Without it a test that needs it skips with a message,
except under CI=true, where its absence is a failure. The CLI executable (to compare with) is
$FM_EXECUTABLE, set by ctest.
"""
import os
import pathlib
import subprocess

import numpy as np
import pytest

import fluoromatch as fm

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def data_dir():
    path = pathlib.Path(os.environ.get("FM_DATA_DIR", REPO.parent / "shared" / "data"))
    if not (path / "README.md").exists():
        if os.environ.get("CI") == "true":
            pytest.fail(f"shared data missing under CI: {path}")
        pytest.skip(f"shared data not found at {path} (set FM_DATA_DIR)")
    return path


@pytest.fixture(scope="session")
def jtml(data_dir):
    return data_dir / "jtml-kneel-tka-fluoro"


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("FM_EXECUTABLE", str(REPO / "build" / "app" / "fluoromatch"))
    if not pathlib.Path(exe).exists():
        pytest.fail(f"the fluoromatch executable is not built: {exe}")

    def run(*args):
        done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, f"fluoromatch {' '.join(map(str, args))}:\n{done.stdout}\n{done.stderr}"
        return done.stdout

    return run


def rotation(axis, deg):
    """The right-handed rotation by deg about x, y or z: independent arithmetic for the tests."""
    c, s = np.cos(np.radians(deg)), np.sin(np.radians(deg))
    return {
        "x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
        "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    }[axis]


def pose(r=np.eye(3), t=(0, 0, 0)):
    m = np.eye(4)
    m[:3, :3] = r
    m[:3, 3] = t
    return m

# pytest set-up of the railsim Python tests (run by ctest, see python/CMakeLists.txt):
# PYTHONPATH holds <build>/python; RAILSIM_BINARY is the program, RAILSIM_SOURCE_DIR the sources.
import os
import subprocess
import sys

import pytest

SOURCE_DIR = os.environ.get("RAILSIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("RAILSIM_BINARY", "railsim")
sys.path.insert(0, os.path.join(SOURCE_DIR, "examples"))


def source(*parts):
    return os.path.join(SOURCE_DIR, *parts)


def railsim_cli(*args, cwd=None):
    """Run the program; returns (exit code, stdout + stderr)."""
    p = subprocess.run([BINARY, *map(str, args)], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    return p.returncode, p.stdout


@pytest.fixture
def cli():
    return railsim_cli

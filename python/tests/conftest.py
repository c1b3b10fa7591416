"""Shared fixtures: small plates made by `exrcomp generate`, and the
command line the package is compared with (EXRCOMP_BIN, the repository's
build, in .ci/run; else the `exrcomp` the wheel put on PATH)."""

import os
import shutil
import subprocess

import pytest


def command_line():
    found = os.environ.get("EXRCOMP_BIN") or shutil.which("exrcomp")
    assert found, "no exrcomp command: install the wheel, or set EXRCOMP_BIN"
    return found


def exrcomp(*args, check=True, cwd=None):
    """The command line run with `args`: its completed process."""
    done = subprocess.run([command_line(), *map(str, args)], capture_output=True,
                          text=True, cwd=cwd)
    if check and done.returncode != 0:
        raise AssertionError(f"exrcomp {' '.join(map(str, args))}: {done.stderr}")
    return done


@pytest.fixture(scope="session")
def plates(tmp_path_factory):
    """fg.####.exr and bg.####.exr, frames 1-4, 64x48."""
    folder = tmp_path_factory.mktemp("plates")
    for kind in ("fg", "bg"):
        exrcomp("generate", "--kind", kind, "--width", 64, "--height", 48,
                "--frames", "1-4", folder / f"{kind}.####.exr")
    return folder

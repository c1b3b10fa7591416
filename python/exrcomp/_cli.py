"""The `exrcomp` command that `pip install` puts on PATH: the command line
of the library in the extension module, run in this process."""

import os
import shutil
import sys

from . import _native


def main():
    # bench and farm start this command again (its path, not Python's).
    script = shutil.which(sys.argv[0]) or sys.argv[0]
    sys.exit(_native.main(["exrcomp", *sys.argv[1:]], os.path.abspath(script)))

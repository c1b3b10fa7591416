"""The `exrcomp` command that `pip install` puts on PATH: the command line
of the library in the extension module, run in this process."""

import sys

from . import _native


def main():
    sys.exit(_native.main(["exrcomp", *sys.argv[1:]]))

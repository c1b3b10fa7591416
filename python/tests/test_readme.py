"""The README's Python script (ten lines: a sequence converted with OCIO,
review PNGs with a burn-in) runs as printed and writes what the same
commands write, byte for byte."""

import os
import re
import struct
import subprocess
import sys

from conftest import exrcomp as command

README = os.path.join(os.path.dirname(__file__), "..", "..", "README.md")


def script():
    with open(README) as f:
        text = f.read()
    section = text.split("\n## Python\n")[1].split("\n## ")[0]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def chunks(png):
    """A PNG's chunks but its fingerprint (which names the input's path,
    here another folder's)."""
    at, out = 8, []
    while at < len(png):
        length, kind = struct.unpack(">I4s", png[at:at + 8])
        data = png[at + 8:at + 8 + length]
        if not (kind == b"tEXt" and data.startswith(b"exrcomp:fingerprint\0")):
            out.append((kind, data))
        at += 12 + length
    return out


def test_the_readmes_script_converts_and_writes_review_pngs(tmp_path):
    text = script()
    assert len(text.splitlines()) <= 10, text
    frames = "1001-1003"
    (tmp_path / "plates").mkdir()
    command("generate", "--kind", "bg", "--width", 64, "--height", 48, "--frames", frames,
            tmp_path / "plates" / "A001.####.exr")
    done = subprocess.run([sys.executable, "-c", text.replace("1001-1100", frames)],
                          cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    # The same conversion and review by the command line.
    cli = tmp_path / "cli"
    command("colorconvert", "plates/A001.####.exr", "--from", "ACES2065-1", "--to", "ACEScg",
            "-o", cli / "work" / "A001.####.exr", "--compression", "zip", "--frames", frames,
            "-q", cwd=tmp_path)
    command("ociodisplay", cli / "work" / "A001.####.exr", "--from", "ACEScg",
            "-o", cli / "review" / "A001.####.png", "--transfer", "none",
            "--burn-in", "A001 {frame:4}", "--frames", frames, "-q", cwd=tmp_path)
    for frame in range(1001, 1004):
        made = f"work/A001.{frame}.exr"
        assert (tmp_path / made).read_bytes() == (cli / made).read_bytes(), made
        made = f"review/A001.{frame}.png"
        assert chunks((tmp_path / made).read_bytes()) == chunks((cli / made).read_bytes())
    # The burn-in is drawn: without it the review differs.
    command("ociodisplay", cli / "work" / "A001.####.exr", "--from", "ACEScg",
            "-o", cli / "plain" / "A001.####.png", "--transfer", "none", "--frames", "1001",
            "-q", cwd=tmp_path)
    png = (tmp_path / "review" / "A001.1001.png").read_bytes()
    assert png.startswith(b"\x89PNG")
    assert chunks(png) != chunks((cli / "plain" / "A001.1001.png").read_bytes())

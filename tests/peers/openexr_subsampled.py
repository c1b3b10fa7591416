#!/usr/bin/env python3
"""PyPI OpenEXR (3.5) as a peer for tests/suite/luminance_chroma.rs.

write DIR: the same luminance/chroma images in every compression, seeded:
    yc_COMPRESSION.exr (Y, RY, BY; 38 x 70 from (-6, 4)) and
    yca_COMPRESSION.exr (and A; 66 x 34 from the origin).
same A B: exit 0 when A and B hold the same channels, sampling and samples
    (bit for bit), else print the first difference and exit 1."""
import sys
import numpy as np
import OpenEXR

COMPRESSIONS = {
    "none": OpenEXR.NO_COMPRESSION, "rle": OpenEXR.RLE_COMPRESSION,
    "zips": OpenEXR.ZIPS_COMPRESSION, "zip": OpenEXR.ZIP_COMPRESSION,
    "piz": OpenEXR.PIZ_COMPRESSION, "pxr24": OpenEXR.PXR24_COMPRESSION,
    "b44": OpenEXR.B44_COMPRESSION, "b44a": OpenEXR.B44A_COMPRESSION,
    "dwaa": OpenEXR.DWAA_COMPRESSION,
}


def image(rng, w, h, alpha):
    def padded(samples):
        # PyPI OpenEXR 3.5 takes arrays of the image's shape and writes a
        # subsampled channel's samples from the start of the buffer.
        full = np.zeros((h, w), dtype=np.float16)
        full.reshape(-1)[: samples.size] = samples.reshape(-1)
        return full

    chroma = lambda: rng.normal(0, 0.4, (h // 2, w // 2)).astype(np.float16)
    channels = {
        "Y": OpenEXR.Channel(np.abs(rng.normal(0.4, 0.3, (h, w))).astype(np.float16), 1, 1),
        "RY": OpenEXR.Channel(padded(chroma()), 2, 2),
        "BY": OpenEXR.Channel(padded(chroma()), 2, 2),
    }
    if alpha:
        channels["A"] = OpenEXR.Channel(rng.uniform(0, 1, (h, w)).astype(np.float16), 1, 1)
    return channels


def write(out):
    for prefix, (w, h, x, y, alpha) in {"yc": (38, 70, -6, 4, False), "yca": (66, 34, 0, 0, True)}.items():
        for name, compression in COMPRESSIONS.items():
            header = {
                "compression": compression,
                "type": OpenEXR.scanlineimage,
                "dataWindow": (np.array([x, y], np.int32), np.array([x + w - 1, y + h - 1], np.int32)),
                "displayWindow": (np.array([0, 0], np.int32), np.array([63, 63], np.int32)),
            }
            rng = np.random.default_rng(11)
            OpenEXR.File(header, image(rng, w, h, alpha)).write(f"{out}/{prefix}_{name}.exr")


def same(a, b):
    a = OpenEXR.File(a, separate_channels=True).channels()
    b = OpenEXR.File(b, separate_channels=True).channels()
    if sorted(a) != sorted(b):
        sys.exit(f"channels {sorted(a)} and {sorted(b)}")
    for name in a:
        x, y = a[name], b[name]
        if (x.xSampling, x.ySampling) != (y.xSampling, y.ySampling):
            sys.exit(f"{name}: sampling differs")
        if x.pixels.shape != y.pixels.shape or not np.array_equal(
            x.pixels.view(np.uint16), y.pixels.view(np.uint16)
        ):
            sys.exit(f"{name}: samples differ")


if __name__ == "__main__":
    {"write": lambda: write(sys.argv[2]), "same": lambda: same(sys.argv[2], sys.argv[3])}[sys.argv[1]]()

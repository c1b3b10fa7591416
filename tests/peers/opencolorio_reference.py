#!/usr/bin/env python3
"""PyPI opencolorio (2.6.0, the reference implementation) as the peer of
tests/suite/colour.rs.

python3 opencolorio_reference.py SPEC.json: SPEC holds "grid", a file of
little-endian float32 RGB triples, and "cases", each a transform and "out",
the file its result on the grid is written to (float32 RGB). Kinds:
  colorconvert: config, from, to
  display: config, from, display, view, looks (optional: the looks override),
    inverse
  look: config, from, to, looks, inverse
  cdl: slope, offset, power, sat, inverse; or file, id, inverse
  file: file, inverse, interpolation (OCIO's name: linear, tetrahedral...)
Processors are OCIO's default CPU processors, as exrcomp's are. A case with
"may_refuse" that OCIO refuses writes OCIO's message to "out" + ".refused"
instead (the sweep of OCIO's own test files)."""
import json
import sys

import numpy as np
import PyOpenColorIO as ocio


def direction(case):
    return ocio.TRANSFORM_DIR_INVERSE if case.get("inverse") else ocio.TRANSFORM_DIR_FORWARD


def processor(case):
    kind = case["kind"]
    if kind in ("cdl", "file"):
        config = ocio.Config.CreateRaw()
        if "file" in case:
            t = ocio.FileTransform(src=case["file"], cccId=case.get("id", ""),
                                   direction=direction(case))
            t.setInterpolation(ocio.Interpolation.__members__[
                "INTERP_" + case.get("interpolation", "default").upper()])
        else:
            t = ocio.CDLTransform(direction=direction(case))
            t.setSlope(case["slope"])
            t.setOffset(case["offset"])
            t.setPower(case["power"])
            t.setSat(case["sat"])
        return config.getProcessor(t)
    config = ocio.Config.CreateFromFile(case["config"])
    if kind == "colorconvert":
        return config.getProcessor(case["from"], case["to"])
    if kind == "look":
        t = ocio.LookTransform(src=case["from"], dst=case["to"], looks=case["looks"],
                               direction=direction(case))
        return config.getProcessor(t)
    t = ocio.DisplayViewTransform(src=case["from"], display=case["display"], view=case["view"],
                                  direction=direction(case))
    if "looks" not in case:
        return config.getProcessor(t)
    pipeline = ocio.LegacyViewingPipeline()
    pipeline.setDisplayViewTransform(t)
    pipeline.setLooksOverrideEnabled(True)
    pipeline.setLooksOverride(case["looks"])
    return pipeline.getProcessor(config)


def main():
    with open(sys.argv[1]) as f:
        spec = json.load(f)
    grid = np.fromfile(spec["grid"], dtype="<f4")
    for case in spec["cases"]:
        values = grid.astype(np.float32).copy()
        try:
            cpu = processor(case).getDefaultCPUProcessor()
        except Exception as e:
            if not case.get("may_refuse"):
                raise
            with open(case["out"] + ".refused", "w") as f:
                f.write(str(e))
            continue
        cpu.applyRGB(values)
        values.astype("<f4").tofile(case["out"])


main()

#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Lightcone's VTK filters in a VTK pipeline from Python, written as one .vtm file for ParaView.

    PYTHONPATH=build/python python3 examples/python/vtk_pipeline.py [OUT_DIR]

The Goedel universe (a = 1) seen from the axis: the observer's light rays in a fan through the
plane (vtkLightconeNullGeodesicSource, closed form), the horizon r = 2a and the past light cone
(vtkLightconeGodelHorizonSource, ports 0 and 1), all in the EMBEDDING chart, gathered by VTK's
vtkMultiBlockDataSet and written by vtkXMLMultiBlockDataWriter to OUT_DIR/godel.vtm. The file is
read back with VTK's reader; the horizon's points must lie at r = 2a and every ray must turn back
inside it (docs/PHYSICS.md section 2). Exits 1 otherwise."""
import math
import pathlib
import sys

import lightcone.filters as lf  # first: says which Python has VTK when this one has not

from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader, vtkXMLMultiBlockDataWriter  # noqa: E402

out_dir = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out_dir.mkdir(parents=True, exist_ok=True)

rays = lf.vtkLightconeNullGeodesicSource()
rays.SetMetricName("godel")
rays.SetMetricParameter("a", 1.0)
rays.SetDirectionModeToFan()
rays.SetNumberOfRays(24)

horizon = lf.vtkLightconeGodelHorizonSource()
horizon.SetGodelA(1.0)
horizon.SetZRange(-1.0, 1.0)

blocks = vtkMultiBlockDataSet()
for index, (name, algorithm, port) in enumerate((("null geodesics", rays, 0), ("horizon", horizon, 0),
                                                 ("past light cone", horizon, 1))):
    algorithm.Update()
    blocks.SetBlock(index, algorithm.GetOutputDataObject(port))
    blocks.GetMetaData(index).Set(vtkMultiBlockDataSet.NAME(), name)

writer = vtkXMLMultiBlockDataWriter()
writer.SetFileName(str(out_dir / "godel.vtm"))
writer.SetInputData(blocks)
if writer.Write() != 1:
    sys.exit("could not write " + str(out_dir / "godel.vtm"))

reader = vtkXMLMultiBlockDataReader()
reader.SetFileName(str(out_dir / "godel.vtm"))
reader.Update()
read = reader.GetOutput()
print(f"wrote {out_dir / 'godel.vtm'}: {read.GetNumberOfBlocks()} blocks")
worst_horizon, farthest_ray = 0.0, 0.0
for k in range(read.GetNumberOfBlocks()):
    block = read.GetBlock(k)
    name = read.GetMetaData(k).Get(vtkMultiBlockDataSet.NAME())
    radii = [math.hypot(*block.GetPoint(i)[:2]) for i in range(block.GetNumberOfPoints())]
    print(f"  {name}: {block.GetNumberOfPoints()} points, {block.GetNumberOfCells()} cells, "
          f"r from {min(radii):.4f} to {max(radii):.4f}")
    if name == "horizon":
        worst_horizon = max(abs(r - 2.0) for r in radii)
    if name == "null geodesics":
        farthest_ray = max(radii)
ok = read.GetNumberOfBlocks() == 3 and worst_horizon < 1e-9 and 0 < farthest_ray <= 2.0 + 1e-9
print("horizon at r = 2a to", f"{worst_horizon:.1e};", "rays turn back inside it:", farthest_ray <= 2.0 + 1e-9)
sys.exit(0 if ok else 1)

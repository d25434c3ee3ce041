"""What ParaView makes of run folders: run by pvpython (Debian's python3-paraview) from
test_paraview_outputs.py as `pvpython paraview_probe.py OUT_DIR RUN_DIR...`.

For each run folder it opens particles.xdmf and, if there, fluid.xdmf with ParaView's default
reader for the file (simple.OpenDataFile), as the GUI's File > Open does, and writes to
OUT_DIR/<run folder name>.json: per file the reader's name, its time values, and per time value
the data's time, point and cell counts, bounds, the point and cell arrays (name: components) and
the cell types; the time keeper's time values with both files open; and, for the last time value,
every array and the points in OUT_DIR/<run folder name>_<file>.npz. It judges nothing: the test
compares all this with the HDF5 files."""
import json
import os
import sys

import numpy as np
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy


def arrays(field):
    return {field.GetArrayName(i): field.GetArray(i).GetNumberOfComponents()
            for i in range(field.GetNumberOfArrays())}


def probe(path, npz):
    src = simple.OpenDataFile(path)
    times = [float(t) for t in src.TimestepValues]
    info = {"reader": src.GetXMLName(), "times": times, "steps": []}
    for t in times:
        src.UpdatePipeline(t)
        d = servermanager.Fetch(src)
        cell_types = sorted({d.GetCellType(c) for c in range(d.GetNumberOfCells())}) \
            if d.IsA("vtkUnstructuredGrid") else []
        info["steps"].append({
            "data_time": src.GetDataInformation().DataInformation.GetTime(),
            "class": d.GetClassName(),
            "points": d.GetNumberOfPoints(),
            "cells": d.GetNumberOfCells(),
            "bounds": list(d.GetBounds()),
            "point_arrays": arrays(d.GetPointData()),
            "cell_arrays": arrays(d.GetCellData()),
            "cell_types": cell_types,
        })
    if times:
        saved = {}
        for kind, field in (("point", d.GetPointData()), ("cell", d.GetCellData())):
            for i in range(field.GetNumberOfArrays()):
                saved[kind + ":" + field.GetArrayName(i)] = vtk_to_numpy(field.GetArray(i))
        if d.IsA("vtkPointSet") and d.GetNumberOfPoints():
            saved["points"] = vtk_to_numpy(d.GetPoints().GetData())
        np.savez(npz, **saved)
    return src, info


def main():
    out = sys.argv[1]
    for run in sys.argv[2:]:
        name = os.path.basename(os.path.normpath(run))
        report, sources = {}, []
        for kind in ("particles", "fluid"):
            path = os.path.join(os.path.abspath(run), kind + ".xdmf")
            if os.path.exists(path):
                src, report[kind] = probe(path, os.path.join(out, name + "_" + kind + ".npz"))
                sources.append(src)
        report["time_keeper"] = [float(t) for t in simple.GetTimeKeeper().TimestepValues]
        for src in sources:
            simple.Delete(src)
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(report, f, indent=1)


main()

"""Reads a boundary VTU (Bezier quadrilaterals) with VTK and evaluates it.

Usage: check_boundary_vtu.py FILE.vtu SAMPLES SEED
Prints "cells N", then per cell "cell id type deg0 deg1 label patch side",
then per cell SAMPLES lines "sample id r s x y z": (r, s) random parametric
coordinates and x the world point VTK computes there (vtkCell.
EvaluateLocation, the cell taken with vtkUnstructuredGrid.GetCell(id,
vtkGenericCell) so that VTK sets its degrees and rational weights).
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def main():
    path, samples, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = np.random.default_rng(seed)
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    ug = reader.GetOutput()
    n = ug.GetNumberOfCells()
    cd = ug.GetCellData()
    assert cd.GetHigherOrderDegrees() is not None, "HigherOrderDegrees not recognised"
    assert ug.GetPointData().GetRationalWeights() is not None, "RationalWeights not recognised"
    degs = vtk_to_numpy(cd.GetHigherOrderDegrees())
    label, patch, side = (vtk_to_numpy(cd.GetArray(a)) for a in ("label", "patch", "side"))
    print("cells %d" % n)
    for c in range(n):
        print("cell %d %d %d %d %d %d %d" % (c, ug.GetCellType(c), degs[c][0], degs[c][1], label[c], patch[c], side[c]))
    gc = vtk.vtkGenericCell()
    x = [0.0, 0.0, 0.0]
    for c in range(n):
        ug.GetCell(c, gc)
        w = [0.0] * gc.GetNumberOfPoints()
        sub = vtk.reference(0)
        for _ in range(samples):
            pc = [rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0), 0.0]
            gc.EvaluateLocation(sub, pc, x, w)
            print("sample %d %.17g %.17g %.17g %.17g %.17g" % (c, pc[0], pc[1], x[0], x[1], x[2]))


if __name__ == "__main__":
    main()

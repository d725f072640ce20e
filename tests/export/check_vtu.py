"""Reads a VTU with VTK's own reader and evaluates its Bezier cells with VTK.

Usage: check_vtu.py FILE.vtu SAMPLES SEED
Prints "cells N", then per cell "cell id type deg0 deg1 deg2 material patch",
then per cell SAMPLES lines
    sample id r s t x y z [ux uy uz vm]
where (r, s, t) are random parametric coordinates, x = the world point VTK
computes (vtkCell.EvaluateLocation, the cell taken with vtkUnstructuredGrid.
GetCell(id, vtkGenericCell) so that VTK sets the degrees and rational weights
as it does for rendering) and, when present, the point data displacement and
von_mises interpolated with VTK's interpolation weights.
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
    print("cells %d" % n)
    cd, pd = ug.GetCellData(), ug.GetPointData()
    assert cd.GetHigherOrderDegrees() is not None, "HigherOrderDegrees not recognised"
    assert pd.GetRationalWeights() is not None, "RationalWeights not recognised"
    degs = vtk_to_numpy(cd.GetHigherOrderDegrees())
    mat = vtk_to_numpy(cd.GetArray("material"))
    pat = vtk_to_numpy(cd.GetArray("patch"))
    disp = pd.GetArray("displacement")
    vm = pd.GetArray("von_mises")
    disp = vtk_to_numpy(disp) if disp is not None else None
    vm = vtk_to_numpy(vm) if vm is not None else None
    for c in range(n):
        d = degs[c]
        print("cell %d %d %d %d %d %d %d" % (c, ug.GetCellType(c), d[0], d[1], d[2], mat[c], pat[c]))
    gc = vtk.vtkGenericCell()
    x = [0.0, 0.0, 0.0]
    for c in range(n):
        ug.GetCell(c, gc)
        npts = gc.GetNumberOfPoints()
        w = [0.0] * npts
        ids = [gc.GetPointId(i) for i in range(npts)]
        sub = vtk.reference(0)
        for _ in range(samples):
            pc = list(rng.uniform(0.0, 1.0, 3))
            gc.EvaluateLocation(sub, pc, x, w)
            line = "sample %d %.17g %.17g %.17g %.17g %.17g %.17g" % (c, pc[0], pc[1], pc[2], x[0], x[1], x[2])
            if disp is not None:
                wa = np.array(w)
                u = wa @ disp[ids]
                s = wa @ vm[ids]
                line += " %.17g %.17g %.17g %.17g" % (u[0], u[1], u[2], s)
            print(line)


if __name__ == "__main__":
    main()

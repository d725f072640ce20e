"""Slices a VTU with VTK's cutter, as ParaView's Slice does.

Usage: slice_vtu.py FILE.vtu
Cuts the Bezier cells with the plane through the bounding box's centre,
normal (1, 1, 1) (through several patches and both materials), and prints
JSON: the slice's point count, the distinct values of the point data
"material" on it, and the range of the cell data "min_scaled_jacobian" and
the shape of "element" in the file, the cell data
"certified_det_lower_bound" when present (issue 23: higher-order cell data came
through the cutter as values of +-2e9), and "surface_faces": the cell faces
no other cell shares (by their corner points), which is what ParaView's
Extract Surface returns.
"""
import json
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def unshared_faces(grid):
    """Cell faces (VTK hexahedron corner order) that appear in one cell only."""
    faces = {}
    corners = ((0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7), (0, 3, 2, 1), (4, 5, 6, 7))
    ids = vtk.vtkIdList()
    for c in range(grid.GetNumberOfCells()):
        grid.GetCellPoints(c, ids)
        for f in corners:
            key = tuple(sorted(ids.GetId(i) for i in f))
            faces[key] = faces.get(key, 0) + 1
    return sum(1 for n in faces.values() if n == 1)


def main():
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(sys.argv[1])
    reader.Update()
    grid = reader.GetOutput()
    plane = vtk.vtkPlane()
    b = grid.GetBounds()
    plane.SetOrigin(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]))
    plane.SetNormal(1.0, 1.0, 1.0)
    cutter = vtk.vtkCutter()
    cutter.SetCutFunction(plane)
    cutter.SetInputData(grid)
    cutter.Update()
    cut = cutter.GetOutput()
    material = vtk_to_numpy(cut.GetPointData().GetArray("material"))
    q = vtk_to_numpy(grid.GetCellData().GetArray("min_scaled_jacobian"))
    element = vtk_to_numpy(grid.GetCellData().GetArray("element"))
    bound = grid.GetCellData().GetArray("certified_det_lower_bound")
    bound = vtk_to_numpy(bound).tolist() if bound is not None else None
    print(json.dumps({"points": cut.GetNumberOfPoints(), "certified_det_lower_bound": bound,
                      "surface_faces": unshared_faces(grid),
                      "materials": sorted(float(v) for v in np.unique(material)),
                      "min_scaled_jacobian": [float(q.min()), float(q.max())],
                      "element_shape": list(element.shape), "element_max": int(element.max())}))


if __name__ == "__main__":
    main()

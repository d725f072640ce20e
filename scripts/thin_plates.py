#!/usr/bin/python3
"""Thin test solids as OFF surfaces, for measuring how the method copes with
thin plates (docs/validation.md, "Thin plates").

Usage (Debian: python3-numpy and python3-vtk9, installed by scripts/setup.sh):
    /usr/bin/python3 scripts/thin_plates.py box A B C H > box.off
        the box [0, A] x [0, B] x [0, C], its faces cut into squares of side
        about H (two triangles each): a plate with a flat rim and sharp edges
    /usr/bin/python3 scripts/thin_plates.py plate T REDUCTION > plate.off
        a smooth plate 1 x 0.6 x T with round rims and two round holes
        (genus 2): its signed distance sampled on a grid, the zero set by
        VTK's flying edges, then VTK's quadric decimation by REDUCTION
"""
import sys


def box(a, b, c, h):
    na, nb, nc = [max(1, int(round(s / h))) for s in (a, b, c)]
    index, faces = {}, []

    def vid(p):
        key = tuple(round(x, 12) for x in p)
        return index.setdefault(key, len(index))

    def side(o, u, v, nu, nv):  # u x v points out of the box
        for i in range(nu):
            for j in range(nv):
                ids = [vid([o[k] + u[k] * (i + di) / nu + v[k] * (j + dj) / nv for k in range(3)])
                       for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
                faces.extend([(ids[0], ids[1], ids[2]), (ids[0], ids[2], ids[3])])

    side((0, 0, 0), (0, b, 0), (a, 0, 0), nb, na)
    side((0, 0, c), (a, 0, 0), (0, b, 0), na, nb)
    side((0, 0, 0), (a, 0, 0), (0, 0, c), na, nc)
    side((0, b, 0), (0, 0, c), (a, 0, 0), nc, na)
    side((0, 0, 0), (0, 0, c), (0, b, 0), nc, nb)
    side((a, 0, 0), (0, b, 0), (0, 0, c), nb, nc)
    points = sorted(index, key=index.get)
    return points, faces


def plate(t, reduction):
    import numpy as np
    import vtk
    from vtk.util import numpy_support as ns
    length, width, corner = 1.0, 0.6, 0.1
    holes = [(-0.25, 0.0, 0.1), (0.25, 0.0, 0.1)]
    r = 0.45 * t  # the rim's radius: nearly half the thickness
    h = 0.5 * t - r
    dx, dz = 0.006, t / 24
    xs = np.arange(-length / 2 - 0.05, length / 2 + 0.05, dx)
    ys = np.arange(-width / 2 - 0.05, width / 2 + 0.05, dx)
    zs = np.arange(-t, t, dz)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    # In the plane: a rounded rectangle shrunk by r, the holes grown by r.
    qx = np.abs(X) - (length / 2 - corner - r)
    qy = np.abs(Y) - (width / 2 - corner - r)
    d2 = np.hypot(np.maximum(qx, 0), np.maximum(qy, 0)) + np.minimum(np.maximum(qx, qy), 0) - corner
    for hx, hy, hr in holes:
        d2 = np.maximum(d2, -(np.hypot(X - hx, Y - hy) - hr - r))
    values = np.empty((len(zs), len(ys), len(xs)))
    for k, z in enumerate(zs):
        wx, wy = d2.T, abs(z) - h
        values[k] = np.minimum(np.maximum(wx, wy), 0) + np.hypot(np.maximum(wx, 0), max(wy, 0)) - r
    image = vtk.vtkImageData()
    image.SetDimensions(len(xs), len(ys), len(zs))
    image.SetSpacing(dx, dx, dz)
    image.SetOrigin(xs[0], ys[0], zs[0])
    image.GetPointData().SetScalars(ns.numpy_to_vtk(values.ravel(), deep=1))
    edges = vtk.vtkFlyingEdges3D()
    edges.SetInputData(image)
    edges.SetValue(0, 0.0)
    decimate = vtk.vtkQuadricDecimation()
    decimate.SetInputConnection(edges.GetOutputPort())
    decimate.SetTargetReduction(reduction)
    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(decimate.GetOutputPort())
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(clean.GetOutputPort())
    normals = vtk.vtkPolyDataNormals()  # orients the triangles outward
    normals.SetInputConnection(triangles.GetOutputPort())
    normals.ConsistencyOn()
    normals.AutoOrientNormalsOn()
    normals.SplittingOff()
    normals.Update()
    out = normals.GetOutput()
    points = ns.vtk_to_numpy(out.GetPoints().GetData())
    faces = ns.vtk_to_numpy(out.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
    return points, faces


def write_off(points, faces):
    print("OFF")
    print(len(points), len(faces), 0)
    for p in points:
        print("%.9g %.9g %.9g" % tuple(p))
    for f in faces:
        print(3, *f)


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "box":
        write_off(*box(*map(float, sys.argv[2:6])))
    elif len(sys.argv) == 4 and sys.argv[1] == "plate":
        write_off(*plate(float(sys.argv[2]), float(sys.argv[3])))
    else:
        sys.exit(__doc__)

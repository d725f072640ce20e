"""Folded sample cells per block of a run written with --keep-intermediate.

Reads OUT/decomposition_samples.vtu (each block's m^3 samples, first
direction fastest) and counts, per block, the cells with any of their 8
corner tets not positive against the block's majority, by layer of cells
along the third direction (for a shell block: the first layer on T1).

    /usr/bin/python3 scripts/sample_folds.py OUT [BLOCKS_TO_LIST]

Prints the total, then the blocks with the most folded cells: block index,
folded cells, folded cells per layer, the block's centre and the mean
corner of its folded cells (docs/validation.md, "Where the folds come from").
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_blocks(folder):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(folder + "/decomposition_samples.vtu")
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    block = vtk_to_numpy(grid.GetPointData().GetArray("block"))
    for b in range(int(block.max()) + 1):
        s = points[block == b]
        m = round(len(s) ** (1.0 / 3.0))
        yield b, s.reshape(m, m, m, 3)  # [k][j][i]


def corner_volumes(x):
    """The 8 corner tets' volumes of every cell of the grid x[k][j][i]."""
    def vol(o, a, b, c):
        return np.einsum("...i,...i", np.cross(a - o, b - o), c - o)

    c000, c100 = x[:-1, :-1, :-1], x[:-1, :-1, 1:]
    c010, c001 = x[:-1, 1:, :-1], x[1:, :-1, :-1]
    c110, c101 = x[:-1, 1:, 1:], x[1:, :-1, 1:]
    c011, c111 = x[1:, 1:, :-1], x[1:, 1:, 1:]
    return np.array([vol(c000, c100, c010, c001), vol(c100, c110, c000, c101),
                     vol(c010, c000, c110, c011), vol(c001, c011, c101, c000),
                     vol(c110, c010, c100, c111), vol(c101, c001, c111, c100),
                     vol(c011, c111, c001, c010), vol(c111, c101, c011, c110)])


def main():
    folder = sys.argv[1]
    listed = int(sys.argv[2]) if len(sys.argv) > 2 else 30
    rows, total = [], 0
    for b, x in read_blocks(folder):
        v = corner_volumes(x)
        sign = np.sign(np.median(v))
        folded = (v * sign <= 0).any(axis=0)
        n = int(folded.sum())
        total += n
        if n:
            per_layer = folded.sum(axis=(1, 2)).tolist()
            rows.append((n, b, per_layer, x.reshape(-1, 3).mean(0), x[:-1, :-1, :-1][folded].mean(0)))
    print("folded sample cells:", total)
    rows.sort(key=lambda r: -r[0])
    for n, b, per_layer, centre, folds in rows[:listed]:
        print(b, n, "per layer", per_layer, "centre", np.round(centre, 2), "folds around", np.round(folds, 2))


if __name__ == "__main__":
    main()

"""Makes defective copies of a good igaprep model file with h5py.

Usage: make_bad_hdf5.py GOOD.h5 OUTDIR
Writes OUTDIR/<defect>.h5 for each defect below and prints the defect names.
"""
import os
import shutil
import sys

import h5py
import numpy as np


def variant(good, outdir, name, edit):
    path = os.path.join(outdir, name + ".h5")
    shutil.copyfile(good, path)
    with h5py.File(path, "r+") as f:
        edit(f)
    print(name)


def replace(f, path, data):
    del f[path]
    f.create_dataset(path, data=data)


def main():
    good, outdir = sys.argv[1], sys.argv[2]
    variant(good, outdir, "missing_knots", lambda f: f.__delitem__("patches/000001/knots_u"))
    variant(good, outdir, "knots_length",
            lambda f: replace(f, "patches/000002/knots_v", np.append(f["patches/000002/knots_v"][...], 1.0)))

    def nan_cp(f):
        cp = f["patches/000000/control_points"][...]
        cp[1, 1, 1, 2] = np.nan
        replace(f, "patches/000000/control_points", cp)
    variant(good, outdir, "nan_control_point", nan_cp)

    def inf_weight(f):
        w = f["patches/000003/weights"][...]
        w[0, 0, 0] = np.inf
        replace(f, "patches/000003/weights", w)
    variant(good, outdir, "inf_weight", inf_weight)

    def missing_patch(f):
        itf = f["interfaces"][...]
        itf[2, 2] = 7
        replace(f, "interfaces", itf.astype(np.int32))
    variant(good, outdir, "interface_missing_patch", missing_patch)

    variant(good, outdir, "wrong_format", lambda f: f.attrs.__setitem__("format", "something-else"))
    variant(good, outdir, "wrong_version", lambda f: f.attrs.__setitem__("format_version", 2))
    variant(good, outdir, "cp_float32",
            lambda f: replace(f, "patches/000001/control_points",
                              f["patches/000001/control_points"][...].astype(np.float32)))
    variant(good, outdir, "interfaces_shape",
            lambda f: replace(f, "interfaces", f["interfaces"][...][:, :9].copy()))
    variant(good, outdir, "weights_shape",
            lambda f: replace(f, "patches/000003/weights", f["patches/000003/weights"][...][:, :, :-1].copy()))
    def huge_shape(f):
        # Declared, never written: chunks are allocated only when written.
        del f["patches/000000/control_points"]
        f.create_dataset("patches/000000/control_points", shape=(100000, 100000, 100000, 3), dtype="f8",
                         chunks=(1, 1, 1, 3))
    variant(good, outdir, "huge_shape", huge_shape)
    variant(good, outdir, "decreasing_knots",
            lambda f: replace(f, "patches/000000/knots_u", f["patches/000000/knots_u"][...][::-1].copy()))


if __name__ == "__main__":
    main()

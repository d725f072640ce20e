"""Independent reader of igaprep's HDF5 model format (h5py + scipy).

Usage: eval_hdf5.py MODEL.h5 SAMPLES SEED
Loads every patch with h5py, draws SAMPLES random parameters in its domain
and evaluates the B-spline/NURBS volume with scipy's B-spline design
matrices and the weights (no igaprep code). Prints one line per sample:
    patch u v w x y z
with every number as %.17g.
"""
import sys

import h5py
import numpy as np
from scipy.interpolate import BSpline


def main():
    path, samples, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = np.random.default_rng(seed)
    with h5py.File(path, "r") as f:
        assert f.attrs["format"] == "igaprep-multipatch", f.attrs["format"]
        assert int(f.attrs["format_version"]) == 1
        count = int(f["patches"].attrs["count"])
        for i in range(count):
            g = f["patches/%06d" % i]
            p = [int(d) for d in g.attrs["degrees"]]
            knots = [g["knots_u"][...], g["knots_v"][...], g["knots_w"][...]]
            cp = g["control_points"][...]  # (n_w, n_v, n_u, 3)
            w = g["weights"][...] if "weights" in g else np.ones(cp.shape[:3])
            params = np.empty((samples, 3))
            mats = []
            for d in range(3):
                t, k = knots[d], p[d]
                lo, hi = t[k], t[len(t) - k - 1]
                x = rng.uniform(lo, hi, samples)
                params[:, d] = x
                mats.append(BSpline.design_matrix(x, t, k).toarray())  # (samples, n_d)
            Bu, Bv, Bw = mats
            hom = cp * w[..., None]
            for s in range(samples):
                # sum over k (w), j (v), i (u)
                num = np.einsum("k,j,i,kjic->c", Bw[s], Bv[s], Bu[s], hom)
                den = np.einsum("k,j,i,kji->", Bw[s], Bv[s], Bu[s], w)
                x = num / den
                print("%d %.17g %.17g %.17g %.17g %.17g %.17g" % (i, *params[s], *x))


if __name__ == "__main__":
    main()

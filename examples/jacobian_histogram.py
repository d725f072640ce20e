"""Loads a model (an igaprep HDF5 file, or a case file that is run first),
refines it once for analysis, and plots the histogram of its scaled Jacobian
sampled on every element, with matplotlib, as a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/jacobian_histogram.py MODEL.h5|CASE.json OUT.png

Prints the smallest scaled Jacobian before and after the refinement: h-
refinement does not change the geometry, so they agree to round-off.
"""
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import igaprep


def scaled_jacobians(model, per_direction=4):
    """The scaled Jacobian det J / (|J_u| |J_v| |J_w|) at a grid of points in every patch."""
    t = (np.arange(per_direction) + 0.5) / per_direction
    values = []
    for patch in model.patches:
        spans = [np.unique(k) for k in patch.knots]
        params = [np.concatenate([a + t * (b - a) for a, b in zip(s[:-1], s[1:])]) for s in spans]
        w, v, u = np.meshgrid(params[2], params[1], params[0], indexing="ij")
        J = patch.jacobian(np.column_stack([u.ravel(), v.ravel(), w.ravel()]))
        norms = np.prod(np.linalg.norm(J, axis=1), axis=1)  # columns: d x / d u, d x / d v, d x / d w
        values.append(np.linalg.det(J) / norms)
    return np.concatenate(values)


def load(path):
    if path.endswith(".json"):
        model, report = igaprep.run(path, write_outputs=False)
        print(f"ran {path}: {report['pipeline']['verdict']}")
        return model
    return igaprep.read_model(path)


def main(source, out):
    model = load(source)
    fine = igaprep.refine(model, elevate=0, refine=1)
    coarse_values, fine_values = scaled_jacobians(model), scaled_jacobians(fine, per_direction=2)
    print(f"{len(model.patches)} patches; smallest sampled scaled Jacobian {coarse_values.min():.4f}, "
          f"after refinement {fine_values.min():.4f} ({fine_values.size} points)")
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.hist(fine_values, bins=50, range=(0, 1), color="#4878a8")
    ax.set_xlabel("scaled Jacobian")
    ax.set_ylabel("sample points")
    ax.set_title(f"{len(fine.patches)} patches, refined once")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")
    return 0 if coarse_values.min() > 0 and abs(coarse_values.min() - fine_values.min()) < 0.05 else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))

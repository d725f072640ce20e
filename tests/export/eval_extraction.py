"""Independent evaluator of an igaprep-bezier-extraction file (written from
docs/hdf5-format.md only).

Usage: eval_extraction.py FILE.h5 T_JSON
T_JSON: a JSON list of [element, tu, tv, tw] (Bernstein coordinates in
[0, 1]). Prints JSON: {"format", "format_version", "functions", "elements",
"faces", "labels", "materials", "points": [[x, y, z], ...]} with the
rational point sum_r w_f N_r(t) P_f / sum_r w_f N_r(t), N = C_e B(t), C_e
the element's operator from /operators.
"""
import json
import sys
from math import comb

import h5py
import numpy as np


def bernstein(p, t):
    return np.array([comb(p, i) * t**i * (1 - t) ** (p - i) for i in range(p + 1)])


def main():
    f = h5py.File(sys.argv[1], "r")
    P = f["control_points"][()]
    w = f["weights"][()]
    e = f["elements"]
    deg = e["degrees"][()]
    fo, fn = e["function_offsets"][()], e["functions"][()]
    op = e["extraction"][()]
    shape, xo, xv = f["operators/shape"][()], f["operators/offsets"][()], f["operators/values"][()]
    out = []
    for el, tu, tv, tw in json.loads(sys.argv[2]):
        pu, pv, pw = deg[el]
        funcs = fn[fo[el]:fo[el + 1]]
        k = op[el]
        C = xv[xo[k]:xo[k + 1]].reshape(shape[k])
        assert C.shape == (len(funcs), (pu + 1) * (pv + 1) * (pw + 1))
        B = np.kron(bernstein(pw, tw), np.kron(bernstein(pv, tv), bernstein(pu, tu)))  # u fastest
        N = C @ B
        wN = w[funcs] * N
        out.append(((wN @ P[funcs]) / wN.sum()).tolist())
    print(json.dumps({"format": f.attrs["format"], "format_version": int(f.attrs["format_version"]),
                      "functions": len(P), "elements": len(deg), "faces": len(f["boundary_faces"]),
                      "labels": [str(s) for s in f["labels"].asstr()[()]],
                      "materials": [str(s) for s in f["materials/name"].asstr()[()]], "points": out}))


if __name__ == "__main__":
    main()

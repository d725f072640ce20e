"""Independent reader of BEXT 2.0 ASCII files (the layout docs/export-formats.md
documents: one part per file, dense coefficient blocks; element blocks of any
number of functions per element, as a T-spline's).

Usage: read_bext.py FILE.bext
Reconstructs every element's Bernstein control points as C^T times its nodes
in homogeneous coordinates (vector k of an element multiplies its k-th node).
Prints JSON: {"pid", "nodes", "vectors", "wfl", "elements": [{"block",
"index", "degrees", "nodes", "points": [[x, y, z]...], "weights": [...]}]}.
"""
import json
import sys

import numpy as np


def main():
    lines = open(sys.argv[1]).read().splitlines()
    assert lines[0].strip() == "B E X T 2.0", lines[0]
    tokens = []
    for ln in lines[1:]:
        if not ln.startswith("$#") and ln.strip():
            tokens.append(ln.split())
    assert lines[-1] == "$#END FILE", lines[-1]
    pos = 0

    def take(count, kind):
        nonlocal pos
        out = []
        while len(out) < count:
            out.extend(kind(x) for x in tokens[pos])
            pos += 1
        assert len(out) == count, (len(out), count)
        return out

    pid, numnod, numel, numcv, wfl = take(5, int)
    nodes = np.array([take(4, float) for _ in range(numnod)])
    neb = take(1, int)[0]
    blocks = [take(7, int) for _ in range(neb)]
    elements = []
    for b, (etype, ne, nn, ncv, pr, ps, pt) in enumerate(blocks):
        # nn: the element's functions; (pr+1)(ps+1)(pt+1) for a tensor patch,
        # any count for a T-spline's element block (checked against the
        # vectors' length below).
        assert etype == 1 and nn == ncv
        for i in range(ne):
            ids = take(nn, int)
            vecs = take(ncv, int)
            assert ids == sorted(ids) and len(set(ids)) == len(ids), "node ids ascending and distinct"
            elements.append({"block": b, "index": i, "degrees": [pr, ps, pt], "ids": ids, "vecs": vecs})
    ndcvb, nscvb = take(2, int)
    assert nscvb == 0
    sizes = [take(2, int) for _ in range(ndcvb)]
    vectors = []
    for ncv, ncvc in sizes:
        vectors.extend(take(ncvc, float) for _ in range(ncv))
    assert len(vectors) == numcv and pos == len(tokens), "counts and trailing data"
    assert len(elements) == numel
    out = []
    for e in elements:
        pr, ps, pt = e["degrees"]
        assert all(len(vectors[v - 1]) == (pr + 1) * (ps + 1) * (pt + 1) for v in e["vecs"]), "vector length"
        C = np.array([vectors[v - 1] for v in e["vecs"]])  # rows: the element's nodes in order
        P = nodes[[i - 1 for i in e["ids"]]]
        hom = np.column_stack([P[:, :3] * P[:, 3:4], P[:, 3]])
        B = C.T @ hom
        out.append({"block": e["block"], "index": e["index"], "degrees": e["degrees"], "nodes": e["ids"],
                    "points": (B[:, :3] / B[:, 3:4]).tolist(), "weights": B[:, 3].tolist()})
    print(json.dumps({"pid": pid, "nodes": numnod, "vectors": numcv, "wfl": wfl, "elements": out}))


if __name__ == "__main__":
    main()

"""Independent reader of the BEXT 2.0 ASCII layout igaprep writes.

Usage: read_bext.py FILE.bext
Parses nodes, element blocks, elements and dense coefficient blocks (the
elements refer to coefficient vectors by id, so vectors may be shared), and
reconstructs every element's Bernstein control points as C^T times its
global nodes in homogeneous coordinates. Prints JSON: {"nodes": N, "vectors": NUMCV,
"elements": [{"patch", "element": [eu, ev, ew], "degrees", "points":
[[x, y, z]...], "weights": [...]}]}.
"""
import json
import sys

import numpy as np


def main():
    lines = open(sys.argv[1]).read().splitlines()
    assert lines[0].strip() == "B E X T 2.0", lines[0]
    body = []  # (tokens, comment) pairs in order
    for ln in lines[1:]:
        if ln.startswith("$"):
            body.append(("comment", ln[1:].split()))
        elif ln.strip():
            body.append(("data", ln.split()))
    pos = 0

    def data():
        nonlocal pos
        while body[pos][0] != "data":
            pos += 1
        pos += 1
        return body[pos - 1][1]

    def ints(count):
        out = []
        while len(out) < count:
            out.extend(int(x) for x in data())
        assert len(out) == count
        return out

    def reals(count):
        out = []
        while len(out) < count:
            out.extend(float(x) for x in data())
        assert len(out) == count
        return out

    numnod, numel, numcv, _ = ints(4)
    nodes = np.array([reals(4) for _ in range(numnod)])
    nblock = ints(1)[0]
    blocks = [ints(7) for _ in range(nblock)]
    elements = []
    for etype, nel, nnpe, ncvpe, pr, ps, pt in blocks:
        for _ in range(nel):
            while body[pos][0] != "comment" or body[pos][1][:1] != ["patch"] or "element" not in body[pos][1]:
                pos += 1
            c = body[pos][1]
            pos += 1
            patch, eu, ev, ew = int(c[1]), int(c[3]), int(c[4]), int(c[5])
            ids = ints(nnpe)
            vecs = ints(ncvpe)
            elements.append({"patch": patch, "element": [eu, ev, ew], "degrees": [pr, ps, pt],
                             "ids": ids, "vecs": vecs})
    ndcvb = ints(1)[0]
    sizes = [ints(2) for _ in range(ndcvb)]
    vectors = []
    for ncv, ncvc in sizes:
        for _ in range(ncv):
            vectors.append(reals(ncvc))
    assert len(vectors) == numcv, (len(vectors), numcv)
    assert pos == len(body) or all(k == "comment" for k, _ in body[pos:]), "trailing data"
    out = []
    for e in elements:
        C = np.array([vectors[v - 1] for v in e["vecs"]])  # rows: local functions
        P = nodes[[i - 1 for i in e["ids"]]]
        hom = np.column_stack([P[:, :3] * P[:, 3:4], P[:, 3]])
        B = C.T @ hom
        out.append({"patch": e["patch"], "element": e["element"], "degrees": e["degrees"],
                    "points": (B[:, :3] / B[:, 3:4]).tolist(), "weights": B[:, 3].tolist()})
    print(json.dumps({"nodes": numnod, "vectors": numcv, "elements": out}))


if __name__ == "__main__":
    main()

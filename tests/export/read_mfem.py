"""Independent reader and checker of an MFEM NURBS mesh v1.0 in patch form.

Usage: read_mfem.py FILE.mesh
Parses the sections as MFEM's Mesh::LoadPatchTopo and NURBSPatch(istream)
do, and checks what MFEM's NURBSExtension checks (CheckPatches,
CheckBdrPatches) plus geometric consistency: parallel edges of a patch carry
the same knot vector in the same sense, each knot-vector class has one knot
vector, boundary faces are outward with both knot vectors starting at their
first vertex, and the corner control points of patches sharing a vertex
coincide. Prints JSON {"elements", "boundary", "edges", "vertices",
"patches": [{"degrees", "ncp", "knots", "points", "weights"}], "problems"}.
"""
import json
import sys

EDGES = [(0, 1), (1, 2), (3, 2), (0, 3), (4, 5), (5, 6), (7, 6), (4, 7), (0, 4), (1, 5), (2, 6), (3, 7)]
FACES = [(3, 2, 1, 0), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7), (4, 5, 6, 7)]
CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def tokens(path):
    out = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            out.extend(line.split())
    return out


def main():
    tok = tokens(sys.argv[1])
    pos = 0

    def take():
        nonlocal pos
        pos += 1
        return tok[pos - 1]

    assert " ".join(tok[:4]) == "MFEM NURBS mesh v1.0", tok[:4]
    pos = 4
    assert take() == "dimension" and int(take()) == 3
    assert take() == "elements"
    elements = []
    for _ in range(int(take())):
        attr, geom = int(take()), int(take())
        assert geom == 5
        elements.append([attr] + [int(take()) for _ in range(8)])
    assert take() == "boundary"
    boundary = []
    for _ in range(int(take())):
        attr, geom = int(take()), int(take())
        assert geom == 3
        boundary.append([attr] + [int(take()) for _ in range(4)])
    assert take() == "edges"
    edges = []
    for _ in range(int(take())):
        edges.append([int(take()), int(take()), int(take())])
    assert take() == "vertices"
    nv = int(take())
    assert take() == "patches"
    patches = []
    for _ in elements:
        assert take() == "knotvectors"
        assert int(take()) == 3
        degrees, ncp, knots = [], [], []
        for d in range(3):
            p, n = int(take()), int(take())
            degrees.append(p)
            ncp.append(n)
            knots.append([float(take()) for _ in range(n + p + 1)])
        assert take() == "dimension" and int(take()) == 3
        assert take() == "controlpoints"
        pts, ws = [], []
        for _ in range(ncp[0] * ncp[1] * ncp[2]):
            h = [float(take()) for _ in range(4)]
            ws.append(h[3])
            pts.append([h[0] / h[3], h[1] / h[3], h[2] / h[3]])
        patches.append({"degrees": degrees, "ncp": ncp, "knots": knots, "points": pts, "weights": ws})
    assert pos == len(tok), "trailing data"

    problems = []
    # Signed knot-vector index of a directed vertex pair (a -> b): k if the
    # knot vector runs a -> b, -1-k if b -> a (MFEM's FlipIndexSign).
    directed = {}
    for k, a, b in edges:
        directed[(a, b)] = k
        directed[(b, a)] = -1 - k
    if any(not (0 <= v < nv) for e in elements for v in e[1:]):
        problems.append("vertex index out of range")

    def norm(U, rev):
        a, b = U[0], U[-1]
        t = [(u - a) / (b - a) for u in U]
        return [1 - x for x in reversed(t)] if rev else t

    kv_first = {}
    corner_xyz = {}
    for p, el in enumerate(elements):
        v = el[1:]
        pt = patches[p]
        signed = []
        for (i, j) in EDGES:
            key = (v[i], v[j])
            if key not in directed:
                problems.append("patch %d: edge %s not listed" % (p, key))
                signed.append(None)
            else:
                signed.append(directed[key])
        for d, group in enumerate([(0, 2, 4, 6), (1, 3, 5, 7), (8, 9, 10, 11)]):
            s = {signed[e] for e in group}
            if len(s) != 1:
                problems.append("patch %d direction %d: parallel edges disagree %s" % (p, d, s))
                continue
            k = s.pop()
            rev = k < 0
            kk = -1 - k if rev else k
            U = norm(pt["knots"][d], rev)
            if kk in kv_first:
                V = kv_first[kk]
                if len(U) != len(V) or max(abs(x - y) for x, y in zip(U, V)) > 1e-10:
                    problems.append("patch %d direction %d: knot vector differs from class %d" % (p, d, kk))
            else:
                kv_first[kk] = U
        n = pt["ncp"]
        for c, (cu, cv, cw) in enumerate(CORNERS):
            idx = (n[0] - 1) * cu + n[0] * ((n[1] - 1) * cv + n[1] * (n[2] - 1) * cw)
            x = pt["points"][idx]
            if v[c] in corner_xyz:
                y = corner_xyz[v[c]]
                if max(abs(a - b) for a, b in zip(x, y)) > 1e-9:
                    problems.append("vertex %d: corners of patches differ %s %s" % (v[c], x, y))
            else:
                corner_xyz[v[c]] = x
    # Boundary faces: outward (an even rotation of an element face cycle) and
    # both first edges positive (CheckBdrPatches).
    for b in boundary:
        q = b[1:]
        for e in range(2):
            k = directed.get((q[e], q[e + 1]))
            if k is None or k < 0:
                problems.append("boundary %s: edge %d does not start its knot vector" % (q, e))
        found = False
        for el in elements:
            v = el[1:]
            for f in FACES:
                cyc = [v[i] for i in f]
                for r in range(4):
                    if cyc[r:] + cyc[:r] == q:
                        found = True
        if not found:
            problems.append("boundary %s is not an outward element face" % (q,))
    print(json.dumps({"elements": elements, "boundary": boundary, "edges": edges, "vertices": nv,
                      "patches": patches, "problems": problems}))


if __name__ == "__main__":
    main()

"""Independent reader of a G+Smo XML multipatch (xml.etree only).

Usage: read_gismo.py FILE.xml
Follows G+Smo's reader (gsXml<gsMultiPatch>, getInterfaces, getBoundaries):
patch numbers are Geometry ids mapped through <patches>, and the normal
direction's dirmap/orient entries are set as G+Smo sets them. Prints JSON:
{"patches": [{"type", "degrees", "knots", "weights", "coefs"}...],
 "interfaces": [[p1, s1, p2, s2, m0, m1, m2, o0, o1, o2, name]...],
 "boundaries": [[patch, side, name]...],
 "conditions": [[type, function, unknown, name]...], "functions": {index: [c...]},
 "materials": [{"Material", "YoungsModulus", "PoissonsRatio", "Patches"}...],
 "displacement": [coefs per patch] (only with a second MultiPatch)}
Follows G+Smo's gsBoundaryConditions reader (multipatch = the MultiPatch's
id, <Function index> with <c> components, <bc type function unknown name>)
and gsOptionList's (<real|int|bool|string label desc value>).
"""
import json
import sys
import xml.etree.ElementTree as ET


def numbers(text, cast=float):
    return [cast(x) for x in text.split()]


def tensor_basis(node):
    assert node.get("type") == "TensorBSplineBasis3", node.get("type")
    comps = node.findall("Basis")
    assert len(comps) == 3
    degrees, knots = [], []
    for i, b in enumerate(comps):
        assert b.get("type") == "BSplineBasis" and int(b.get("index")) == i
        kv = b.find("KnotVector")
        degrees.append(int(kv.get("degree")))
        knots.append(numbers(kv.text))
    return degrees, knots


def patch_range(mp):
    pnode = mp.find("patches")
    assert pnode.get("type") == "id_range"
    first, last = numbers(pnode.text, int)
    return first, last


def read_conditions(root, multipatch_id, out):
    bcs = root.findall("boundaryConditions")
    assert len(bcs) == 1
    assert int(bcs[0].get("multipatch")) == multipatch_id
    out["functions"] = {}
    for f in bcs[0].findall("Function"):
        assert int(f.get("dim")) == 3
        out["functions"][int(f.get("index"))] = [c.text for c in f.findall("c")]
    out["conditions"] = [[b.get("type"), int(b.get("function")), int(b.get("unknown")), b.get("name")]
                         for b in bcs[0].findall("bc")]


def options(node):
    result = {}
    for o in node:
        assert o.get("desc") is not None
        value = o.get("value")
        result[o.get("label")] = float(value) if o.tag == "real" else value
    return result


def main():
    root = ET.parse(sys.argv[1]).getroot()
    assert root.tag == "xml"
    geometries = {}
    for g in root.findall("Geometry"):
        gid = int(g.get("id"))
        basis = g.find("Basis")
        if g.get("type") == "TensorNurbs3":
            assert basis.get("type") == "TensorNurbsBasis3"
            degrees, knots = tensor_basis(basis.find("Basis"))
            weights = numbers(basis.find("weights").text)
        else:
            assert g.get("type") == "TensorBSpline3", g.get("type")
            degrees, knots = tensor_basis(basis)
            weights = []
        coefs_node = g.find("coefs")
        assert int(coefs_node.get("geoDim")) == 3
        flat = numbers(coefs_node.text)
        n = 1
        for d in range(3):
            n *= len(knots[d]) - degrees[d] - 1
        assert len(flat) == 3 * n, (len(flat), n)
        if weights:
            assert len(weights) == n
        geometries[gid] = {"type": g.get("type"), "degrees": degrees, "knots": knots,
                           "weights": weights, "coefs": [flat[3 * i:3 * i + 3] for i in range(n)]}

    multipatches = root.findall("MultiPatch")
    mp = multipatches[0]
    assert int(mp.get("parDim")) == 3
    first, last = patch_range(mp)
    ids = {gid: gid - first for gid in range(first, last + 1)}
    patches = [geometries[gid] for gid in range(first, last + 1)]
    out = {"patches": patches}
    if len(multipatches) > 1:
        f2, l2 = patch_range(multipatches[1])
        assert l2 - f2 == last - first
        out["displacement"] = [geometries[gid]["coefs"] for gid in range(f2, l2 + 1)]
    read_conditions(root, int(mp.get("id")), out)
    out["materials"] = [options(o) for o in root.findall("OptionList")]

    interfaces = []
    for inode in mp.findall("interfaces"):
        name = inode.get("name", "")
        vals = numbers(inode.text, int)
        assert len(vals) % 10 == 0
        for r in range(0, len(vals), 10):
            p1, s1, p2, s2 = vals[r:r + 4]
            dirmap, orient = vals[r + 4:r + 7], vals[r + 7:r + 10]
            # as G+Smo's boundaryInterface constructor: normal direction
            n1, n2 = (s1 - 1) // 2, (s2 - 1) // 2
            dirmap[n1] = n2
            orient[n1] = 1 if ((s1 - 1) % 2) == ((s2 - 1) % 2) else 0
            interfaces.append([ids[p1], s1, ids[p2], s2] + dirmap + orient + [name])
    boundaries = []
    for bnode in mp.findall("boundary"):
        name = bnode.get("name", "")
        vals = numbers(bnode.text, int)
        for r in range(0, len(vals), 2):
            boundaries.append([ids[vals[r]], vals[r + 1], name])
    out["interfaces"], out["boundaries"] = interfaces, boundaries
    print(json.dumps(out))


if __name__ == "__main__":
    main()

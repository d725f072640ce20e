"""The igaprep Python module (pytest, run by ctest with PYTHONPATH=build/python).

A unit cube built by hand checks the model API and the solve against the
exact uniaxial solution; one pipeline run on sphere2 checks run(), check(),
read_model/write_model, export and evaluation against the C++ library's
own figures.
"""
import json
import os

import numpy as np
import pytest

import igaprep

MODELS = os.path.join(os.environ["IGAPREP_SOURCE_DIR"], "models")


def cube(elements=2, degree=1):
    """The unit cube as one patch, sides labelled; E = 200, nu = 0.3."""
    n = elements + degree
    knots = [0.0] * degree + list(np.linspace(0.0, 1.0, elements + 1)) + [1.0] * degree
    g = np.array([np.mean(knots[i + 1:i + degree + 1]) for i in range(n)])  # Greville: x(u) = u
    w, v, u = np.meshgrid(g, g, g, indexing="ij")
    cps = np.stack([u, v, w], axis=-1)
    m = igaprep.Model()
    m.add_material("steel", 200.0, 0.3)
    m.add_patch((degree,) * 3, [knots] * 3, cps)
    for side, label in enumerate(["x0", "x1", "y0", "y1", "z0", "z1"], start=1):
        m.add_boundary(0, side, label)
    return m


def test_model_built_by_hand_has_the_hdf5_shapes():
    m = cube(elements=2, degree=2)
    p = m.patches[0]
    assert p.degrees == [2, 2, 2] or tuple(p.degrees) == (2, 2, 2)
    assert p.control_points.shape == (4, 4, 4, 3)
    assert p.weights is None
    assert [len(k) for k in p.knots] == [7, 7, 7]
    assert m.labels == ["x0", "x1", "y0", "y1", "z0", "z1"]
    assert m.boundaries.shape == (6, 3)
    assert m.interfaces.shape == (0, 10)
    assert m.materials[0]["young_modulus"] == 200.0


def test_evaluation_and_jacobian_of_the_identity_map():
    p = cube(elements=3, degree=2).patches[0]
    uvw = np.array([[0.1, 0.2, 0.3], [0.9, 0.5, 0.05]])
    np.testing.assert_allclose(p.evaluate(uvw), uvw, atol=1e-14)
    np.testing.assert_allclose(p.jacobian(uvw), np.broadcast_to(np.eye(3), (2, 3, 3)), atol=1e-13)
    with pytest.raises(igaprep.BadInputError, match=r"parameters must lie in \[0, 1\]"):
        p.evaluate(np.array([[1.5, 0.0, 0.0]]))


def test_uniaxial_tension_matches_the_exact_solution():
    # Symmetry planes x0, y0, z0 fixed in their normal direction, traction t on z1:
    # u_z = t z / E, u_x = -nu t x / E; energy t^2 / (2 E) on the unit volume.
    t, e, nu = 5.0, 200.0, 0.3
    s = igaprep.solve(cube(), fix={"x0": "x", "y0": "y", "z0": "z"}, traction={"z1": (0.0, 0.0, t)})
    assert s["strain_energy"] == pytest.approx(t * t / (2 * e), rel=1e-10)
    d = s["displacements"][0]
    assert d.shape == (3, 3, 3, 3)
    np.testing.assert_allclose(d[-1, :, :, 2], t / e, rtol=1e-10)
    np.testing.assert_allclose(d[:, :, -1, 0], -nu * t / e, rtol=1e-10)
    assert s["max_displacement"] == pytest.approx(np.linalg.norm([nu * t / e, nu * t / e, t / e]), rel=1e-10)


def test_total_force_and_rotation_reach_the_solve():
    # A total force on z1 (area 1) is the traction itself; a spin about z
    # through the cube's centre gives an energy quadratic in omega^2.
    t, e = 5.0, 200.0
    s = igaprep.solve(cube(), fix={"x0": "x", "y0": "y", "z0": "z"}, force={"z1": (0.0, 0.0, t)})
    assert s["strain_energy"] == pytest.approx(t * t / (2 * e), rel=1e-10)
    spin = {"density": 2.0, "angular_velocity": 3.0, "axis": (0, 0, 1), "point": (0.5, 0.5, 0.0)}
    fix = {"x0": "x", "y0": "y", "z0": "z"}
    e1 = igaprep.solve(cube(), fix=fix, rotation=spin)["strain_energy"]
    spin["angular_velocity"] = 6.0
    e2 = igaprep.solve(cube(), fix=fix, rotation=spin)["strain_energy"]
    assert e1 > 0.0
    assert e2 == pytest.approx(16.0 * e1, rel=1e-10)
    with pytest.raises(igaprep.BadInputError, match="rotation: needs 'density' and 'angular_velocity'"):
        igaprep.solve(cube(), fix=fix, rotation={"density": 1.0})


def test_errors_carry_the_library_message():
    with pytest.raises(igaprep.BadInputError, match="unknown label 'top'"):
        igaprep.solve(cube(), fix="top")
    with pytest.raises(ValueError, match="'surfaces' must be a non-empty list"):
        igaprep.run({"surfaces": []})
    with pytest.raises(igaprep.Error, match="cannot"):
        igaprep.read_model("/nonexistent/model.h5")


@pytest.fixture(scope="module")
def sphere2(tmp_path_factory):
    """sphere2 through the pipeline (validation off: seconds, not tens)."""
    with open(os.path.join(MODELS, "sphere2", "case.json")) as f:
        case = json.load(f)
    case["validation"] = {"enabled": False}
    stages = []
    out = tmp_path_factory.mktemp("sphere2")
    model, report = igaprep.run(case, folder=os.path.join(MODELS, "sphere2"), output_dir=str(out),
                                on_stage=lambda s: stages.append(s["stage"]))
    return model, report, stages, out


def test_run_returns_the_model_and_the_report(sphere2):
    model, report, stages, out = sphere2
    assert stages == ["validate", "midsurface", "base", "decompose", "param", "fit", "check", "export"]
    assert report["passed"] and report["check"]["passed"]
    assert report["check"]["summary"]["negative"] == 0
    assert len(model) == 26 == report["check"]["summary"]["patches"]
    assert model.labels == ["outer", "inner"]
    assert sorted({p.material for p in model.patches}) == [0, 1]
    assert model.interfaces.shape[1] == 10 and model.boundaries.shape[1] == 3
    assert json.loads(model.provenance["inputs"])["options"]["fit"]["degree"] == 3
    assert os.path.exists(out / "model.h5") and report["output_dir"] == str(out)


def test_check_of_the_returned_model_agrees_with_the_run(sphere2):
    model, report, _, _ = sphere2
    again = igaprep.check(model)
    assert again["passed"]
    assert again["summary"]["elements"] == report["check"]["summary"]["elements"]
    assert again["quality"]["scaled_jacobian"]["min"] == report["check"]["quality"]["scaled_jacobian"]["min"]
    criteria = {c["name"]: c for c in again["summary"]["criteria"]}
    assert not criteria["fidelity"]["checked"] and criteria["fidelity"]["passed"]  # no surfaces given


def test_check_fidelity_limit_decides_the_verdict(sphere2):
    model, report, _, _ = sphere2
    surfaces = [igaprep.read_surface(os.path.join(MODELS, "sphere2", f)) for f in ("outer.off", "inner.off")]
    fidelity = {c["name"]: c for c in report["check"]["summary"]["criteria"]}["fidelity"]["value"]
    assert 0.0 < fidelity < 0.005
    assert igaprep.check(model, surfaces)["passed"]
    tight = igaprep.check(model, surfaces, fidelity_limit=50.0 * fidelity)  # percent: half the figure
    assert not tight["passed"]
    assert tight["summary"]["verdict"].startswith("FAIL: fidelity: ")


def test_written_model_reads_back_bit_for_bit(sphere2, tmp_path):
    model, _, _, _ = sphere2
    igaprep.write_model(model, str(tmp_path / "m.h5"))
    back = igaprep.read_model(str(tmp_path / "m.h5"))
    for a, b in zip(model.patches, back.patches):
        assert np.array_equal(a.control_points, b.control_points)
    assert np.array_equal(model.interfaces, back.interfaces)
    paths = igaprep.export(model, ["gismo", "mfem"], str(tmp_path / "m"))
    assert [os.path.basename(p) for p in paths] == ["m.xml", "m.mesh"]


def test_refine_keeps_the_geometry(sphere2):
    model, _, _, _ = sphere2
    fine = igaprep.refine(model, elevate=0, refine=1)
    p, q = model.patches[5], fine.patches[5]
    assert q.control_points.shape[0] == 2 * p.control_points.shape[0] - p.degrees[2]
    uvw = np.random.default_rng(1).random((20, 3))
    np.testing.assert_allclose(q.evaluate(uvw), p.evaluate(uvw), atol=1e-12)


def test_reduce_takes_back_a_refinement_within_its_bound():
    """A cube refined once is the same cube: reduction gives back 2 elements."""
    coarse = cube(elements=2, degree=2)
    fine = igaprep.refine(coarse, elevate=0, refine=1)
    reduced, figures = igaprep.reduce(fine, tolerance=1e-9)
    assert figures["control_points_before"] == 6 ** 3
    assert figures["control_points_after"] == 3 ** 3  # the linear map needs no interior knot
    assert figures["bound"] <= 1e-9
    assert figures["measured"] <= figures["bound"] + 1e-14  # the bound is exact; evaluation rounds
    assert figures["passed"]
    uvw = np.random.default_rng(2).random((20, 3))
    np.testing.assert_allclose(reduced.patches[0].evaluate(uvw), fine.patches[0].evaluate(uvw), atol=1e-12)
    with pytest.raises(Exception, match="tolerance"):
        igaprep.reduce(fine)

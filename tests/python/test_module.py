"""The Python module against the command: the same scene gives the same numbers and the same errors.

The independent side of each check is the other front end (the `skinfem` executable, run as a user would)
and, for the documentation (README.md, docs/*.md), the examples run exactly as written. Environment (set by
ctest): PYTHONPATH with the package, SKINFEM_EXE the command, SKINFEM_SOURCE_DIR the source tree.
"""
import glob
import json
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import skinfem

SRC = os.environ["SKINFEM_SOURCE_DIR"]
EXE = os.environ["SKINFEM_EXE"]
FLAT = os.path.join(SRC, "scenes", "flat_layer.json")
HERTZ = os.path.join(SRC, "scenes", "hertz_layer.json")
COARSE_CAP = os.path.join(SRC, "tests", "app", "data", "coarse_cap.json")
# Timing and memory differ from run to run; everything else must agree.
VOLATILE = re.compile(r"(wall|peak_rss|seconds|ms_per_position)")


def run_cli(*args):
    return subprocess.run([EXE, *args], capture_output=True, text=True)


def assert_same(a, b, where="", rel=1e-12):
    """Equal structure, strings and booleans; numbers to `rel` relative."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), f"{where}: keys {sorted(set(a) ^ set(b))}"
        for k in a:
            if not VOLATILE.search(k):
                assert_same(a[k], b[k], f"{where}/{k}", rel)
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{where}[{i}]", rel)
    elif isinstance(a, float) or isinstance(b, float):
        assert math.isclose(a, b, rel_tol=rel, abs_tol=1e-300), f"{where}: {a} != {b}"
    else:
        assert a == b, f"{where}: {a!r} != {b!r}"


@pytest.fixture(scope="module")
def flat_kfit(tmp_path_factory):
    out = tmp_path_factory.mktemp("kfit")
    r = run_cli("kfit", FLAT, "--out", str(out))
    assert r.returncode == 0, r.stderr
    with open(out / "kfit.json") as f:
        return json.load(f)


def test_kfit_reproduces_the_command(flat_kfit):
    fit = skinfem.kfit(skinfem.scene(FLAT))
    assert_same(flat_kfit, fit.to_dict())
    # The typed attributes are the same numbers as the file's.
    s = fit.sensors[0]
    assert s.k_central == flat_kfit["k_central"] and s.k_lsq_line == flat_kfit["k_lsq_line"]
    assert s.k_central_exact == flat_kfit["k_central_exact"]
    names = ["zz", "zx", "xz", "xx"]
    assert np.array_equal(s.component_k, [flat_kfit["components"][c]["k"] for c in names])
    assert np.array_equal(s.disc_max_diff_over_peak, [flat_kfit["fe_vs_exact_max_err_over_peak"][c] for c in names])
    assert fit.path == flat_kfit["path"] and fit.dofs == flat_kfit["dofs"] and fit.verdict == flat_kfit["verdict"]


def test_contact_reproduces_the_command(tmp_path):
    # hertz_layer is frictionless: the automatic path is the meridian in both front ends; the 3D one asked
    # (Release only: under the sanitizers the 3D contact runs in the contact suites and the defect test below).
    paths = ("auto",) if os.environ.get("SKINFEM_SANITIZE") else ("auto", "3d")
    for path in paths:
        out = tmp_path / path
        r = run_cli("contact", HERTZ, "--path", path, "--out", str(out))
        assert r.returncode == 0, r.stderr
        with open(out / "summary.json") as f:
            summary = json.load(f)
        c = skinfem.contact(skinfem.scene(HERTZ), path=path)
        assert summary["path"] == ("meridian" if path == "auto" else "3d")
        assert_same(summary, c.to_dict())
        assert c.friction == summary["friction"]
        assert (c.contact_radius_mm, c.p0_kPa, c.indentation_um) == (
            summary["contact_radius_mm"], summary["p0_kPa"], summary["indentation_um"])
        # The sensor readings of the command's sensors.csv (written with 10 digits).
        rows = [line.split(",") for line in (out / "sensors.csv").read_text().splitlines()[1:]]
        assert np.allclose(c.readings_kPa, [[float(r[3]), float(r[4])] for r in rows], rtol=1e-9, atol=1e-12)
        # One non-negative nodal pressure per multiplier, each at its zone vertex.
        where = c.multiplier_r_mm if path == "auto" else c.multiplier_xy_mm
        assert c.pressure_kPa.shape == (where.shape[0],) and c.pressure_kPa.min() >= 0
    with pytest.raises(skinfem.SceneError, match="^friction: 'sticky' is not one of none, static, uncoupled, coupled$"):
        skinfem.contact(skinfem.scene(HERTZ), friction="sticky")
    with pytest.raises(skinfem.SceneError, match="^path: 'flat' is not one of auto, 3d, meridian$"):
        skinfem.contact(skinfem.scene(HERTZ), path="flat")


SWEEP_CONTACT = {
    "force": 0.2, "zone_radius": 2.6, "h": 0.8,
    "friction": {"mode": "coupled", "mu": 1.0, "static_ratio": 0.1, "direction": [1.0, 0.0]},
    "sweep": {"from": [-1.0, 0.0], "to": [1.0, 0.0], "positions": 21, "hole_diameter": 0.5, "h": 0.5}}


@pytest.fixture(scope="module")
def sweep_path(tmp_path_factory):
    """The Hertz layer with a short coupled sweep: small enough for a test, both cases, every sensor."""
    with open(HERTZ) as f:
        scene = json.load(f)
    scene["contact"].update(SWEEP_CONTACT)
    path = tmp_path_factory.mktemp("sweep") / "sweep.json"
    path.write_text(json.dumps(scene))
    return path


def test_defect_reproduces_the_command(tmp_path, sweep_path):
    path = sweep_path
    # The error bar's levels coarse (x3, x2) to keep the test short; the same levels on both sides.
    r = run_cli("defect", str(path), "--error-scales", "3,2", "--out", str(tmp_path / "out"))
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "out" / "summary.json") as f:
        summary = json.load(f)
    d = skinfem.defect(skinfem.scene(str(path)), error_scales=(3, 2))
    assert [l["mesh_scale"] for l in summary["largest_sliding"]["levels"]] == [3, 2, 1]
    assert_same(summary, d.to_dict())
    assert d.cases == ["static", "sliding"] and d.u_mm.shape == (21,)
    # defect.csv (10 digits): case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa
    rows = [line.split(",") for line in (tmp_path / "out" / "defect.csv").read_text().splitlines()[1:]]
    for case in d.cases:
        v = d.varsigma_kPa(case)
        ref = np.array([[float(x[3]), float(x[4])] for x in rows if x[0] == case]).reshape(v.shape)
        assert np.allclose(v, ref, rtol=1e-9, atol=1e-12 * np.abs(ref).max())
    with pytest.raises(skinfem.SceneError, match="^case: 'rolling' is not one of static, sliding$"):
        d.varsigma_kPa("rolling")
    with pytest.raises(skinfem.SceneError, match="contact.sweep: missing"):
        skinfem.defect(skinfem.scene(HERTZ))


def test_report_reproduces_the_command(tmp_path):
    # The main job through the library's one call (pipeline/report.hpp), as `skinfem report` runs it: the
    # dict is the command's report.json but for the figures, which only the command draws.
    r = run_cli("report", COARSE_CAP, "--fast", "--out", str(tmp_path / "out"))
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "out" / "report.json") as f:
        cli = json.load(f)
    cli.pop("figures_exit_code")
    d = skinfem.report(skinfem.scene(COARSE_CAP), fast=True)
    assert_same(cli, d)
    assert "left_out" in d["fast"] and "crosscheck" not in os.listdir(tmp_path)  # the library wrote nothing
    with pytest.raises(skinfem.SceneError, match="^error_scales: a fast report draws no error bars"):
        skinfem.report(skinfem.scene(COARSE_CAP), error_scales=[2, 1.41], fast=True)
    with pytest.raises(skinfem.SceneError, match=r"^--error-scales: 0\.5"):
        skinfem.report(skinfem.scene(COARSE_CAP), error_scales=[0.5, 2])


def test_scene_from_dict_is_the_scene_from_its_file():
    with open(FLAT) as f:
        as_dict = json.load(f)
    a, b = skinfem.scene(FLAT), skinfem.scene(as_dict)
    assert (a.name, a.E_MPa, a.nu, a.nominal_thickness_mm) == (b.name, b.E_MPa, b.nu, b.nominal_thickness_mm)
    assert np.array_equal(a.sensor_positions_mm, b.sensor_positions_mm)
    assert a.sensor_positions_mm.shape == (1, 2)


@pytest.mark.parametrize(
    "field, value",
    [(("material", "E"), -3.0), (("material", "nu"), 0.7), (("geometry", "type"), "torus"), (("sensors",), 5)],
)
def test_bad_scene_raises_the_commands_message(tmp_path, field, value):
    with open(FLAT) as f:
        scene = json.load(f)
    node = scene
    for key in field[:-1]:
        node = node[key]
    node[field[-1]] = value
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(scene))
    r = run_cli("kfit", str(path), "--out", str(tmp_path / "out"))
    assert r.returncode == 2
    cli_message = r.stderr.strip().splitlines()[-1]
    with pytest.raises(skinfem.SceneError) as e:
        skinfem.scene(str(path))
    assert isinstance(e.value, ValueError)
    assert "\n" not in str(e.value)
    assert cli_message.endswith(str(e.value)), (cli_message, str(e.value))
    assert not (tmp_path / "out").exists()


def test_bad_arguments_name_the_argument():
    scene = skinfem.scene(FLAT)
    with pytest.raises(skinfem.SceneError, match="^load: 'ring' is not one of punch, point$"):
        skinfem.kfit(scene, load="ring")
    with pytest.raises(skinfem.SceneError, match="^path: 'radial' is not one of auto, 3d, meridian$"):
        skinfem.kfit(scene, path="radial")
    with pytest.raises(skinfem.SceneError, match="neither an existing file"):
        skinfem.scene("no/such/scene.json")


def test_max_dofs_guards_a_python_run_as_the_command_line_does():
    """Scene.max_dofs is the command line's --max-dofs (pipeline/resources.hpp): a run over it stops before
    meshing with the command's one-line message; out of range, the setter names the property."""
    scene = skinfem.scene(FLAT)
    assert scene.max_dofs == 0
    scene.max_dofs = 1000
    with pytest.raises(skinfem.SceneError, match=r"above max_dofs \(--max-dofs\) = 1e\+03; coarsen mesh.h_min"):
        skinfem.kfit(scene, path="3d")
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(skinfem.SceneError, match="max_dofs = .*must be a finite number >= 0"):
            scene.max_dofs = bad


def test_progress_reaches_the_callback():
    lines = []
    skinfem.set_progress(lines.append)
    try:
        skinfem.kfit(skinfem.scene(FLAT))
    finally:
        skinfem.set_progress(None)
    assert any(line.startswith("kfit: calibration scans") for line in lines), lines


def test_entry_points_refuse_arguments_out_of_range():
    # Issue 57: scaled(nan) crashed in CGAL, scaled(-1) meshed for 87 s, a NaN or negative layer thickness
    # became the half space, a 1e6 mm punch hung k_sweep. Each is one line naming the argument.
    scene = skinfem.scene(FLAT)
    for s in (float("nan"), -1.0, 0.0, float("inf")):
        with pytest.raises(skinfem.SceneError, match=r"^s = .*: must be a finite mesh scale > 0$"):
            scene.scaled(s)
    for h in (float("nan"), -1.0):
        with pytest.raises(skinfem.SceneError, match=r"^layer_h_mm = .*: must be 0 \(the half space\)"):
            skinfem.hertz_tractions(1.0, 10.0, 3.0, layer_h_mm=h)
    with pytest.raises(skinfem.SceneError, match=r"^nu = 0.7: must be a Poisson's ratio in \[0, 0.5\]$"):
        skinfem.hertz_tractions(1.0, 10.0, 3.0, nu=0.7)
    with pytest.raises(skinfem.SceneError, match=r"^punch_diameter = 1e\+06: must be a calibration punch"):
        skinfem.k_sweep(h=3.04, nu=0.5, punch_diameter=1e6)
    assert isinstance(skinfem.SceneError("x"), ValueError)


def test_the_papers_model_refuses_what_it_cannot_compute():
    # Issue 57: a kernel for fewer sensors than the scene's surfaced as vector::_M_range_check, a negative or
    # NaN reach as max_size(), a NaN hole area or centre as NaN readings. Each is one line naming the argument.
    scene = skinfem.scene(FLAT)
    t = skinfem.hertz_tractions(0.8, 129.7, 3.0)
    with pytest.raises(skinfem.SceneError, match=r"^thickness_mm = \[\]: must hold one thickness per sensor$"):
        skinfem.halfspace_kernel([], 1.5)
    too_few = skinfem.halfspace_kernel([3.04] * (len(scene.sensor_positions_mm) + 1), 1.5)
    with pytest.raises(skinfem.SceneError, match=r"^kernel: built for \d+ sensor\(s\) .*, the scene 'flat_layer' has"):
        skinfem.convolve(t, too_few, scene)
    for k in (float("nan"), float("inf"), 0.0):
        with pytest.raises(skinfem.SceneError, match=r"^k = .*: must be a finite rescaling factor > 0$"):
            skinfem.halfspace_kernel([3.04], k)
    for reach in (-1.0, float("nan"), 1e6):
        with pytest.raises(skinfem.SceneError, match=r"^reach_mm = .*: must be the largest offset tabulated"):
            skinfem.layer_kernel(3.04, 0.5, reach)
    with pytest.raises(skinfem.SceneError, match=r"^nu = nan: must be a Poisson's ratio"):
        skinfem.layer_kernel(3.04, float("nan"))
    fits = skinfem.halfspace_kernel([3.04] * len(scene.sensor_positions_mm), 1.5)
    for area in (float("nan"), -1.0):
        with pytest.raises(skinfem.SceneError, match=r"^hole_area_mm2 = .*: must be a finite area > 0$"):
            skinfem.first_order_hole(t, fits, scene, [[0.0, 0.0]], area)
    with pytest.raises(skinfem.SceneError, match=r"^centers_mm = nan: must be finite positions"):
        skinfem.first_order_hole(t, fits, scene, [[float("nan"), 0.0]], 0.2)


def test_a_progress_callback_left_set_does_not_hang_the_exit():
    # Issue 57: the sink's Python callable was released after finalization, waiting for the GIL forever.
    r = subprocess.run([sys.executable, "-c", "import skinfem; skinfem.set_progress(print)"],
                       capture_output=True, text=True, timeout=60, env=os.environ)
    assert r.returncode == 0, r.stderr


def test_readme_python_examples_run_as_written(tmp_path):
    """Every ```python block after a <!-- python-example --> marker in README.md or docs/*.md (the module's
    example is in docs/library.md), run from the source tree."""
    docs = [os.path.join(SRC, "README.md")] + sorted(glob.glob(os.path.join(SRC, "docs", "*.md")))
    blocks = []
    for doc in docs:
        with open(doc) as f:
            text = f.read()
        blocks += [(os.path.relpath(doc, SRC), code)
                   for code in re.findall(r"<!-- python-example -->\s*```python\n(.*?)```", text, re.S)]
    assert blocks, "no <!-- python-example --> block in README.md or docs/*.md"
    for doc, code in blocks:
        r = subprocess.run([sys.executable, "-c", code], cwd=SRC, capture_output=True, text=True,
                           env=os.environ | {"PYTHONPATH": os.environ["PYTHONPATH"]})
        assert r.returncode == 0, f"{doc}'s example failed:\n{code}\n{r.stderr}"


def test_paper_model_ingredients_against_closed_forms():
    # A sphere whose contact radius a is far below the depth h presses like a point force: on the axis of the
    # half space (k = 1) σ_z = 3F/(2πh²)·(1 − (a/h)² + O((a/h)⁴)), the (a/h)² term from Hertz's ⟨r²⟩ = 2a²/5
    # in Boussinesq's expansion (3/(2πh²))(1 − (5/2) r²/h²). The rescaled kernel k·g(√k r) moves that term to
    # k(a/h)² and multiplies the rest by k.
    s = skinfem.scene(FLAT)
    g = skinfem.greens(s)
    h = float(g.thickness_mm[0])
    F, R, E, nu = 1.0, 0.01, 1000.0, 0.5
    a = (3 * F * R / (4 * E / (1 - nu * nu))) ** (1 / 3)
    t = skinfem.hertz_tractions(F, R, E, nu)
    assert math.isclose(t.force_N, F, rel_tol=1e-9)
    boussinesq = 1e3 * 3 * F / (2 * math.pi * h * h)  # kPa
    for k in (1.0, 1.48):
        sigma = skinfem.convolve(t, skinfem.halfspace_kernel([h], k), s)
        assert sigma.shape == (1, 2)
        expected = k * (1 - k * (a / h) ** 2)
        assert abs(sigma[0, 0] / boussinesq - expected) < 0.1 * k * (a / h) ** 2, (k, sigma)
        assert abs(sigma[0, 1]) < 1e-9 * sigma[0, 0]  # no tangential load, no σ_x on the axis
    # The same maps by two routes: the kernel grid at the sensor's own grid point and g_per_mm2 at zero offset.
    grid = g.kernel(0.5)
    x0, y0 = s.sensor_positions_mm[0]
    i, j = int(np.argmin(abs(grid["x_mm"] - x0))), int(np.argmin(abs(grid["y_mm"] - y0)))
    at = g.g_per_mm2(0, [grid["x_mm"][i] - x0], [grid["y_mm"][j] - y0])[0]
    assert grid["on_skin"][j, i]
    assert np.allclose(grid["g_per_mm2"][0, :, j, i], at, rtol=1e-12, atol=1e-15)
    with pytest.raises(skinfem.SceneError, match="^k = -1: must be a finite rescaling factor > 0$"):
        skinfem.halfspace_kernel([h], -1.0)


def test_crosscheck_variants_are_their_ingredients(sweep_path):
    # Full FE is the defect sweep itself, and the paper_model variant is eqs. (2)-(3) with the exact-layer
    # Hertz pressure of the same force, uncoupled Coulomb friction and the paper's k = 1.48: rebuilt here from
    # the module's ingredients, it must agree to round-off.
    s = skinfem.scene(str(sweep_path))
    x = skinfem.crosscheck(s)
    d = skinfem.defect(s, error_scales=())
    assert "fe" in x.signal_variants and "paper_model" in x.signal_variants
    assert np.allclose(x.u_mm, d.u_mm, rtol=0, atol=1e-14)
    with open(HERTZ) as f:
        base = json.load(f)
    h, E, nu = base["geometry"]["h"], base["material"]["E"], base["material"]["nu"]
    R = base["contact"]["indenter"]["R"]
    fr = SWEEP_CONTACT["friction"]
    kernel = skinfem.halfspace_kernel([h] * len(s.sensor_positions_mm), 1.48)
    area = math.pi * SWEEP_CONTACT["sweep"]["hole_diameter"] ** 2 / 4
    centers = [[u, 0.0] for u in x.u_mm]
    for case, ratio in (("static", fr["static_ratio"]), ("sliding", fr["mu"])):
        # defect may condense by a bordered factorization, crosscheck by block solves of the skin it shares
        # with kfit: the two roads agree to 1e-10 of the largest entry (tests/contact/test_condensed.cpp).
        fe, own = x.varsigma_kPa("fe", case), d.varsigma_kPa(case)
        assert np.allclose(fe, own, rtol=0, atol=1e-10 * np.abs(own).max())
        assert np.allclose(x.amplitude_ratio("fe", case), 1.0, rtol=1e-14)
        t = skinfem.hertz_tractions(SWEEP_CONTACT["force"], R, E, nu, ratio=ratio, layer_h_mm=h)
        rebuilt = skinfem.first_order_hole(t, kernel, s, centers, area)
        model = x.varsigma_kPa("paper_model", case)
        assert np.allclose(model, rebuilt, rtol=1e-12, atol=1e-12 * np.abs(model).max())
    with pytest.raises(skinfem.SceneError, match="^variant: 'magic' is not one"):
        x.varsigma_kPa("magic", "static")


def test_kernel_grid_reproduces_the_command(tmp_path):
    # `skinfem green --grid` writes kernel.h5; the module's kernel() is the same grid over the same footprint.
    import h5py  # scripts/setup installs it (docs/kernels.md's kernel snippet needs it too)
    r = run_cli("green", FLAT, "--grid", "0.5", "--out", str(tmp_path))
    assert r.returncode == 0, r.stderr
    k = skinfem.greens(skinfem.scene(FLAT)).kernel(0.5)
    with h5py.File(tmp_path / "kernel.h5", "r") as f:
        assert np.array_equal(f["x_mm"][:], k["x_mm"]) and np.array_equal(f["y_mm"][:], k["y_mm"])
        assert np.array_equal(f["on_skin"][:].astype(bool), k["on_skin"])
        for c, name in enumerate(("zz", "zx", "xz", "xx")):
            ref = f[f"sensor01/g_{name}_per_mm2"][:]
            assert np.allclose(k["g_per_mm2"][0, c], ref, rtol=1e-12, atol=1e-15), name
    with pytest.raises(skinfem.SceneError, match="^--grid = 0.001: the kernel grid"):
        skinfem.greens(skinfem.scene(FLAT)).kernel(0.001)


def test_sweep_reproduces_the_reports_k_sweep(tmp_path):
    """sweeps/k_vs_nu_and_punch.json (kfit on the flat layer, 6 Poisson's ratios x 7 punch diameters, run by
    Snakemake) against the report's k sweep (skinfem.k_sweep, validation/k_sweep: the exact bonded layer):
    on the sweep's lines through the report's base (nu 0.5, punch 0.5 mm) each member's exact-layer k is the
    report's to round-off, both criteria. The shipped grid is written (--dry-run: its 42 members); the run
    takes the 12 members on those lines, zipped, so its other 30 kfits do not run."""
    import csv

    spec_path = os.path.join(SRC, "sweeps", "k_vs_nu_and_punch.json")
    r = run_cli("sweep", spec_path, "--out", str(tmp_path / "grid"), "--dry-run")
    assert r.returncode == 0, r.stderr[-3000:]
    with open(tmp_path / "grid" / "manifest.json") as f:
        assert len(json.load(f)["members"]) == 42
    with open(spec_path) as f:
        spec = json.load(f)
    spec["scene"] = os.path.join(SRC, "sweeps", spec["scene"])
    nus, punches = (axis["values"] for axis in spec["axes"])
    lines = [(nu, 0.5) for nu in nus] + [(0.5, d) for d in punches if d != 0.5]
    spec["combine"] = "zip"
    for i, axis in enumerate(spec["axes"]):
        axis["values"] = [point[i] for point in lines]
    lined = tmp_path / "lines.json"
    lined.write_text(json.dumps(spec))
    out = tmp_path / "k_sweep"
    r = run_cli("sweep", str(lined), "--out", str(out), "--cores", "2")
    assert r.returncode == 0, r.stderr[-3000:]
    with open(out / "results.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 12 and all(row["exit_code"] == "0" for row in rows)
    by = {(float(row["material.nu"]), float(row["calibration.punch_diameter_mm"])): row for row in rows}
    compared = 0
    for p in skinfem.k_sweep(h=3.04, nu=0.5, punch_diameter=0.5):
        key = {"nu": (p["value"], 0.5), "punch_diameter_mm": (0.5, p["value"])}.get(p["parameter"])
        if key is None:
            continue  # the load model, disc and thickness lines are not this sweep's axes
        row = by[key]
        assert float(row["k_central_exact"]) == pytest.approx(p["k_central"], rel=1e-12, abs=0)
        assert float(row["k_lsq_line_exact"]) == pytest.approx(p["k_lsq_line"], rel=1e-12, abs=0)
        compared += 1
    assert compared == 13  # the report's 6 Poisson's ratios and 7 punch diameters

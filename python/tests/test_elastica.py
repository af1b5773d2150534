# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module against the `elastica` command on the same inputs, against analytic values, and
on bad arrays. Run by ctest (python_module) with PYTHONPATH at the built module, ELASTICA_EXE at
the command and OMP_NUM_THREADS=1 (a parallel sum's order depends on the thread count, so equal
results need equal threads)."""
import json
import math
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import elastica

EXE = os.environ["ELASTICA_EXE"]
DATA = os.environ["ELASTICA_DATA_DIR"]
BUNNY_HOLE = os.path.join(DATA, "bunny_flank_hole.ply")


def cli(*args):
    return subprocess.run([EXE, *map(str, args)], check=True, capture_output=True, text=True).stdout


@pytest.fixture(scope="module")
def noisy(tmp_path_factory):
    path = tmp_path_factory.mktemp("noisy") / "noisy.ply"
    cli("generate", "icosphere", "--level", 2, "--noise", 0.05, "--seed", 7, "-o", path)
    return path


def same(a, b, rel=1e-12):
    scale = max(np.abs(b).max(), 1e-300)
    return a.shape == b.shape and np.abs(a - b).max() <= rel * scale


@pytest.mark.parametrize("scheme, extra", [("semi-implicit", []), ("explicit", ["--max-steps", 3000])])
def test_fair_equals_the_cli(noisy, tmp_path, scheme, extra):
    out, report = tmp_path / "out.ply", tmp_path / "r.json"
    cli("fair", noisy, "-o", out, "--scheme", scheme, "--report", report, *extra)
    V, F = elastica.read(noisy)
    kwargs = {"max_steps": extra[1]} if extra else {}
    V2, F2, r = elastica.fair(V, F, scheme=scheme, **kwargs)
    Vc, Fc = elastica.read(out)
    assert same(V2, Vc) and (F2 == Fc).all()
    expected = json.loads(report.read_text())
    for key in ("energy_initial", "energy_final", "steps", "stop", "flow", "mesh_energy_before", "mesh_energy_after"):
        assert r[key] == pytest.approx(expected[key], rel=1e-12) if isinstance(r[key], float) else r[key] == expected[key]
    assert r["output"] == {"vertices": len(V2), "faces": len(F2)}


def test_fair_selected_faces_keeps_the_rest(tmp_path):
    V, F = elastica.read(os.path.join(DATA, "bunny.ply"))
    selected = np.arange(0, 400, 2)
    V2, F2, r = elastica.fair(V, F, selected, scheme="semi-implicit")
    # A vertex moves only if all its faces are selected: every vertex of an unselected face stays bit for bit.
    mask = np.ones(len(F), bool)
    mask[selected] = False
    fixed = np.unique(F[mask])
    assert (V2[fixed] == V[fixed]).all()
    assert (V2 != V).any(axis=1).sum() > 0
    # The same selection as a bool mask.
    V3, _, _ = elastica.fair(V, F, ~mask, scheme="semi-implicit")
    assert (V3 == V2).all()
    out = tmp_path / "out.ply"
    faces = tmp_path / "faces.txt"
    faces.write_text("\n".join(map(str, selected)))
    cli("fair", os.path.join(DATA, "bunny.ply"), "-o", out, "--scheme", "semi-implicit", "--selected-faces", faces)
    assert same(V2, elastica.read(out)[0])


def test_fill_holes_equals_the_cli(tmp_path):
    out, report = tmp_path / "out.ply", tmp_path / "r.json"
    cli("fill", BUNNY_HOLE, "-o", out, "--report", report)
    V, F = elastica.read(BUNNY_HOLE)
    V2, F2, new_faces, r = elastica.fill_holes(V, F)
    Vc, Fc = elastica.read(out)
    assert same(V2, Vc) and (F2 == Fc).all()
    # The input comes first, unchanged; the new faces are the appended ones.
    assert (V2[: len(V)] == V).all() and (F2[: len(F)] == F).all()
    assert new_faces.dtype == bool and not new_faces[: len(F)].any() and new_faces[len(F):].all()
    expected = json.loads(report.read_text())
    assert r["filled"] == expected["filled"] == 1
    assert [h["border_edges"] for h in r["holes"]] == [h["border_edges"] for h in expected["holes"]]


def test_curvature_of_a_sphere_and_the_cli(tmp_path):
    path = tmp_path / "sphere.ply"
    cli("generate", "icosphere", "--level", 4, "-o", path)
    V, F = elastica.read(path)
    V = V * 2.0  # radius 2: H = 1/2, K = 1/4, E = 8 pi
    c = elastica.curvature(V, F)
    assert np.abs(c["H"] - 0.5).max() < 0.005 * 0.5
    assert np.abs(c["K"] - 0.25).max() < 0.01 * 0.25
    assert c["energy"] == pytest.approx(8 * math.pi, rel=0.01)
    text = cli("curvature", path, "-o", tmp_path / "c.ply")
    cli_energy = float(text.split("total curvature energy E = ")[1].split()[0])
    assert elastica.curvature(V / 2.0, F)["energy"] == pytest.approx(cli_energy, rel=1e-8)  # printed with 9 digits


def test_any_real_dtype_is_accepted(noisy):
    V, F = elastica.read(noisy)
    a = elastica.curvature(V, F)["energy"]
    b = elastica.curvature(V.astype(np.float32).astype(np.float64), F.astype(np.int64))["energy"]
    c = elastica.curvature(V.astype(np.float32), F.astype(np.uint32))["energy"]
    assert b == c and a == pytest.approx(b, rel=1e-5)


def bad_calls():
    V, F = elastica.read(os.path.join(DATA, "bunny_flank_hole.ply"))
    nan = V.copy()
    nan[5, 2] = np.nan
    # Three triangles on one edge: non-manifold.
    Vn = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], float)
    Fn = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    return {
        "V not n x 3": (V[:, :2], F),
        "F not m x 3": (V, F[:, :2]),
        "V not numbers": (np.array([["a", "b", "c"]]), F[:1]),
        "F not integers": (V, F.astype(float)),
        "NaN": (nan, F),
        "index out of range": (V, F + len(V)),
        "negative index": (V, F - 1),
        "non-manifold edge": (Vn, Fn),
    }


@pytest.mark.parametrize("case", list(bad_calls()))
@pytest.mark.parametrize("function", ["fair", "fill_holes", "curvature"])
def test_bad_arrays_raise_cleanly(case, function):
    V, F = bad_calls()[case]
    with pytest.raises(elastica.InvalidInputError) as e:
        getattr(elastica, function)(V, F)
    assert isinstance(e.value, ValueError) and isinstance(e.value, elastica.Error) and str(e.value)


def test_bad_options_and_selection(noisy):
    V, F = elastica.read(noisy)
    for kwargs in ({"flow": "willmore"}, {"scheme": "implicit"}, {"boundary": "free"}, {"subdivide": 9},
                   {"max_steps": -1}):
        with pytest.raises(elastica.InvalidInputError):
            elastica.fair(V, F, **kwargs)
    # Errors name the caller's keywords (snake_case), not the core's fields or MeshLab's names.
    for function, kwargs, message in [
            (elastica.fair, {"max_steps": -3}, "max_steps must be >= 0, not -3"),
            (elastica.fair, {"max_seconds": -1}, "max_seconds must be >= 0"),
            (elastica.fair, {"subdivide": 9}, "subdivide must be in 0..8"),
            (elastica.fair, {"energy_tol": -0.5}, "energy_tol must be >= 0"),
            (elastica.fill_holes, {"max_hole_edges": 2}, "max_hole_edges must be >= 3"),
            (elastica.fill_holes, {"max_steps": -1}, "max_steps must be >= 0")]:
        with pytest.raises(elastica.InvalidInputError) as e:
            function(V, F, **kwargs)
        assert str(e.value).startswith(message), str(e.value)
        assert not any(name in str(e.value) for name in ("maxSteps", "maxSeconds", "subdivisionLevels", "MaxHoleSize"))
    for selection in (np.array([len(F)]), np.zeros(len(F), bool), np.zeros(3, bool)):
        with pytest.raises(elastica.InvalidInputError):
            elastica.fair(V, F, selection)


def test_progress_reports_and_cancels(noisy):
    V, F = elastica.read(noisy)
    seen = []
    elastica.fair(V, F, scheme="semi-implicit", progress=lambda p: seen.append(p) or True)
    assert seen and {"level", "step", "energy", "lambda", "seconds"} <= set(seen[0])
    with pytest.raises(elastica.Error, match="cancelled"):
        elastica.fair(V, F, scheme="semi-implicit", progress=lambda p: p["step"] < 3)
    with pytest.raises(elastica.Error, match="cancelled"):
        elastica.fill_holes(*elastica.read(BUNNY_HOLE), progress=lambda p: False)

    def boom(p):
        raise KeyError("from the callback")

    with pytest.raises(KeyError, match="from the callback"):  # the callback's own error comes through
        elastica.fair(V, F, scheme="semi-implicit", progress=boom)


def test_the_gil_is_released_while_computing(noisy):
    """A Python thread keeps running while fair computes (an explicit run of a few seconds' worth)."""
    V, F = elastica.read(noisy)
    ticks = []
    done = threading.Event()

    def ticker():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    try:
        elastica.fair(V, F, scheme="explicit", feature_size=0, max_steps=20000)  # seconds of work
    finally:
        done.set()
        t.join()
    assert len(ticks) > 10


def test_read_write_round_trip_and_errors(noisy, tmp_path):
    V, F = elastica.read(noisy)
    for ascii in (False, True):
        path = tmp_path / f"rt{int(ascii)}.ply"
        elastica.write(path, V, F, ascii=ascii)
        V2, F2 = elastica.read(path)
        assert (F2 == F).all()
        # Binary PLY stores the doubles; ASCII their 16 significant digits (last-bit differences).
        assert (V2 == V).all() if not ascii else same(V2, V, rel=1e-15)
    with pytest.raises(elastica.IoError) as e:
        elastica.read(tmp_path / "missing.ply")
    assert isinstance(e.value, OSError)
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(OSError):
        elastica.read(bad)
    with pytest.raises(elastica.IoError):
        elastica.write(tmp_path / "out.xyz", V, F)
    assert not (tmp_path / "out.xyz").exists()
    elastica.write(tmp_path / "rt.off", V, F)  # by extension; OFF keeps every double
    V2, F2 = elastica.read(tmp_path / "rt.off")
    assert (F2 == F).all() and (V2 == V).all()
    elastica.write(tmp_path / "rt.obj", V, F)  # OBJ is read back by tinyobjloader, in float
    V2, F2 = elastica.read(tmp_path / "rt.obj")
    assert (F2 == F).all() and same(V2, V, rel=1e-7)
    elastica.write(tmp_path / "rt.stl", V, F)  # STL: unshared float32 corners, merged again on reading
    V2, F2 = elastica.read(tmp_path / "rt.stl")
    assert len(V2) == len(V) and same(V2[F2], V[F], rel=1e-7)


def test_filters_describe_the_meshlab_parameters(tmp_path):
    """filters(): every MeshLab parameter with its default; the keywords at those defaults run what
    `elastica run` runs on the example scripts (which list every parameter at its default)."""
    specs = elastica.filters()
    assert set(specs) == {"fair", "fill_holes", "curvature"}
    assert specs["fair"]["name"] == "Discrete Elastica Fairing"
    for spec in specs.values():
        for p in spec["parameters"]:
            assert p["type"] in ("bool", "int", "float", "enum") and p["label"] and p["description"]
            if p["type"] == "enum":
                assert p["default"] in p["choices"] and len(p["choices"]) == len(p["labels"])
    fair = {p["name"]: p for p in specs["fair"]["parameters"]}
    assert fair["scheme"]["default"] == "auto" and fair["scheme"]["choices"] == ["explicit", "semi-implicit", "vector", "auto"]
    # Float defaults as the decimals typed, not MeshLab's float widened (0.05000000074505806).
    assert repr(fair["energyTolerance"]["default"]) == "0.05" and repr(fair["maxSeconds"]["default"]) == "60.0"
    assert fair["subdivisionLevels"]["min"] == 0 and fair["subdivisionLevels"]["max"] == 8
    assert fair["Selected"]["keyword"] is None and fair["maxSteps"]["keyword"] == "max_steps"

    def defaults(name):
        return {p["keyword"]: p["default"] for p in specs[name]["parameters"] if p["keyword"]}

    examples = os.path.join(os.path.dirname(DATA), "meshlab_plugin", "examples")
    out = tmp_path / "fill.ply"
    cli("run", "-i", BUNNY_HOLE, "-o", out, "-s", os.path.join(examples, "fill_holes.mlx"))
    V2, F2, _, _ = elastica.fill_holes(*elastica.read(BUNNY_HOLE), **defaults("fill_holes"))
    Vc, Fc = elastica.read(out)
    assert same(V2, Vc) and (F2 == Fc).all()
    sphere = tmp_path / "sphere.ply"
    cli("generate", "icosphere", "--level", 2, "-o", sphere)
    c = elastica.curvature(*elastica.read(sphere), **defaults("curvature"))
    assert c["energy"] == elastica.curvature(*elastica.read(sphere))["energy"]
    V, F = elastica.read(sphere)
    elastica.fair(V, F, **{**defaults("fair"), "max_steps": 5})  # every keyword is accepted


def test_example_scripts_list_every_parameter_at_its_default():
    """meshlab_plugin/examples/*.mlx run each filter as its dialog opens on a mesh without a
    selection: every parameter listed (Debian's meshlabserver aborts on a script that leaves one
    out), each at the default filters() reports, enums with the dialog's entries."""
    import xml.etree.ElementTree as ET

    by_name = {spec["name"]: spec for spec in elastica.filters().values()}
    examples = os.path.join(os.path.dirname(DATA), "meshlab_plugin", "examples")
    seen = set()
    for script in sorted(os.listdir(examples)):
        assert script.endswith(".mlx"), script
        for f in ET.parse(os.path.join(examples, script)).getroot().iter("filter"):
            spec = by_name[f.get("name")]
            seen.add(f.get("name"))
            params = {p.get("name"): p for p in f.iter("Param")}
            meshlab = [p for p in spec["parameters"] if p["name"]]  # the table's rows MeshLab has
            assert set(params) == {p["name"] for p in meshlab}, script
            for p in meshlab:
                got = params[p["name"]]
                where = f"{script}: {p['name']}"
                if p["type"] == "bool":
                    assert got.get("type") == "RichBool" and got.get("value") == str(p["default"]).lower(), where
                elif p["type"] == "int":
                    assert got.get("type") == "RichInt" and int(got.get("value")) == p["default"], where
                elif p["type"] == "float" and p["default"] is None:  # the feature size: -1, the mesh's own
                    assert got.get("type") == p["rich_type"] and float(got.get("value")) == -1, where
                elif p["type"] == "float":  # RichFloat
                    assert got.get("type") == p["rich_type"] and float(got.get("value")) == pytest.approx(p["default"]), where
                else:
                    assert got.get("type") == "RichEnum", where
                    assert int(got.get("value")) == p["choices"].index(p["default"]), where
                    entries = [got.get(f"enum_val{i}") for i in range(int(got.get("enum_cardinality")))]
                    assert entries == p["labels"], where
    assert seen == set(by_name)  # an example for every filter


def test_cmake_install_puts_the_module_on_the_python_path(tmp_path):
    """`cmake --install` with a prefix: the module lands in ELASTICA_PYTHON_INSTALL_DIR under it and
    imports from there; for the default prefix /usr/local that directory is on the system Python's path."""
    build, subdir = os.environ["ELASTICA_BUILD_DIR"], os.environ["ELASTICA_PYTHON_INSTALL_DIR"]
    subprocess.run([os.environ["CMAKE_COMMAND"], "--install", build, "--component", "python", "--prefix", tmp_path],
                   check=True, capture_output=True)
    env = {**os.environ, "PYTHONPATH": str(tmp_path / subdir)}
    where = subprocess.run(["/usr/bin/python3", "-c", "import elastica; print(elastica.__file__)"], env=env, cwd=tmp_path,
                           check=True, capture_output=True, text=True).stdout
    assert where.startswith(str(tmp_path / subdir))
    system_path = subprocess.run(["/usr/bin/python3", "-c", "import sys; print('\\n'.join(sys.path))"], check=True,
                                 capture_output=True, text=True, env={"PATH": os.environ["PATH"]}).stdout.split()
    assert os.path.join("/usr/local", subdir) in system_path


def doc_blocks(page, section, language):
    """The fenced `language` blocks of the section of docs/`page` whose heading starts with `section`."""
    text = open(os.path.join(os.path.dirname(os.environ["ELASTICA_README"]), "docs", page)).read()
    body = text.split("\n## " + section, 1)[1].split("\n## ", 1)[0]
    return [b.split("\n```", 1)[0] for b in body.split("```" + language + "\n")[1:]]


def test_the_documented_python_example_runs_as_written(tmp_path, monkeypatch):
    (block,) = doc_blocks("python.md", "Example", "python")
    os.symlink(DATA, tmp_path / "data")
    monkeypatch.chdir(tmp_path)
    exec(compile(block, "docs/python.md", "exec"), {})
    V, F = elastica.read(tmp_path / "restored.ply")
    assert len(F) > len(elastica.read(BUNNY_HOLE)[1])


def test_keywords_are_the_options_tables(noisy):
    """The keyword arguments of fair, fill_holes and curvature are the options table's rows with a
    keyword (filters()), with the core's defaults in the docstring's signature; an unknown keyword or a
    value of the wrong type raises TypeError, a value out of the row's range InvalidInputError naming
    the keyword, and None takes the default."""
    V, F = elastica.read(noisy)
    calls = {"fair": elastica.fair, "fill_holes": elastica.fill_holes, "curvature": elastica.curvature}
    for name, function in calls.items():
        rows = [p for p in elastica.filters()[name]["parameters"] if p["keyword"]]
        signature = function.__doc__.split("\n", 1)[0]
        for p in rows:
            assert f" {p['keyword']}=" in signature, (name, p["keyword"], signature)
            if p["type"] == "enum":
                assert f"{p['keyword']}='" in signature
        assert signature.count("=") == len(rows) + (2 if name == "fair" else 1 if name == "fill_holes" else 0), signature
        with pytest.raises(TypeError, match="unexpected keyword argument 'bogus'"):
            function(V, F, bogus=1)
        for p in rows:
            wrong = "x" if p["type"] != "enum" else 3
            with pytest.raises(TypeError, match=p["keyword"]):
                function(V, F, **{p["keyword"]: wrong})
            if p["type"] == "enum":
                with pytest.raises(elastica.InvalidInputError, match=f"{p['keyword']} must be one of"):
                    function(V, F, **{p["keyword"]: "bogus"})
            elif p["type"] in ("int", "float") and p.get("min") is not None:
                below = int(p["min"]) - 1 if p["type"] == "int" else p["min"] - 0.5  # (-1 is the amount's "auto")
                with pytest.raises(elastica.InvalidInputError, match=f"^{p['keyword']} must be"):
                    function(V, F, **{p["keyword"]: below})
    _, _, report = elastica.fair(V, F, scheme=None, max_steps=None, energy_tol=None)
    assert report["scheme"] in ("vector", "semi-implicit")


def test_remesh_and_flip_edges_are_the_cli_flags(noisy, tmp_path):
    V, F = elastica.read(noisy)
    for flags, kwargs in ((["--no-remesh"], {"remesh": False}), (["--remesh", "--no-remesh"], {"remesh": False, "flip_edges": True}),
                          (["--flip-edges", "--no-remesh"], {"remesh": False, "flip_edges": True})):
        out = tmp_path / "out.ply"
        cli("fair", noisy, "-o", out, *flags)
        V2, F2, r = elastica.fair(V, F, **kwargs)
        Vc, Fc = elastica.read(out)
        assert same(V2, Vc) and (F2 == Fc).all()
    V2, F2, r = elastica.fair(V, F, remesh=False)
    assert (F2 == F).all() and r["mesh_quality"]["remeshings"] == 0


def test_feature_size_is_a_length_in_every_face(noisy):
    """feature_size=F: a length in the mesh's units, the report's feature_size, the flow time of F, then
    report['stop'] says so; filters() shows it as a length (no upper bound), the default None."""
    V, F = elastica.read(noisy)
    _, _, report = elastica.fair(V, F, feature_size=0.1)
    assert report["stop"] == "feature_size" and report["feature_size"] == 0.1
    diagonal = float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
    assert report["feature_size_per_diagonal"] == pytest.approx(0.1 / diagonal, rel=1e-12)
    spec = {p["name"]: p for p in elastica.filters()["fair"]["parameters"]}["featureSize"]
    assert spec["keyword"] == "feature_size" and spec["rich_type"] == "RichAbsPerc" and spec["unit"] == "length"
    assert (spec["min"], spec["max"], spec["default"]) == (0.0, None, None)  # None: the mesh's own
    _, _, big = elastica.fair(V * 100, F, feature_size=12.8665)  # larger than 1: a length, not a fraction
    assert big["stop"] == "feature_size" and big["feature_size"] == 12.8665
    with pytest.raises(elastica.InvalidInputError, match="feature_size"):
        elastica.fair(V, F, feature_size=-0.5)


def test_the_reports_amount_typed_back_gives_the_same_output(tmp_path):
    """On a real scan with 3-D noise (the bundled bunny, 0.3 mean edge): auto_feature_size is the amount
    the default used (report['feature_size']), and that value typed back gives the same arrays, bit for
    bit, and the CLI's --feature-size with it the same file as fair --report's own run."""
    V, F = elastica.read(os.path.join(DATA, "bunny.ply"))
    edge = np.linalg.norm(V[F] - V[np.roll(F, -1, axis=1)], axis=2).mean()
    rng = np.random.default_rng(1)
    step = rng.normal(size=V.shape)
    step *= (0.3 * edge * rng.random(len(V)) ** (1 / 3) / np.linalg.norm(step, axis=1))[:, None]
    V = V + step
    V2, F2, r = elastica.fair(V, F)
    assert r["feature_size_auto"] and r["feature_size_halvings"] == 0
    assert elastica.auto_feature_size(V, F) == r["feature_size"]
    assert r["roughness_before"] == elastica.surface_roughness(V, F) and r["roughness_after"] < r["roughness_before"]
    V3, F3, r3 = elastica.fair(V, F, feature_size=r["feature_size"])
    assert (V3 == V2).all() and (F3 == F2).all() and not r3["feature_size_auto"]
    noisy = tmp_path / "noisy.ply"
    elastica.write(noisy, V, F)
    cli("fair", noisy, "-o", tmp_path / "a.ply", "--report", tmp_path / "r.json")
    typed = json.load(open(tmp_path / "r.json"))["feature_size"]
    assert typed == r["feature_size"]
    cli("fair", noisy, "-o", tmp_path / "b.ply", "--feature-size", repr(typed))
    assert (tmp_path / "a.ply").read_bytes() == (tmp_path / "b.ply").read_bytes()


def test_the_selection_round_trip(tmp_path):
    """write(selected_faces=mask) stores MeshLab's face selection (PLY face flags), which the CLI's
    --selected reads; read(selection=True) gives it back as a bool mask; fill_holes' new faces
    likewise. The plain calls stay as they were."""
    V, F = elastica.read(os.path.join(DATA, "bunny.ply"))
    mask = V[F].mean(axis=1)[:, 1] > np.quantile(V[:, 1], 0.8)
    path = tmp_path / "sel.ply"
    elastica.write(path, V, F, selected_faces=mask)
    V1, F1, sel = elastica.read(path, selection=True)
    assert sel.dtype == bool and (sel == mask).all() and (F1 == F).all() and same(V1, V, 1e-6)
    assert len(elastica.read(path)) == 2
    # The CLI's --selected fairs the region the mask names, as Python's selected_faces does.
    cli("fair", path, "-o", tmp_path / "f.ply", "--selected")
    Vp, _, _ = elastica.fair(V1, F1, sel)
    assert same(elastica.read(tmp_path / "f.ply")[0], Vp, 1e-6)
    # Indices, an empty selection, and a file without flags.
    elastica.write(path, V, F, selected_faces=np.flatnonzero(mask))
    assert (elastica.read(path, selection=True)[2] == mask).all()
    elastica.write(path, V, F, selected_faces=np.zeros(len(F), bool))
    assert not elastica.read(path, selection=True)[2].any()
    elastica.write(tmp_path / "plain.ply", V, F)
    assert not elastica.read(tmp_path / "plain.ply", selection=True)[2].any()
    # The fill's new faces, selected as MeshLab's fill selects them.
    Vh, Fh = elastica.read(BUNNY_HOLE)
    Vf, Ff, new, _ = elastica.fill_holes(Vh, Fh)
    elastica.write(tmp_path / "filled.ply", Vf, Ff, selected_faces=new)
    assert (elastica.read(tmp_path / "filled.ply", selection=True)[2] == new).all()
    with pytest.raises(elastica.InvalidInputError, match="only a .ply"):
        elastica.write(tmp_path / "sel.off", V, F, selected_faces=mask)
    with pytest.raises(elastica.InvalidInputError, match="one entry per face"):
        elastica.write(path, V, F, selected_faces=mask[:-1])


def test_an_open_sheet_keeps_its_rim_unless_close_rims(tmp_path):
    # The case: a 20x20 grid with a hole cut in its middle. The hole is filled, the rim stays
    # open (it came back as a closed pillow before); close_rims and --close-rims close it too.
    n = 20
    V = np.array([(x, y, 0.0) for y in range(n + 1) for x in range(n + 1)])
    F = []
    for y in range(n):
        for x in range(n):
            a, b, c, d = y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x
            for t in ((a, b, c), (a, c, d)):
                if np.hypot(*(V[list(t)].mean(axis=0)[:2] - n / 2)) > 3:
                    F.append(t)
    F = np.array(F)
    used = np.unique(F)
    V, F = V[used], np.searchsorted(used, F)
    _, _, new, report = elastica.fill_holes(V, F)
    assert report["filled"] == 1 and [h["rim"] for h in report["holes"]].count(True) == 1
    assert "outer rim" in next(h["reason"] for h in report["holes"] if h["rim"])
    _, _, new_all, report = elastica.fill_holes(V, F, close_rims=True)
    assert report["filled"] == 2 and report["close_rims"] and new_all.sum() > new.sum()
    elastica.write(tmp_path / "sheet.ply", V, F)
    out = cli("fill", tmp_path / "sheet.ply", "-o", tmp_path / "filled.ply")
    assert "1 hole filled, 1 skipped" in out, out
    out = cli("fill", tmp_path / "sheet.ply", "-o", tmp_path / "closed.ply", "--close-rims")
    assert "2 holes filled, 0 skipped" in out, out


def test_zero_max_steps_means_no_limit(noisy):
    V, F = elastica.read(noisy)
    _, _, report = elastica.fair(V, F, max_steps=0, scheme="semi-implicit")
    assert report["steps"] > 0 and report["stop"] != "max_steps"
    assert report["mesh_energy_before"] > report["mesh_energy_after"]  # the whole mesh's, as `elastica curvature` gives


def test_region_report_names_its_energies(noisy):
    """A region's run reports the region's energy and the whole mesh's under their own names; the
    region's never ends above its start."""
    V, F = elastica.read(noisy)
    top = np.nonzero(V[F].mean(axis=1)[:, 2] > 0.3 * np.abs(V).max())[0]
    _, _, report = elastica.fair(V, F, top)
    for key in ("region_energy_before", "region_energy_after", "mesh_energy_before", "mesh_energy_after"):
        assert key in report, key
    assert report["region_energy_after"] <= report["region_energy_before"]
    assert report["region_energy_before"] < report["mesh_energy_before"]  # a part of the whole




def test_ctrl_c_raises_keyboard_interrupt_and_keeps_the_input(tmp_path):
    """SIGINT during fair() raises KeyboardInterrupt promptly; the input arrays are unchanged."""
    mesh = tmp_path / "big.ply"
    cli("generate", "icosphere", "--level", 5, "--noise", 0.3, "--seed", 3, "-o", mesh)
    child = tmp_path / "child.py"
    child.write_text(f"""
import elastica
V, F = elastica.read({str(mesh)!r})
V0, F0 = V.copy(), F.copy()
print("ready", flush=True)
try:
    elastica.fair(V, F, scheme="explicit", max_steps=0)
    print("finished", flush=True)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    assert (V == V0).all() and (F == F0).all()
    print("unchanged", flush=True)
""")
    proc = subprocess.Popen([sys.executable, str(child)], stdout=subprocess.PIPE, text=True,
                            env={**os.environ, "OMP_NUM_THREADS": "1"})
    assert proc.stdout.readline().strip() == "ready"
    time.sleep(1.0)  # inside fair()
    interrupted_at = time.monotonic()
    proc.send_signal(signal.SIGINT)
    try:
        out, _ = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        proc.kill()
        pytest.fail("fair() went on after SIGINT")
    print(f"SIGINT to exit: {time.monotonic() - interrupted_at:.2f} s")  # measured, not asserted (load)
    assert "interrupted" in out and "unchanged" in out, out


def test_defaults_keep_the_model_of_a_scan():
    """fair(V, F) with every default on a real scan (the bundled Stanford bunny, and a region of
    it): a fairer surface of the same model, not the flow's limit shape. The amount is
    auto_feature_size's, stated in the report with how far the vertices moved; RMS distance to the
    input at most 1 % of the bounding-box diagonal, the energy down, the run finished by itself."""
    V, F = elastica.read(os.path.join(DATA, "bunny.ply"))
    diagonal = float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
    E0 = elastica.curvature(V, F)["energy"]
    V2, F2, r = elastica.fair(V, F)
    assert r["stop"] == "feature_size" and r["feature_size_auto"] and r["feature_size_halvings"] == 0
    assert r["feature_size"] == elastica.auto_feature_size(V, F)
    assert (F2 == F).all()  # the amount keeps the connectivity
    rms = float(np.sqrt(((V2 - V) ** 2).sum(axis=1).mean()))
    assert r["moved"]["rms"] == pytest.approx(rms, rel=1e-9)
    assert 0 < rms <= 0.01 * diagonal
    assert elastica.curvature(V2, F2)["energy"] < E0
    # A region: only its vertices move, its energy goes down.
    top = np.flatnonzero(V[F].mean(axis=1)[:, 1] > np.quantile(V[:, 1], 0.8))
    V3, F3, r3 = elastica.fair(V, F, top)
    assert r3["stop"] == "feature_size" and r3["region_energy_after"] < r3["region_energy_before"]
    assert r3["feature_size"] == elastica.auto_feature_size(V, F, top)
    assert 0 < np.sqrt(((V3 - V) ** 2).sum(axis=1).mean()) <= 0.01 * diagonal
    # The limit shape stays one keyword away.
    _, _, limit = elastica.fair(V, F, feature_size=0, max_steps=3)
    assert "feature_size" not in limit and limit["stop"] == "max_steps"

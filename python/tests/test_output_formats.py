# SPDX-License-Identifier: GPL-3.0-or-later
# `elastica … -o OUT` writes the format OUT's extension names; each file is read back here by a
# parser written from the format's definition (NumPy only, none of Elastica's or vcglib's code),
# against the same mesh written as binary PLY.
import os
import subprocess

import numpy as np
import pytest

EXE = os.environ["ELASTICA_EXE"]


def run(*args):
    return subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)


def read_binary_ply(path):
    """The x y z doubles and the triangles of a binary PLY as `elastica` writes it."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    vprops = []
    for line in header[header.index(next(l for l in header if l.startswith("element vertex"))) + 1:]:
        if not line.startswith("property"):
            break
        vprops.append(line.split())
    types = {"double": "<f8", "float": "<f4", "uchar": "u1", "int": "<i4"}
    vtype = np.dtype([(p[2], types[p[1]]) for p in vprops])
    v = np.frombuffer(data, vtype, nv, end)
    ftype = np.dtype([("n", "u1"), ("i", "<i4", 3)])  # no face property after the indices here
    f = np.frombuffer(data, ftype, nf, end + nv * vtype.itemsize)
    assert (f["n"] == 3).all()
    return np.stack([v["x"], v["y"], v["z"]], axis=1), f["i"].astype(np.int64)


def read_off(path):
    """OFF, or COFF with r g b a after each vertex (the colours are checked to be bytes)."""
    words = open(path).read().split()
    assert words[0] in ("OFF", "COFF")
    per_vertex = 7 if words[0] == "COFF" else 3
    nv, nf = int(words[1]), int(words[2])
    numbers = words[4:]
    rows = np.array(numbers[:per_vertex * nv], dtype=float).reshape(nv, per_vertex)
    assert ((rows[:, 3:] >= 0) & (rows[:, 3:] <= 255)).all()
    F = np.array(numbers[per_vertex * nv:per_vertex * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    assert (F[:, 0] == 3).all() and len(numbers) == per_vertex * nv + 4 * nf
    return rows[:, :3], F[:, 1:]


def read_obj(path):
    lines = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    V = np.array([l[1:] for l in lines if l[0] == "v"], dtype=float)
    F = np.array([l[1:] for l in lines if l[0] == "f"], dtype=np.int64) - 1
    assert len(V) + len(F) == len(lines)
    return V, F


def read_ascii_stl(path):
    """(corners of each facet: n×3×3, facet normals: n×3)"""
    words = open(path).read().split()
    assert words[0] == "solid" and words[-2] == "endsolid"
    normals = [words[i + 2:i + 5] for i, w in enumerate(words) if w == "facet"]
    corners = [words[i + 1:i + 4] for i, w in enumerate(words) if w == "vertex"]
    return np.array(corners, dtype=float).reshape(-1, 3, 3), np.array(normals, dtype=float)


def read_binary_stl(path):
    data = open(path, "rb").read()
    (n,) = np.frombuffer(data, "<u4", 1, 80)
    assert len(data) == 84 + 50 * n
    rec = np.frombuffer(data, np.dtype([("n", "<f4", 3), ("c", "<f4", (3, 3)), ("a", "<u2")]), n, 84)
    return rec["c"].astype(float), rec["n"].astype(float)


@pytest.fixture(scope="module")
def sphere(tmp_path_factory):
    d = tmp_path_factory.mktemp("formats")
    r = run("generate", "icosphere", "--level", 2, "--noise", 0.05, "--seed", 3, "-o", d / "s.ply")
    assert r.returncode == 0, r.stderr
    return d, read_binary_ply(d / "s.ply")


@pytest.mark.parametrize("command", ["subdivide", "curvature"])
def test_every_format_reads_back_as_the_ply(sphere, command):
    d, _ = sphere
    extra = ["--levels", 1] if command == "subdivide" else []
    assert run(command, d / "s.ply", "-o", d / f"{command}.ply", *extra).returncode == 0
    V, F = read_binary_ply(d / f"{command}.ply")
    for ext, reader in [("off", read_off), ("obj", read_obj)]:
        r = run(command, d / "s.ply", "-o", d / f"{command}.{ext}", *extra)
        assert r.returncode == 0, r.stderr
        V2, F2 = reader(d / f"{command}.{ext}")
        assert (F2 == F).all() and (V2 == V).all(), ext  # every double exactly (%.17g)
        # `curvature` writes H and K, which these formats cannot hold: said once.
        assert r.stderr.count("written without") == (command == "curvature"), r.stderr
    for ascii, reader in [(True, read_ascii_stl), (False, read_binary_stl)]:
        path = d / f"{command}_{int(ascii)}.stl"
        r = run(command, d / "s.ply", "-o", path, *extra, *(["--ascii"] if ascii else []))
        assert r.returncode == 0, r.stderr
        corners, normals = reader(path)
        expected = V[F]
        assert np.abs(corners - expected).max() <= (0 if ascii else 1e-6 * np.abs(V).max())
        turn = np.cross(expected[:, 1] - expected[:, 0], expected[:, 2] - expected[:, 0])
        turn /= np.linalg.norm(turn, axis=1)[:, None]
        assert np.abs(normals - turn).max() < 1e-6  # unit facet normals, the way the corners turn


@pytest.mark.parametrize("name", ["out.xyz", "out", "out.ply.gz"])
def test_an_unknown_extension_is_refused_before_any_work(sphere, name):
    d, _ = sphere
    for args in (["fair", d / "s.ply"], ["fill", d / "s.ply"], ["generate", "grid"]):
        r = run(*args, "-o", d / name)
        assert r.returncode != 0
        assert "unknown mesh file extension" in r.stderr and r.stderr.count("\n") == 1, r.stderr
        assert not (d / name).exists()
        assert not [p for p in os.listdir(d) if p.startswith(name)]  # no temporary left either

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""region_sweep.py [MESH] [options]: fair seeded regions of a scan, the way a MeshLab user selects
a bumpy part and fairs only that, and check every output (issue 42).

A region is the faces whose centroid lies within the --quantile of centroid distances to a random
vertex; with --noise, N(0, noise * mean edge) is added to its faces' vertices (one generator,
numpy's default_rng(--seed), for both, as the issue's recipe). Each region runs as it is and noisy
(--variants). Every run fairs to the limit shape (feature_size=0; the default since issue 42 is a
fairing amount) with the default options but max_seconds (and --scheme). Per run, one line:
  faces, seconds, attempts, stop, the region's energy before -> after (measured here, on the
  vertices of the region's faces: the region and its fixed rings, each mesh at its own resolution),
  manifold (every edge on at most two faces, one fan per vertex), coincident vertices (used
  vertices at the same point), new crossing faces (vcglib's test through bench's mesh_check, output
  count minus input count), outside (the faces off the region: every one in the output, bit for
  bit), read (elastica.read takes the PLY elastica.write wrote, with no vertex merged), and the
  report's region_resolution_gap (how much the region's energy rises when Loop-subdivided once; above
  0.1 a faceted lid, docs/decisions.md "Regions"), region_runs and scheme.

  PYTHONPATH=build/python bench/region_sweep.py ~/.cache/elastica/cgal-data-*/meshes/lion-head.off \
      --regions 8 --noise 0.1 --max-seconds 60 --mesh-check build/bin/mesh_check

With --sizes, one region per size instead: the SIZE faces whose
centroids are nearest a random vertex (default_rng(--seed)), no noise, optionally on the scan
Loop-subdivided --loop times (bench/loop_energy.py's Loop step; closed scans only); "all" fairs the
whole scan (its border fixed). One Markdown table row per run, with the load average before it:

  PYTHONPATH=build/python bench/region_sweep.py /work/zoo/data/meshes/man.off --sizes 1000,10000,50000 --loop 2

With --sizes and --cgal (docs/benchmarks.md, "Regions beside CGAL's fair()"), each region (with
--region-noise, N(0, that * mean edge) on its vertices) is also faired by CGAL's fair() on the same
moving vertices, and the table has both times, stop, attempts, resolution gap and whole-mesh energies:

  PYTHONPATH=build/python bench/region_sweep.py ~/.cache/elastica/cgal-data-*/meshes/armadillo.off \
      --sizes 1000,10000,50000 --region-noise 0.1 --max-seconds 120 --cgal build/bin/cgal_region_fair
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import elastica


def mixed_areas(V, F):
    """Meyer's mixed Voronoi area per vertex (the core's default), for the region's energy."""
    A = np.zeros(len(V))
    P = V[F]  # faces x corners x 3
    for k in range(3):
        i, j, l = k, (k + 1) % 3, (k + 2) % 3
        e_ij, e_il = P[:, j] - P[:, i], P[:, l] - P[:, i]
        e_jl = P[:, l] - P[:, j]
        area = 0.5 * np.linalg.norm(np.cross(e_ij, e_il), axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            def cot(a, b):
                return np.einsum("ij,ij->i", a, b) / np.linalg.norm(np.cross(a, b), axis=1)
            cot_j = cot(P[:, i] - P[:, j], P[:, l] - P[:, j])  # angle at j, opposite edge il
            cot_l = cot(P[:, i] - P[:, l], P[:, j] - P[:, l])  # angle at l, opposite edge ij
            voronoi = (np.einsum("ij,ij->i", e_il, e_il) * cot_j + np.einsum("ij,ij->i", e_ij, e_ij) * cot_l) / 8
        obtuse_i = np.einsum("ij,ij->i", e_ij, e_il) < 0
        obtuse_other = (np.einsum("ij,ij->i", -e_ij, e_jl) < 0) | (np.einsum("ij,ij->i", -e_il, -e_jl) < 0)
        a = np.where(obtuse_i, area / 2, np.where(obtuse_other, area / 4, voronoi))
        np.add.at(A, F[:, i], np.nan_to_num(a))
    return A


def border_vertices(F):
    e = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    u, c = np.unique(e, axis=0, return_counts=True)
    return np.unique(u[c == 1])


def region_energy(V, F, region_faces):
    """sum (4H^2 - 2K) A over the interior vertices of the region's faces (elastica.curvature's H
    and K, mixed areas), as the flow's energy sums it."""
    c = elastica.curvature(V, F)
    H, K = np.asarray(c["H"]), np.asarray(c["K"])
    A = mixed_areas(V, F)
    verts = np.unique(F[region_faces])
    verts = np.setdiff1d(verts, border_vertices(F))
    return float(np.sum((4 * H[verts] ** 2 - 2 * K[verts]) * A[verts]))


def manifold(F):
    e = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    _, c = np.unique(e, axis=0, return_counts=True)
    if c.max() > 2:
        return False
    # one fan per vertex: the faces at a vertex, joined across shared edges, are connected
    at = {}
    for f, t in enumerate(F):
        for v in t:
            at.setdefault(int(v), []).append(f)
    for v, fs in at.items():
        if len(fs) < 2:
            continue
        parent = {f: f for f in fs}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x
        by_edge = {}
        for f in fs:
            for w in F[f]:
                if w != v:
                    by_edge.setdefault(int(w), []).append(f)
        for group in by_edge.values():
            for g in group[1:]:
                parent[find(g)] = find(group[0])
        if len({find(f) for f in fs}) > 1:
            return False
    return True


def coincident(V, F):
    used = V[np.unique(F)]
    return len(used) - len(np.unique(used, axis=0))


def face_keys(V, F):
    """Each face as the bytes of its three corners, rotated to start at its smallest corner."""
    keys = []
    for t in F:
        c = [V[i].tobytes() for i in t]
        k = min(range(3), key=lambda i: c[i])
        keys.append(b"".join(c[k:] + c[:k]))
    return keys


def crossing_faces(mesh_check, V, F, tmp):
    if not mesh_check:
        return None
    path = os.path.join(tmp, "check.ply")
    elastica.write(path, V, F)
    out = subprocess.run([mesh_check, path], capture_output=True, text=True)
    try:
        return json.loads(out.stdout.strip().splitlines()[-1])["self_intersecting_faces"]
    except Exception:
        return None


def again(V, F, sel, V3, F3, rep, max_seconds):
    """Fairs an output's region (the faces that are not the input's faces off the region) again
    with the defaults and prints the region's energy before and after (region_energy, each mesh at
    its own resolution): a 'converged' that a longer run takes much lower was not one."""
    V3, F3 = np.asarray(V3, float), np.asarray(F3)
    index = {k: i for i, k in enumerate(face_keys(V3, F3))}
    kept = [index[k] for k in face_keys(V, F[np.setdiff1d(np.arange(len(F)), sel)])]
    region = np.setdiff1d(np.arange(len(F3)), kept)
    e1 = region_energy(V3, F3, region)
    c0 = time.process_time()
    V4, F4, rep2 = elastica.fair(V3, F3, region, feature_size=0, max_seconds=max_seconds)
    V4, F4 = np.asarray(V4), np.asarray(F4)
    index = {k: i for i, k in enumerate(face_keys(V4, F4))}
    kept = [index[k] for k in face_keys(V3, np.delete(F3, region, axis=0))]
    e2 = region_energy(V4, F4, np.setdiff1d(np.arange(len(F4)), kept))
    print(f"<!-- again: {rep2['steps']} attempts, {rep2['stop']}, cpu {time.process_time() - c0:.1f} s, "
          f"region E {e1:.4g} -> {e2:.4g} ({100 * (e2 / e1 - 1):+.1f} %) -->", flush=True)


def sized_scan(args, V, F):
    """The scan --sizes runs on (Loop-subdivided --loop times) and its name in the table."""
    if args.loop:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        from loop_energy import loop_subdivide
        for _ in range(args.loop):
            V, F = loop_subdivide(V, F)
    return V, F, os.path.basename(args.mesh) + (f" Loop x{args.loop}" if args.loop else "")


def sizes_table(args, V, F):
    """One region per size (or the whole scan), one table row each."""
    V, F, name = sized_scan(args, V, F)
    centroids = V[F].mean(axis=1)
    threads = os.environ.get("OMP_NUM_THREADS", "all")
    print(f"| scan | vertices | region faces | seconds | attempts (rejected) | stop | region E before -> after | outside kept | load, threads |")
    print("|---|---:|---:|---:|---:|---|---|---|---|")
    for size in args.sizes.split(","):
        rng = np.random.default_rng(args.seed)
        load = os.getloadavg()[0]
        # The seconds are elastica.fair's alone: not the region's choice nor --check-outside's check
        # (a Python set of every face, seconds on a 400k-vertex scan).
        if size == "all":
            t0, c0 = time.time(), time.process_time()
            V3, F3, rep = elastica.fair(V, F, feature_size=0, scheme=args.scheme, max_seconds=args.max_seconds)
            secs, cpu = time.time() - t0, time.process_time() - c0
            energies = f"{rep['mesh_energy_before']:.4g} -> {rep['mesh_energy_after']:.4g} (whole)"
            kept, faces = "-", len(F)
        else:
            p = V[rng.integers(len(V))]
            d = np.linalg.norm(centroids - p, axis=1)
            sel = np.argsort(d, kind="stable")[:int(size)]
            t0, c0 = time.time(), time.process_time()
            V3, F3, rep = elastica.fair(V, F, sel, feature_size=0, scheme=args.scheme, max_seconds=args.max_seconds)
            secs, cpu = time.time() - t0, time.process_time() - c0
            energies = f"{rep['region_energy_before']:.4g} -> {rep['region_energy_after']:.4g}"
            faces = len(sel)
            kept = "-"
            if args.check_outside:
                outside = np.setdiff1d(np.arange(len(F)), sel)
                index = set(face_keys(V3, F3))
                kept = "yes" if all(k in index for k in face_keys(V, F[outside])) else "NO"
        stop = rep["stop"] + (f" ({rep['refused_because']})" if rep.get("refused_because") else "")
        print(f"| {name} | {len(V)} | {faces} | {secs:.2f} | {rep['steps']} ({rep.get('rejected_steps', 0)}) | "
              f"{stop} | {energies} | {kept} | {load:.1f}, {threads} |", flush=True)
        print(f"<!-- resolution gap {rep.get('region_resolution_gap', float('nan')):+.3f}, runs {rep.get('region_runs', 1)}, "
              f"scheme {rep['scheme']}; cpu {cpu:.1f} s; stages (vertices, attempts, E): "
              f"{[(st['vertices'], st['steps'], round(st['energy'], 4)) for st in rep['stages']]} -->", flush=True)
        if args.again and size != "all":
            again(V, F, sel, V3, F3, rep, args.again)
        if args.save:
            os.makedirs(args.save, exist_ok=True)
            elastica.write(os.path.join(args.save, f"{size}.ply"), V3, F3)


def cgal_table(args, V, F):
    """--sizes with --cgal: each region faired by elastica.fair (its limit shape) and by CGAL's
    fair() on the same moving vertices (bench/cgal_region_fair), one Markdown row each: wall seconds
    (elastica.fair's call; CGAL's fair() call alone), stop, attempts, the report's resolution gap,
    the whole mesh's energy (elastica.curvature's) of the input and of both outputs."""
    V, F, name = sized_scan(args, V, F)
    centroids = V[F].mean(axis=1)
    e = np.linalg.norm(V[F[:, 1]] - V[F[:, 0]], axis=1).mean()
    threads = os.environ.get("OMP_NUM_THREADS", "all")
    print("| scan | vertices | region faces | elastica s | stop | attempts | gap | CGAL s | ratio | "
          "whole-mesh E: input / elastica / CGAL | load, threads |")
    print("|---|---:|---:|---:|---|---:|---:|---:|---:|---|---|")
    energy = lambda V_, F_: elastica.curvature(V_, F_)["energy"]  # noqa: E731
    with tempfile.TemporaryDirectory() as tmp:
        for size in args.sizes.split(","):
            rng = np.random.default_rng(args.seed)
            p = V[rng.integers(len(V))]
            sel = np.argsort(np.linalg.norm(centroids - p, axis=1), kind="stable")[:int(size)]
            Vin = V.copy()
            verts = np.unique(F[sel])
            Vin[verts] += rng.normal(0, args.region_noise * e, (len(verts), 3))
            load = os.getloadavg()[0]
            t0 = time.time()
            V3, F3, rep = elastica.fair(Vin, F, sel, feature_size=0, scheme=args.scheme, max_seconds=args.max_seconds)
            secs = time.time() - t0
            mesh_in, region_in, cgal_out = (os.path.join(tmp, n) for n in ("in.ply", "region.txt", "cgal.ply"))
            elastica.write(mesh_in, Vin, F)
            np.savetxt(region_in, sel, fmt="%d")
            out = subprocess.run([args.cgal, mesh_in, region_in, cgal_out], capture_output=True, text=True)
            try:
                cg = json.loads(out.stdout.strip().splitlines()[-1])
                Vc, Fc = elastica.read(cgal_out)
                e_cgal = f"{energy(np.asarray(Vc), np.asarray(Fc)):.5g}" + ("" if cg["ok"] else " (failed)")
                cgal_s, ratio = f"{cg['seconds']:.3f}", f"{secs / max(cg['seconds'], 1e-9):.0f}"
            except Exception:  # noqa: BLE001 - a sweep reports every failure and goes on
                cgal_s, ratio, e_cgal = "error", "-", (out.stderr.strip() or "no output")[:60]
            stop = rep["stop"] + (f" ({rep['refused_because']})" if rep.get("refused_because") else "")
            print(f"| {name} | {len(V)} | {len(sel)} | {secs:.2f} | {stop} | {rep['steps']} | "
                  f"{100 * rep.get('region_resolution_gap', float('nan')):+.1f} % | {cgal_s} | {ratio} | "
                  f"{energy(Vin, F):.5g} / {energy(np.asarray(V3), np.asarray(F3)):.5g} / {e_cgal} | "
                  f"{load:.1f}, {threads} |", flush=True)
            print(f"<!-- runs {rep.get('region_runs', 1)}, scheme {rep['scheme']}; stages (vertices, attempts, E): "
                  f"{[(st['vertices'], st['steps'], round(st['energy'], 4)) for st in rep['stages']]} -->", flush=True)
            if args.save:
                os.makedirs(args.save, exist_ok=True)
                elastica.write(os.path.join(args.save, f"{size}.ply"), V3, F3)
                os.replace(cgal_out, os.path.join(args.save, f"{size}-cgal.ply"))
                elastica.write(os.path.join(args.save, f"{size}-in.ply"), Vin, F)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mesh")
    ap.add_argument("--regions", type=int, default=8)
    ap.add_argument("--quantile", type=float, default=0.03)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--noise", type=float, default=0.1, help="times the mean edge")
    ap.add_argument("--max-seconds", type=float, default=60)
    ap.add_argument("--scheme", default="auto", help="fair()'s scheme (auto, vector, semi-implicit)")
    ap.add_argument("--variants", default="clean,noisy", help="clean, noisy or both (comma-separated)")
    ap.add_argument("--mesh-check", default="", help="bench's mesh_check binary, for crossing faces")
    ap.add_argument("--only", default="", help="comma-separated run names (e.g. 3,3n) to run alone")
    ap.add_argument("--save", default="", help="a folder to write each output to (RUN.ply)")
    ap.add_argument("--sizes", default="", help="comma-separated region sizes in faces, or all: one region each")
    ap.add_argument("--loop", type=int, default=0, help="with --sizes: Loop-subdivide the scan this many times")
    ap.add_argument("--check-outside", action="store_true", help="with --sizes: check the faces off the region")
    ap.add_argument("--again", type=float, default=0, help="with --sizes: fair each output's region again with "
                    "this max_seconds and print its energy (is a 'converged' kept by a longer run?)")
    ap.add_argument("--cgal", default="", help="with --sizes: bench's cgal_region_fair binary; each region is "
                    "faired by CGAL's fair() too, and the table compares them")
    ap.add_argument("--region-noise", type=float, default=0, help="with --cgal: N(0, this * mean edge) on the region")
    args = ap.parse_args()

    V, F = elastica.read(args.mesh)
    V, F = np.asarray(V, dtype=float), np.asarray(F)
    if args.sizes and args.cgal:
        return cgal_table(args, V, F)
    if args.sizes:
        return sizes_table(args, V, F)
    e = np.linalg.norm(np.concatenate([V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 1]], V[F[:, 0]] - V[F[:, 2]]]), axis=1).mean()
    print(f"{os.path.basename(args.mesh)}: {len(V)} vertices, {len(F)} faces, mean edge {e:.4g}")
    print("run  faces  seconds  attempts  stop          region E before -> after   manifold coincident "
          "new_crossing outside read  (report's region / mesh energies)")
    only = set(filter(None, args.only.split(",")))
    rng = np.random.default_rng(args.seed)
    centroids = V[F].mean(axis=1)
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.regions):
            # the recipe: one generator, a vertex, then the noise on the region's vertices
            p = V[rng.integers(len(V))]
            d = np.linalg.norm(centroids - p, axis=1)
            sel = np.nonzero(d <= np.quantile(d, args.quantile))[0]
            Vn = V.copy()
            verts = np.unique(F[sel])
            Vn[verts] += rng.normal(0, args.noise * e, (len(verts), 3))  # drawn always: the same regions
            variants = ([("", V)] if "clean" in args.variants else []) + \
                       ([("n", Vn)] if "noisy" in args.variants else [])
            for suffix, Vin in variants:
                name = f"{r}{suffix}"
                if only and name not in only:
                    continue
                before = region_energy(Vin, F, sel)
                cross_in = crossing_faces(args.mesh_check, Vin, F, tmp)
                t0 = time.time()
                try:
                    V3, F3, rep = elastica.fair(Vin, F, sel, feature_size=0, scheme=args.scheme, max_seconds=args.max_seconds)
                except Exception as ex:  # noqa: BLE001 - a sweep reports every failure and goes on
                    print(f"{name:4} {len(sel):6} {time.time() - t0:8.2f}  error: {ex}")
                    continue
                secs = time.time() - t0
                V3, F3 = np.asarray(V3), np.asarray(F3)
                outside = np.setdiff1d(np.arange(len(F)), sel)
                out_keys = face_keys(V3, F3)
                in_keys = face_keys(Vin, F[outside])
                index = {k: i for i, k in enumerate(out_keys)}
                outside_ok = all(k in index for k in in_keys)
                out_region = np.setdiff1d(np.arange(len(F3)), [index[k] for k in in_keys if k in index])
                after = region_energy(V3, F3, out_region) if len(out_region) else float("nan")
                cross_out = crossing_faces(args.mesh_check, V3, F3, tmp)
                new_cross = "?" if cross_in is None or cross_out is None else str(cross_out - cross_in)
                path = os.path.join(tmp, "out.ply")
                elastica.write(path, V3, F3)
                try:
                    V4, F4 = elastica.read(path)
                    read = "yes" if len(V4) == len(np.unique(F3)) and len(F4) == len(F3) else "merged"
                except Exception as ex:  # noqa: BLE001
                    read = "NO: " + str(ex)[:60]
                if args.save:
                    os.makedirs(args.save, exist_ok=True)
                    elastica.write(os.path.join(args.save, name + ".ply"), V3, F3)
                reg = (rep.get("region_energy_before", rep.get("energy_initial")),
                       rep.get("region_energy_after", rep.get("energy_final")))
                mesh_e = (rep.get("mesh_energy_before", rep.get("energy_input")),
                          rep.get("mesh_energy_after", rep.get("energy_output")))
                print(f"{name:4} {len(sel):6} {secs:8.2f} {rep['steps']:9}  {rep['stop']:13} "
                      f"{before:10.4g} -> {after:<10.4g}  {'yes' if manifold(F3) else 'NO':8} "
                      f"{coincident(V3, F3):10} {new_cross:>12} {'yes' if outside_ok else 'NO':7} {read:5} "
                      f"({reg[0]:.4g} -> {reg[1]:.4g} / {mesh_e[0]:.4g} -> {mesh_e[1]:.4g})"
                      + (f" refused: {rep['refused_because']}, kept stage {rep['kept_stage']}" if "refused_because" in rep else "")
                      + f" resolution gap {rep.get('region_resolution_gap', float('nan')):+.3f}, runs {rep.get('region_runs', 1)}, {rep['scheme']}",
                      flush=True)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""amount_operators_sweep.py [--build DIR] [--noise "0.1 0.3 0.5"] [--edges "1 1.5 2 2.5 3"]
[--operators graph] MESH...: the fairing amount's filter with the operators named
(bench/amount_operators: cotangent or graph, FlowOptions::amountOperators) at amounts in MEAN edge
lengths, to size the rough scan's default (app/fairing_amount.h, graphAmountEdges). For each scan
and noise level (bench/add_noise: 3-D, uniform in a ball of NOISE x the mean edge, seed 1) prints
the roughness elastica measures and the distance to the clean scan (bench/mesh_distance: the mean
of both RMS, / the diagonal) for each amount; the best in bold. One run each. /usr/bin/python3."""
import argparse
import itertools
import os
import json
import subprocess
import sys
import tempfile


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser()
    for flag, default in (("--build", os.path.join(here, "..", "build")), ("--noise", "0.1 0.3 0.5"),
                          ("--edges", "1 1.5 2 2.5 3"), ("--operators", "graph")):
        ap.add_argument(flag, default=default)
    ap.add_argument("meshes", nargs="+")
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(a.build, "python"))
    import elastica

    bin_ = os.path.join(a.build, "bin")
    tmp = tempfile.mkdtemp()
    edges = a.edges.split()
    print(f"| scan | noise | roughness | " + " | ".join(f"{e} mean edges" for e in edges) + " |")
    print("|---|---:|---:|" + "---:|" * len(edges))
    for mesh, noise in itertools.product(a.meshes, a.noise.split()):
        name = os.path.splitext(os.path.basename(mesh))[0]
        src = mesh if float(noise) == 0 else os.path.join(tmp, f"{name}-{noise}.ply")
        if src != mesh:
            subprocess.run([os.path.join(bin_, "add_noise"), mesh, src, noise, "1"], check=True)
        V, F = elastica.read(src)
        rough = elastica.surface_roughness(V, F)
        d = []
        for e in edges:
            out = os.path.join(tmp, "out.ply")
            subprocess.run([os.path.join(bin_, "amount_operators"), src, out, e, a.operators], check=True,
                           capture_output=True)
            j = json.loads(subprocess.run([os.path.join(bin_, "mesh_distance"), out, mesh], check=True,
                                          capture_output=True, text=True).stdout)
            d.append((j["a_to_b"]["rms_per_diagonal"] + j["b_to_a"]["rms_per_diagonal"]) / 2)
        cells = [f"**{x:.3e}**" if x == min(d) else f"{x:.3e}" for x in d]
        print(f"| {name} | {noise} | {rough:.4f} | " + " | ".join(cells) + " |", flush=True)

if __name__ == "__main__":
    main()

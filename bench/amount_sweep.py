#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""amount_sweep.py [--build DIR] [--noise "0.1 0.3"] [--edges "2 3 4"] MESH...: how the fairing
amount's best size depends on a scan's roughness, to size the default (app/fairing_amount.h). For
each scan and noise level (bench/add_noise: 3-D, uniform in a ball of NOISE x the mean edge, seed 1)
prints the roughness elastica measures (elastica.surface_roughness) and, for each amount in edge
lengths (x the 25 % edge quantile, as the default counts them), the distance to the clean scan
(bench/mesh_distance: the mean of both RMS, / the diagonal). Noise 0 is the clean scan itself (its
distance is how far the amount moved it). One run each. Run with /usr/bin/python3."""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(os.path.dirname(__file__), "..", "build"))
    ap.add_argument("--noise", default="0 0.1 0.2 0.3 0.5")
    ap.add_argument("--edges", default="2 3 4 6 8")
    ap.add_argument("meshes", nargs="+")
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(a.build, "python"))
    import elastica
    import numpy as np

    tmp = tempfile.mkdtemp()
    print("| scan | noise | roughness | " + " | ".join(f"{e} edges" for e in a.edges.split()) + " | default (edges) |")
    print("|---|---:|---:|" + "---:|" * (len(a.edges.split()) + 1))
    for mesh in a.meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        for noise in a.noise.split():
            noisy = os.path.join(tmp, f"{name}-{noise}.ply")
            if float(noise) > 0:
                subprocess.run([os.path.join(a.build, "bin", "add_noise"), mesh, noisy, noise, "1"], check=True)
            else:
                noisy = mesh
            V, F = elastica.read(noisy)
            rough = elastica.surface_roughness(V, F)
            L = np.linalg.norm(V[F] - V[np.roll(F, -1, axis=1)], axis=2).ravel()
            q25 = np.sort(L)[int(np.floor(0.25 * (len(L) - 1)))]
            cells = []
            for e in [float(x) for x in a.edges.split()] + [None]:
                out = os.path.join(tmp, "out.ply")
                V2, F2, r = elastica.fair(V, F, feature_size=None if e is None else e * q25, max_seconds=120)
                elastica.write(out, V2, F2)
                d = json.loads(subprocess.run([os.path.join(a.build, "bin", "mesh_distance"), out, mesh],
                                              check=True, capture_output=True, text=True).stdout)
                dist = (d["a_to_b"]["rms_per_diagonal"] + d["b_to_a"]["rms_per_diagonal"]) / 2
                cell = f"{dist:.3e}"
                if e is None:
                    cell += f" ({r.get('feature_size', 0) / q25:.2f})"
                cells.append(cell)
            print(f"| {name} | {noise} | {rough:.4f} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""meshlab_screenshot_input.py SCAN OUT_DIR: the inputs of bench/meshlab_screenshots.sh. Writes
OUT_DIR/lion_head.ply (the scan as ASCII PLY) and OUT_DIR/lion_head_region.ply: the 1,000 faces whose
centroids are nearest a vertex of the cheek that MeshLab shows first, the vertices of the 500 nearest moved by
Gaussian noise of 0.2 mean edge lengths, selected with MeshLab's face flag (vcglib's SELECTED bit, 0x20)."""
import os
import sys

import numpy as np

import elastica


def write_ply(path, V, F, selected=None):
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(V)}\nproperty double x\nproperty double y\n"
                f"property double z\nelement face {len(F)}\nproperty list uchar int vertex_indices\n")
        if selected is not None:
            f.write("property int flags\n")
        f.write("end_header\n")
        for p in V:
            f.write(f"{p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        for i, t in enumerate(F):
            f.write(f"3 {t[0]} {t[1]} {t[2]}" + (f" {32 if selected[i] else 0}" if selected is not None else "") + "\n")


def main(scan, out):
    V, F = elastica.read(scan)
    write_ply(os.path.join(out, "lion_head.ply"), V, F)
    rng = np.random.default_rng(11)
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    ell = np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()
    centroids = V[F].mean(axis=1)
    # On the cheek MeshLab faces first (it looks down -z): a quarter of the width off the middle.
    lo, hi = V.min(axis=0), V.max(axis=0)
    seed = V[np.argmin(np.linalg.norm(V - [lo[0] + 0.7 * (hi[0] - lo[0]), 0.5 * (lo[1] + hi[1]), hi[2]], axis=1))]
    region = np.argsort(np.linalg.norm(centroids - seed, axis=1))[:1000]
    selected = np.zeros(len(F), bool)
    selected[region] = True
    # The damage lies inside the selection: the selection's two outer rings stay fixed (G1), so
    # noise there would stay.
    moved = np.unique(F[region[:500]])
    V2 = V.copy()
    V2[moved] += rng.normal(0, 0.2 * ell, (len(moved), 3))
    write_ply(os.path.join(out, "lion_head_region.ply"), V2, F, selected)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

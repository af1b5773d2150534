#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""region_loop_gap.py INPUT OUTPUT: is a faired region's output a fair surface, or a faceted lid?

The vector scheme can leave a region as a few large flat faces meeting at creases, whose discrete
energy is small (docs/decisions.md, "Regions"). One Loop subdivision shows what such a
mesh stands for. This prints, over the output's vertices that are not the input's (the region's
moved and new vertices), E = sum (4H^2 - 2K) A at the output's resolution and over the same part of
the whole output Loop-subdivided once (those vertices and the new vertices of the edges between two
of them), their relative gap, and the largest face among them against the input's mean face.
The core measures its own gap differently (FlowReport::regionResolutionGap: the region alone
subdivided, its border kept), so the two differ near the region's rim.

  PYTHONPATH=build/python bench/region_loop_gap.py scan.off faired.ply
"""
import os
import sys

import numpy as np

import elastica

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from loop_energy import loop_subdivide  # noqa: E402
from region_sweep import mixed_areas  # noqa: E402


def terms(V, F):
    c = elastica.curvature(V, F)
    return (4 * np.asarray(c["H"]) ** 2 - 2 * np.asarray(c["K"])) * mixed_areas(V, F)


def face_areas(V, F):
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    V0, F0 = (np.asarray(a) for a in elastica.read(sys.argv[1]))
    V, F = (np.asarray(a) for a in elastica.read(sys.argv[2]))
    V = np.asarray(V, float)
    known = {tuple(v) for v in V0}
    moved = np.array([tuple(v) not in known for v in V])
    edge_points = {}
    V1, F1 = loop_subdivide(V, F, border=True, edge_points=edge_points)
    moved1 = np.zeros(len(V1), bool)
    moved1[:len(V)] = moved
    for (a, b), w in edge_points.items():
        moved1[w] = moved[a] and moved[b]
    e0, e1 = terms(V, F)[moved].sum(), terms(V1, F1)[moved1].sum()
    largest = face_areas(V, F)[moved[F].all(axis=1)].max(initial=0)
    print(f"{sys.argv[2]}: region E {e0:.2f}, Loop-subdivided {e1:.2f}, gap {100 * (e1 / e0 - 1):+.1f} %, "
          f"largest face {largest / face_areas(V0, F0).mean():.1f}x the input's mean")


if __name__ == "__main__":
    main()

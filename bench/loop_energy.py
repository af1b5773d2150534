#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""loop_energy.py MESH [LEVELS]: the total curvature energy E of MESH and of its Loop subdivisions.

A check that a faired mesh resolves its shape. Loop's limit surface is smooth, so where the mesh
resolves the surface E changes little under subdivision (the elephant's default output: 168.9,
171.3, 171.6); where the flow found a state that only its coarse mesh allows (a tunnel closed to a
pin-hole a few edges around), E jumps (the vector scheme's elephant: 143.8, 187.0, 270.1).

Uses the `elastica` Python module (build it with the project: BUILD/python) for reading and for
E = sum (4H^2 - 2K) A, exactly as `elastica curvature` computes it. Closed manifold meshes only
(a border is refused; with --border, an open mesh too: a border edge's point is its midpoint and a
border vertex stays, so a fixed border stays where it was). Vertex weights are Loop's own, beta = (5/8 - (3/8 + cos(2 pi/k)/4)^2)/k;
the core's subdivideLoop (the flow's resolution check) uses Warren's 3/(8k) (3/16 at k = 3). Both
are 1/16 at valence 6, so the two differ only around irregular vertices.

  PYTHONPATH=build/python bench/loop_energy.py out.ply 2 [--border [--beyond R]]

--beyond R also prints E over the vertices farther than R mean edge lengths (the level-0 mesh's)
from the border: where a fixed border is the scan's own rough rows, Loop's smoothing of them
raises E whatever the faired part does (mannequin-devil).
"""
import sys

import numpy as np

import elastica


def loop_subdivide(V, F, border=False, edge_points=None):
    """One Loop step: edge points 3/8, 3/8, 1/8, 1/8; vertices (1 - k beta) v + beta sum of ring.
    With `border`, a border edge's point is its midpoint and a border vertex stays. The old
    vertices keep their indices; `edge_points`, a dict if given, receives (a, b) -> the new
    vertex of edge ab (a < b)."""
    opposite = {}
    for a, b, c in F:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            opposite.setdefault((min(u, v), max(u, v)), []).append(w)
    if any(len(o) > 2 or (len(o) != 2 and not border) for o in opposite.values()):
        raise SystemExit("loop_energy: the mesh has a border (see --border) or a non-manifold edge")
    n = len(V)
    index = {e: n + i for i, e in enumerate(opposite)}
    if edge_points is not None:
        edge_points.update(index)
    out = np.zeros((n + len(opposite), 3))
    ring = [[] for _ in range(n)]
    on_border = np.zeros(n, bool)
    for (a, b), o in opposite.items():
        ring[a].append(b)
        ring[b].append(a)
        if len(o) == 1:
            on_border[[a, b]] = True
            out[index[(a, b)]] = (V[a] + V[b]) / 2
        else:
            out[index[(a, b)]] = 3 / 8 * (V[a] + V[b]) + 1 / 8 * (V[o[0]] + V[o[1]])
    for v in range(n):
        k = len(ring[v])
        if on_border[v] or k == 0:
            out[v] = V[v]
            continue
        beta = (5 / 8 - (3 / 8 + np.cos(2 * np.pi / k) / 4) ** 2) / k
        out[v] = (1 - k * beta) * V[v] + beta * V[ring[v]].sum(0)
    faces = []
    for a, b, c in F:
        ab, bc, ca = (index[(min(u, v), max(u, v))] for u, v in ((a, b), (b, c), (c, a)))
        faces += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return out, np.array(faces)


def energy_beyond(V, F, reach):
    """E over the vertices farther than `reach` from every border vertex."""
    from region_sweep import border_vertices, mixed_areas
    c = elastica.curvature(V, F)
    H, K = np.asarray(c["H"]), np.asarray(c["K"])
    B = V[border_vertices(F)]
    far = np.ones(len(V), bool)
    for s in range(0, len(V), 2000):
        far[s:s + 2000] = np.min(np.linalg.norm(V[s:s + 2000, None, :] - B[None], axis=2), axis=1) > reach
    return np.sum(((4 * H ** 2 - 2 * K) * mixed_areas(V, F))[far])


def main():
    argv = sys.argv[1:]
    beyond = None
    if "--beyond" in argv:
        i = argv.index("--beyond")
        beyond = float(argv[i + 1])
        del argv[i:i + 2]
    args = [a for a in argv if a != "--border"]
    border = len(args) < len(argv)
    if len(args) not in (1, 2):
        raise SystemExit(__doc__)
    V, F = elastica.read(args[0])
    V, F = np.asarray(V, float), np.asarray(F)
    levels = int(args[1]) if len(args) == 2 else 2
    edge = np.mean(np.linalg.norm(V[F[:, 0]] - V[F[:, 1]], axis=1))
    for level in range(levels + 1):
        energy = elastica.curvature(V, F)["energy"]
        line = f"level {level}: {len(V)} vertices, E {energy:.2f}"
        if beyond is not None and border:
            line += f", E beyond {beyond:g} edges of the border {energy_beyond(V, F, beyond * edge):.3f}"
        print(line)
        if level < levels:
            V, F = loop_subdivide(V, F, border)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""default_amount.py MESH...: the default `fair` (a fairing amount sized from the mesh,
app/fairing_amount.h) on whole meshes, one row each: the amount in mean edge lengths, how often it
was halved, how far the surface moved (RMS and largest, as fractions of the bounding-box diagonal),
the energy before and after, the time. Prints a Markdown table (docs/options.md, "The default
amount"). Run with PYTHONPATH=build/python and /usr/bin/python3."""
import os
import sys
import time

import elastica


def main(paths):
    print("| mesh | vertices | amount (mean edges) | halved | moved RMS / max (% of diagonal) | E before → after | seconds |")
    print("|---|---:|---:|---:|---|---|---:|")
    for path in paths:
        V, F = elastica.read(path)
        start = time.perf_counter()
        V2, F2, r = elastica.fair(V, F)
        seconds = time.perf_counter() - start
        m = r["moved"]
        print(f"| {os.path.basename(path)} | {len(V):,} | {r.get('feature_size_edges', 0):.2f} | "
              f"{r.get('feature_size_halvings', 0)} | {100 * m['rms_per_diagonal']:.3f} / {100 * m['max_per_diagonal']:.2f} | "
              f"{r['mesh_energy_before']:.0f} → {r['mesh_energy_after']:.0f} | {seconds:.2f} |", flush=True)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])

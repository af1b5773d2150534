# SPDX-License-Identifier: GPL-3.0-or-later
"""An ASCII PLY (elastica generate --ascii) with its positions rounded to float, as MeshLab keeps them,
and its faces above z = 0 selected as MeshLab's face flags (vcg's SELECTED bit, 0x20): the selected
region of scripts/meshlab2025.sh.   python3 select_upper.py IN.ply OUT.ply"""
import sys

import numpy as np

lines = open(sys.argv[1]).read().splitlines()
end = lines.index("end_header")
nv = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
header = lines[:end] + ["property int flags", "end_header"]
V = np.array([[float(x) for x in l.split()[:3]] for l in lines[end + 1:end + 1 + nv]], np.float32)
out = header + [" ".join(repr(float(x)) for x in v) for v in V]
selected = 0
for l in lines[end + 1 + nv:]:
    f = [int(x) for x in l.split()[1:4]]
    s = 32 if all(V[i, 2] > 0 for i in f) else 0
    selected += s > 0
    out.append(l.strip() + " " + str(s))
if selected == 0:
    sys.exit("no face above z = 0")
open(sys.argv[2], "w").write("\n".join(out) + "\n")

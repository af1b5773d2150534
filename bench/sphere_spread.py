#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""sphere_spread.py MESH: radius spread (max - min) / r about the least-squares sphere, in percent.

Reads PLY (binary or ASCII, as elastica writes it) or OFF vertex positions only."""
import struct
import sys

import numpy as np


def positions(path):
    data = open(path, "rb").read()
    if path.endswith(".off") or data.split(None, 1)[0].endswith(b"OFF"):
        toks = data.decode().split()
        i = 1 if toks[0].endswith("OFF") else 0  # OFF, COFF, NOFF...
        n = int(toks[i])
        return np.array(toks[i + 3:i + 3 + 3 * n], float).reshape(n, 3)
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    fmt = next(l for l in header if l.startswith("format")).split()[1]
    n, props, in_vertex = 0, [], False
    for line in header:
        t = line.split()
        if t[0] == "element":
            in_vertex = t[1] == "vertex"
            if in_vertex:
                n = int(t[2])
        elif t[0] == "property" and in_vertex:
            props.append((t[1], t[2]))
    if fmt == "ascii":
        rows = data[end:].decode().split("\n")[:n]
        return np.array([[float(x) for x in r.split()[:3]] for r in rows])
    codes = {"float": "f4", "float32": "f4", "double": "f8", "float64": "f8", "uchar": "u1", "uint8": "u1",
             "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4", "short": "i2", "ushort": "u2", "char": "i1"}
    dtype = np.dtype([(name, "<" + codes[t]) for t, name in props])
    v = np.frombuffer(data, dtype=dtype, count=n, offset=end)
    return np.stack([v["x"], v["y"], v["z"]], 1).astype(float)


P = positions(sys.argv[1])
A = np.c_[2 * P, np.ones(len(P))]
x = np.linalg.lstsq(A, (P ** 2).sum(1), rcond=None)[0]
c = x[:3]
r = np.sqrt(x[3] + c @ c)
d = np.linalg.norm(P - c, axis=1)
print("%.3f" % (100 * (d.max() - d.min()) / r))

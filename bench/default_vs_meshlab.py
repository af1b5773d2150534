#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""default_vs_meshlab.py [--build DIR] [--noise "0 0.3"] [--pictures DIR] MESH...: the default
`fair` (no options: the amount sized from the scan's edges and roughness, app/fairing_amount.h)
beside MeshLab's own default smoothing run by Debian's meshlabserver: Taubin Smooth (lambda 0.5,
mu -0.53, 10 steps) and HC Laplacian Smooth (once). Each scan as given (noise 0) and with 3-D vertex
noise (bench/add_noise: uniform in a ball of NOISE x the mean edge, seed 1). Distance to the clean
scan: the mean of both RMS (bench/mesh_distance), / the clean scan's diagonal. Also the roughness
before and after (report['roughness_before'/'roughness_after']), the amount in edge lengths, whether
the result was reported rough, and for the clean scan how far the default moved it (RMS, % of the
diagonal). One run each; prints a Markdown table (docs/options.md, "The default amount").
Needs meshlabserver and xvfb-run. Run with /usr/bin/python3."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

TAUBIN = ('<filter name="Taubin Smooth"><Param type="RichFloat" value="0.5" name="lambda"/>'
          '<Param type="RichFloat" value="-0.53" name="mu"/><Param type="RichInt" value="10" name="stepSmoothNum"/>'
          '<Param type="RichBool" value="false" name="Selected"/></filter>')
HC = '<filter name="HC Laplacian Smooth"/>'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build"))
    ap.add_argument("--noise", default="0 0.3")
    ap.add_argument("--pictures", default="")
    ap.add_argument("meshes", nargs="+")
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(a.build, "python"))
    import elastica

    tmp = tempfile.mkdtemp()
    scripts = {}
    for name, body in (("taubin", TAUBIN), ("hc", HC)):
        scripts[name] = os.path.join(tmp, name + ".mlx")
        with open(scripts[name], "w") as f:
            f.write("<!DOCTYPE FilterScript>\n<FilterScript>\n" + body + "\n</FilterScript>\n")

    def distance(result, clean):
        out = subprocess.run([os.path.join(a.build, "bin", "mesh_distance"), result, clean],
                             check=True, capture_output=True, text=True).stdout
        j = json.loads(out)
        return (j["a_to_b"]["rms_per_diagonal"] + j["b_to_a"]["rms_per_diagonal"]) / 2

    def meshlab(script, src, dst):
        subprocess.run(["xvfb-run", "-a", "meshlabserver", "-i", src, "-o", dst, "-s", scripts[script]],
                       check=True, capture_output=True)
        return dst

    print("| scan | vertices | noise | input | MeshLab Taubin | MeshLab HC | elastica default | amount (edges) "
          "| roughness before → after | reported rough | clean: moved RMS |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---|---|---:|")
    for mesh in a.meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        for noise in a.noise.split():
            src = mesh
            if float(noise) > 0:
                src = os.path.join(tmp, f"{name}-{noise}.ply")
                subprocess.run([os.path.join(a.build, "bin", "add_noise"), mesh, src, noise, "1"], check=True)
            V, F = elastica.read(src)
            V2, F2, r = elastica.fair(V, F)
            ours = os.path.join(tmp, f"{name}-{noise}-elastica.ply")
            elastica.write(ours, V2, F2)
            t = meshlab("taubin", src, os.path.join(tmp, f"{name}-{noise}-taubin.ply"))
            h = meshlab("hc", src, os.path.join(tmp, f"{name}-{noise}-hc.ply"))
            d = {k: distance(p, mesh) for k, p in (("in", src), ("taubin", t), ("hc", h), ("ours", ours))}
            best = min(d["taubin"], d["hc"])
            mark = lambda k: f"**{d[k]:.3e}**" if d[k] == min(d["ours"], best) else f"{d[k]:.3e}"
            moved = f"{100 * r['moved']['rms_per_diagonal']:.3f} %" if float(noise) == 0 else ""
            print(f"| {name} | {len(V):,} | {noise} | {d['in']:.3e} | {mark('taubin')} | {mark('hc')} | {mark('ours')} | "
                  f"{r.get('feature_size_edges', 0):.2f} | {r.get('roughness_before', 0):.3f} → {r.get('roughness_after', 0):.3f} | "
                  f"{'yes: try ' + format(r['suggested_feature_size'], '.4g') if r.get('rough') else 'no'} | {moved} |", flush=True)
            if a.pictures and float(noise) > 0:
                os.makedirs(a.pictures, exist_ok=True)
                render = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render_mesh.sh")
                for label, p in (("clean", mesh), ("noisy", src), ("taubin", t), ("hc", h), ("elastica", ours)):
                    subprocess.run([render, p, os.path.join(a.pictures, f"default_{name}_{label}.png")],
                                   check=True, capture_output=True)


if __name__ == "__main__":
    main()

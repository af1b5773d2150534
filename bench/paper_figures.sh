#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The paper's Figs. 5–7 from real runs: a coarse tubular cage faired by the bilaplacian flow, the
# Laplacian-of-mean-curvature flow and the discrete elastica flow, coarse to fine (one linear 1-to-4
# subdivision between two stages), rendered coloured by mean curvature, with energy-versus-time
# curves; writes docs/figures.md with the pictures, the energy table and the command.
#
#   bench/paper_figures.sh [--elastica PATH] [--docs DIR] [--work DIR] [--seconds S] [--lmc-steps N]
#
#   --elastica  the elastica binary (default: build/bin/elastica)
#   --docs      where figures.md and figures/ go (default: docs)
#   --work      scratch directory for meshes and reports (default: a new temporary directory)
#   --seconds   wall-time budget of each elastica stage (default: 90)
#   --lmc-steps step budget of each Laplacian-of-H stage (default: 30000; a step budget, not a
#               time budget, so that the pictures do not depend on the machine's speed or load)
#
# Takes about four minutes on two cores. Needs f3d, xvfb, gnuplot-nox, jq and imagemagick
# (scripts/setup.sh). Every number on the page comes from this run's JSON reports.
set -euo pipefail

command_line="bench/paper_figures.sh${*:+ $*}"  # for the page, before the options are parsed
root=$(cd "$(dirname "$0")/.." && pwd)
elastica=$root/build/bin/elastica docs=$root/docs work="" seconds=90 lmc_steps=30000
while [[ $# -gt 0 ]]; do
  case "$1" in
    --elastica) elastica=$2; shift 2 ;;
    --docs) docs=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --lmc-steps) lmc_steps=$2; shift 2 ;;
    -h|--help) sed -n '3,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) printf 'paper_figures: unknown option %s (try --help)\n' "$1" >&2; exit 2 ;;
  esac
done
for tool in "$elastica" f3d xvfb-run gnuplot jq convert; do
  command -v "$tool" >/dev/null || { printf 'paper_figures: %s not found (scripts/setup.sh)\n' "$tool" >&2; exit 1; }
done
[[ -n "$work" ]] || work=$(mktemp -d)
mkdir -p "$work" "$docs/figures"
render=$root/bench/render_mesh.sh
log() { printf 'paper_figures: %s\n' "$*" >&2; }

# ---------------------------------------------------------------- the cage
# A flat frame of square tubes (one unit wide) around 2 × 1 square windows four units wide: genus 2,
# proportioned like the paper's tubular object (thin tubes, wide openings). Each unit square is
# split into four triangles around its centre, then subdivided once: 1,070 vertices.
cage_args=(frame --segments 2,1 --window 4 --level 1)
"$elastica" generate "${cage_args[@]}" -o "$work/cage.ply" >/dev/null
"$elastica" curvature "$work/cage.ply" -o "$work/cage_h.ply" >/dev/null
"$render" "$work/cage.ply" "$work/cage.png" --size 480,360 --edges

# ---------------------------------------------------------------- the three flows
# Each flow: stage 0 on the cage, `elastica subdivide`, stage 1 on the subdivided result. The
# elastica flow runs semi-implicit with edge flips and stops at its energy plateau (or the budget);
# the Laplacian of H runs the paper's explicit scheme for a step budget (its energy is not a
# Lyapunov function, so there is no plateau to wait for); the bilaplacian flow is explicit only and
# shrinks the tubes until they collapse (the divergence guard stops it; the script measures when),
# so it gets a step budget that stops it while there is still a shape to look at.
declare -A stage_opts=(
  [elastica]="--feature-size 0 --max-seconds $seconds"
  [lmc]="--feature-size 0 --scheme explicit --max-steps $lmc_steps"
  [bilaplacian]="--scheme explicit --max-steps 1500"
)
declare -A scheme_name=([elastica]="semi-implicit, remeshing (default)" [lmc]="explicit (paper)" [bilaplacian]="explicit (paper)")
flows=(bilaplacian lmc elastica)
early_steps=12
for flow in "${flows[@]}"; do
  log "$flow: stage 0"
  # shellcheck disable=SC2086  # the options are words
  nice -n 5 "$elastica" fair "$work/cage.ply" -o "$work/${flow}_0.ply" --flow "$flow" ${stage_opts[$flow]} \
    --report "$work/${flow}_0.json" --color-by-mean-curvature >/dev/null
  "$elastica" subdivide "$work/${flow}_0.ply" -o "$work/${flow}_0s.ply" >/dev/null
  log "$flow: stage 1"
  # shellcheck disable=SC2086
  nice -n 5 "$elastica" fair "$work/${flow}_0s.ply" -o "$work/${flow}_1.ply" --flow "$flow" ${stage_opts[$flow]} \
    --report "$work/${flow}_1.json" --color-by-mean-curvature >/dev/null
  for s in 0 1; do "$render" "$work/${flow}_$s.ply" "$work/${flow}_$s.png" --size 480,360; done
  # One picture per flow, as in the paper: the cage, (elastica: an early state,) the end of stage 0,
  # the end of stage 1.
  panels=("$work/cage.png")
  if [[ $flow == elastica ]]; then
    # The first few semi-implicit steps of the same run (it is deterministic): the tubes round off
    # before the windows close.
    "$elastica" fair "$work/cage.ply" -o "$work/elastica_early.ply" ${stage_opts[elastica]} --max-steps "$early_steps" \
      --report "$work/elastica_early.json" --color-by-mean-curvature >/dev/null
    "$render" "$work/elastica_early.ply" "$work/elastica_early.png" --size 480,360
    panels+=("$work/elastica_early.png")
  fi
  convert "${panels[@]}" "$work/${flow}_0.png" "$work/${flow}_1.png" +append -strip PNG8:"$docs/figures/fig_$flow.png"
done
# How far the bilaplacian flow goes before the divergence guard stops it (E above 10× its start).
log "bilaplacian: until it collapses"
"$elastica" fair "$work/cage.ply" -o "$work/bilaplacian_collapse.ply" --flow bilaplacian \
  --report "$work/bilaplacian_collapse.json" >/dev/null 2>&1 || true

# ---------------------------------------------------------------- energy curves
# E against wall-clock seconds, stage 1 drawn after stage 0 (the subdivision itself takes no time
# worth drawing). Log scale: E falls by an order of magnitude.
for flow in "${flows[@]}"; do
  offset=$(jq '.seconds' "$work/${flow}_0.json")
  {
    jq -r '.energy_history[] | "\(.seconds) \(.energy)"' "$work/${flow}_0.json"
    echo
    jq -r --argjson off "$offset" '.energy_history[] | "\(.seconds + $off) \(.energy)"' "$work/${flow}_1.json"
  } >"$work/${flow}_energy.dat"
done
gnuplot <<EOF
set terminal svg size 720,420 font "sans,13" background "white"
set output "$docs/figures/energy.svg"
set logscale y
set xlabel "wall-clock seconds (stage 0, then stage 1 after the 1-to-4 subdivision)"
set ylabel "total curvature energy E = sum (4H^2 - 2K) A"
set key top right
set grid
plot "$work/bilaplacian_energy.dat" with lines lw 2 lc rgb "#c0392b" title "bilaplacian (explicit)", \
     "$work/lmc_energy.dat" with lines lw 2 lc rgb "#2471a3" title "Laplacian of H (explicit)", \
     "$work/elastica_energy.dat" with lines lw 2 lc rgb "#1e8449" title "elastica (semi-implicit, flips)"
EOF

# ---------------------------------------------------------------- the page
row() {  # flow, stage → one table row from the stage's report
  local flow=$1 s=$2 j="$work/$1_$2.json"
  jq -r --arg flow "$flow" --arg scheme "${scheme_name[$flow]}" --arg s "$s" \
    '"| \($flow) | \($scheme) | \($s) | \(.input.vertices) | \(.steps) | \(.energy_initial * 10 | round / 10) | \(.energy_final * 10 | round / 10) | \(.seconds * 10 | round / 10) | \(.stop) |"' "$j"
}
r1() { jq -r "$1 * 10 | round / 10" "$2"; }  # a report value to one decimal
cage_energy=$(r1 .energy_initial "$work/elastica_0.json")
early_energy=$(r1 .energy_final "$work/elastica_early.json")
collapse_steps=$(jq -r '.steps' "$work/bilaplacian_collapse.json")
collapse_stop=$(jq -r '.stop' "$work/bilaplacian_collapse.json")
collapse_min=$(jq -r '[.energy_history[].energy] | min * 10 | round / 10' "$work/bilaplacian_collapse.json")
lmc_end=$(r1 .energy_final "$work/lmc_1.json")
bil_end=$(r1 .energy_final "$work/bilaplacian_1.json")
ela_0=$(r1 .energy_final "$work/elastica_0.json")
ela_1=$(r1 .energy_final "$work/elastica_1.json")
ela_stop0=$(jq -r .stop "$work/elastica_0.json")
ela_stop1=$(jq -r .stop "$work/elastica_1.json")
ela_seconds=$(jq -r -s '(.[0].seconds + .[1].seconds) * 10 | round / 10' "$work/elastica_0.json" "$work/elastica_1.json")
cage_vertices=$(jq -r '.input.vertices' "$work/elastica_0.json")
# The page's second section (bench/cage_figures.sh) is kept as it is.
cage_section=$(sed -n '/<!-- cage-figures:begin -->/,$p' "$docs/figures.md" 2>/dev/null || true)
{
  cat <<EOF
# The paper's Figs. 5–7 from real runs

Made by \`$command_line\` (the script writes this page and the pictures in \`docs/figures/\`;
every number below is read from the JSON reports of that run). Paper: Yoshizawa & Belyaev, *Fair
Triangle Mesh Generation with Discrete Elastica*, §3: the same tubular cage faired by the
bilaplacian flow (Fig. 5), the Laplacian-of-mean-curvature flow (Fig. 6) and the discrete elastica
flow (Fig. 7), combined with 1-to-4 subdivision, coloured by mean curvature.

**The cage**: \`elastica generate ${cage_args[*]}\` — a flat frame of square tubes one unit wide
around two square windows four units wide (genus 2), every unit square split into four triangles
around its centre and subdivided once: $cage_vertices vertices, E = $cage_energy. Each flow runs a stage
on the cage, then \`elastica subdivide\` (linear 1-to-4: no vertex moves), then a second stage on the
subdivided mesh. Rendering: \`bench/render_mesh.sh\` (f3d under xvfb-run) with the colour ramp that
\`elastica fair --color-by-mean-curvature\` writes (red: lowest H, blue: highest, 2–98 % percentiles
of each mesh, so colours are not comparable between pictures). Each figure: the cage, the end of
stage 0, the end of stage 1.

## Fig. 5 — bilaplacian flow (P ← P − τ U0²(P), explicit)

![bilaplacian flow](figures/fig_bilaplacian.png)

## Fig. 6 — Laplacian of mean curvature flow (F = −Δ_B H, explicit)

![Laplacian of mean curvature flow](figures/fig_lmc.png)

## Fig. 7 — discrete elastica flow (F = −Δ_B H − 2H(H² − K))

![discrete elastica flow](figures/fig_elastica.png)

## Energy against time

![energy versus time](figures/energy.svg)

| flow | scheme | stage | vertices | steps | E start | E end | seconds | stop |
|---|---|---|---|---|---|---|---|---|
EOF
  for flow in "${flows[@]}"; do row "$flow" 0; row "$flow" 1; done
  cat <<EOF

## What the figures show

- **Bilaplacian** (Fig. 5): the equal-weight bi-umbrella pulls every vertex toward its neighbours'
  average, so the tubes shrink and thin out; the dots along the tubes are the valence-4 vertices at
  the centres of the cage's squares (the flow depends on the connectivity, not only on the shape).
  It is not a descent of E: the energy falls while the square tubes round off and rises again as
  they thin. Left alone it does not stop at a shape: from the cage, E went down to $collapse_min and
  then up until the divergence guard (E above ten times its start) ended the run after
  $collapse_steps steps (\`$collapse_stop\`), hence the step budget above. Final E: $bil_end.
- **Laplacian of mean curvature** (Fig. 6): keeps the enclosed volume and evens out H, so the tubes
  become round but stay uneven, thicker where they meet and thinner along the straight runs: a
  flow heading for constant mean curvature rather than for low bending energy (run far longer, the
  middle bar thins to a neck that pinches, as constant-mean-curvature flows do). Its E levels off
  far above the elastica's (final $lmc_end); the explicit step (τ = A_min²/150) makes the fine
  stage slow, which is the paper's reason for coarse-to-fine.
- **Discrete elastica** (Fig. 7): the tubes round off first (second picture: $early_steps
  semi-implicit steps, E = $early_energy), then, because a round tube is not an elastica (a
  cylinder's speed points outward), they thicken and the windows close in toward the minimiser of
  the bending energy in genus 2, a Lawson-like surface with two small openings. E reaches
  $ela_0 on the cage's resolution and $ela_1 after the subdivision ($ela_seconds s in all; Lawson's
  genus-2 surface has E = 4W − 4πχ ≈ 112.8, with its Willmore energy W ≈ 21.9 as computed by
  Hsu, Kusner and Sullivan, and the discrete E underestimates at
  O(h²)). Its stages stopped with \`$ela_stop0\` and \`$ela_stop1\`
  (\`converged\`: the energy plateau). The paper's explicit scheme moves far more slowly (its
  step shrinks with the square of the smallest triangle's area: compare the Laplacian-of-H row),
  so the paper's pictures show earlier stages of the same flow.

Times are wall-clock seconds on a shared two-core machine: compare them within this page only.

Stage options: bilaplacian \`${stage_opts[bilaplacian]}\`; Laplacian of H \`${stage_opts[lmc]}\`;
elastica \`${stage_opts[elastica]}\`. "steps" counts attempts for the semi-implicit scheme (accepted
or rejected); "stop" is the report's reason (\`converged\`: the energy plateau; \`max_seconds\`,
\`max_steps\`: the budget).
EOF
  [[ -z "$cage_section" ]] || printf '\n%s\n' "$cage_section"
} >"$docs/figures.md"
log "wrote $docs/figures/ and $docs/figures.md (work files in $work)"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Elastica set-up from Debian packages only.
#
#   scripts/setup.sh            install missing binary packages, fetch MeshLab's source trees
#   scripts/setup.sh --check    only report what is missing (exit 1 if anything is)
#
# 1. Binary packages (apt-get) that the build, the tests and the MeshLab plugin need.
# 2. Real sample meshes from Debian's libcgal-demo package (downloaded, not installed; the list cgal_meshes).
# 3. Debian's `meshlab` *source* package, the same version as the installed `meshlab` binary (so the
#    plugin ABI matches), unpacked into a cache: it holds vcglib and MeshLab's plugin headers
#    (src/common). And Debian 13 (trixie)'s `meshlab` source package (MeshLab 2022.02), for the
#    compile check of the plugin's 2022 API. The machines have no deb-src lines, so we derive a
#    private apt configuration at run time from the system's own Debian sources (same mirrors, type
#    swapped to deb-src; for the second, the suite swapped to trixie) and use a private list
#    directory: the system's apt configuration is never touched, and no mirror host is written in
#    this repository.
#
# Idempotent: a second run finds everything in place and returns in well under a second.
# Cache location: $ELASTICA_CACHE_DIR, else ${XDG_CACHE_HOME:-$HOME/.cache}/elastica. CMake looks
# in the same place (cmake/FindMeshLabSource.cmake), or takes -DMESHLAB_SOURCE_DIR=/-DVCGLIB_DIR=
# (and -DMESHLAB_2022_SOURCE_DIR= for the 2022.02 tree).
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config dpkg-dev          # toolchain; dpkg-source unpacks the source package
  libeigen3-dev libcli11-dev nlohmann-json3-dev       # core numerics, CLI parsing, JSON reports
  libsuitesparse-dev                                   # CHOLMOD: large semi-implicit systems
  libtinyobjloader-dev                                 # OBJ reader (vcglib's is broken in this version)
  libgtest-dev libbenchmark-dev                        # tests and benchmarks
  meshlab qtbase5-dev libqt5opengl5-dev libglew-dev    # the MeshLab plugin and its integration tests
  xvfb xauth x11-utils                                 # headless MeshLab for the plugin tests (scripts/with-xvfb.sh: Xvfb, xdpyinfo)
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (python/) and its tests
  blender                                              # the Blender add-on's tests (blender_addon/; 690 MB with its libraries)
  clang                                                # libFuzzer targets (scripts/fuzz.sh)
  libclang-rt-14-dev                                   # libFuzzer and sanitizer runtimes for clang
  libtinyxml2-dev                                      # .mlx filter scripts (elastica run)
  xdotool                                              # the plugin's GUI test finds MeshLab's dialog
  imagemagick                                          # ... and screenshots it (import)
  f3d                                                  # headless renders for docs (bench/render_mesh.sh)
  gnuplot-nox jq                                       # energy curves from the JSON reports (bench/paper_figures.sh)
  time                                                 # /usr/bin/time -v: wall time and peak memory (bench/io_bench.sh)
  libcgal-dev                                          # CGAL's fill and fair() beside ours in bench/ (never linked by Elastica)
)

log() { printf 'setup: %s\n' "$*" >&2; }
die() { printf 'setup: error: %s\n' "$*" >&2; exit 1; }

check_only=0
case "${1:-}" in
  --check) check_only=1 ;;
  -h|--help) sed -n '3,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  "") ;;
  *) die "unknown option '$1' (try --help)" ;;
esac

command -v dpkg-query >/dev/null || die "this script needs a Debian system (dpkg-query not found)"

# ---------------------------------------------------------------- 1. binary packages
missing=()
for p in "${PACKAGES[@]}"; do
  [[ "$p" == \#* ]] && continue
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [[ "$status" == installed ]] || missing+=("$p")
done

as_root() {
  if [[ $(id -u) -eq 0 ]]; then "$@"
  elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then sudo "$@"
  else return 99
  fi
}

if ((${#missing[@]})); then
  if ((check_only)); then
    log "missing packages: ${missing[*]}"
    exit 1
  fi
  log "installing ${#missing[@]} Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  if ! as_root apt-get update -qq; then
    rc=$?
    ((rc == 99)) && die "packages missing (${missing[*]}) and this user cannot install them. Run as root, or:
    sudo apt-get install ${missing[*]}"
    die "apt-get update failed (exit $rc)"
  fi
  as_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || die "apt-get install failed for: ${missing[*]}"
fi

cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}

# ---------------------------------------------------------------- 2. real sample meshes
# Meshes from the data archive of Debian's libcgal-demo package (CGAL's own examples): an
# elephant (2,775 vertices, genus 3), the same elephant with 106 holes, whose borders pass twice
# through some vertices, and a closed scan of the Stanford bunny (bunny00.off, 37,706 vertices) for
# the scanner-style holes (tests/scanner_holes_test.cpp) and the many-holes benchmark
# (bench/scan_holes_bench), and two more scans for the hole-size sweep of docs/restoration.md
# (bench/restoration_sweep.sh): the armadillo (26,002 vertices) and a refined elephant (44,460);
# and four whole scans the default fair() is tested on (tests/real_shape_fairing_test.cpp): a cow
# (2,904 vertices), a dino (3,916), a bull (6,200) and a knotted tube, knot1 (3,200, genus 1); with
# the elephant (genus 3), a CAD part, joint (221, genus 2), and an elk (1,645, genus 1) for shapes
# with handles.
# The restoration tests and benchmarks use them. `apt-get download`
# fetches the package file without installing it (24 MB; no root needed once apt's lists exist).
cgal_meshes=(elephant.off elephant-with-holes.off bunny00.off armadillo.off refined_elephant.off cow.off dino.off bull.off knot1.off lion-head.off mannequin-devil.off joint.off elk.off)
fetch_cgal_meshes() {
  local candidate dir work deb m complete=1
  candidate=$(apt-cache policy libcgal-demo 2>/dev/null | awk '/Candidate:/ {print $2}')
  if [[ -z "$candidate" || "$candidate" == "(none)" ]]; then
    ((check_only)) && { log "apt's package lists do not know libcgal-demo (run apt-get update)"; exit 1; }
    as_root apt-get update -qq || die "apt-get update failed; cannot look up libcgal-demo"
    candidate=$(apt-cache policy libcgal-demo 2>/dev/null | awk '/Candidate:/ {print $2}')
  fi
  [[ -n "$candidate" && "$candidate" != "(none)" ]] || die "no libcgal-demo package in the configured Debian sources"
  dir="$cache/cgal-data-$candidate"
  for m in "${cgal_meshes[@]}"; do [[ -f "$dir/meshes/$m" ]] || complete=0; done
  if [[ -f "$dir/.elastica-complete" ]] && ((complete)); then
    log "sample meshes ready: $dir"
    return
  fi
  ((check_only)) && { log "sample meshes not fetched yet ($dir)"; exit 1; }
  work=$(mktemp -d "$cache/cgal-work.XXXXXX")
  log "fetching Debian's libcgal-demo $candidate for ${#cgal_meshes[@]} sample meshes (about 24 MB)"
  (cd "$work" && apt-get -o APT::Sandbox::User="$(id -un)" download -qq "libcgal-demo=$candidate") || die "could not download libcgal-demo=$candidate"
  deb=$(ls "$work"/libcgal-demo_*.deb | head -n1)
  rm -rf "$dir" && mkdir -p "$dir"
  dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/share/doc/libcgal-dev/data.tar.gz \
    | tar -xz -C "$dir" --strip-components=1 "${cgal_meshes[@]/#/data/meshes/}" \
    || die "libcgal-demo $candidate lacks one of data/meshes/{$(IFS=,; echo "${cgal_meshes[*]}")}"
  rm -rf "$work"
  touch "$dir/.elastica-complete"
  log "sample meshes ready: $dir"
}
mkdir -p "$cache"
fetch_cgal_meshes

# ---------------------------------------------------------------- 3. MeshLab source trees
# Debian source packages are fetched with a private apt state (source list, lists and archives in
# a work directory under the cache, removed afterwards): the system's apt configuration is never
# touched. The machines have no deb-src lines, so the source list is derived at run time from the
# system's own Debian sources (same mirrors and keys, type swapped to deb-src); no mirror host is
# written in this repository.
codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[[ -n "$codename" ]] || die "cannot tell the Debian release (no VERSION_CODENAME in /etc/os-release)"

# deb_src_list FILE [SUITE]: writes deb-src entries for the system's Debian sources of this release
# into FILE: its suites (codename, codename-updates, codename-security), or, with SUITE, only the
# release's main suite renamed SUITE (another Debian release on the same mirror). Entries of other
# suites (third-party repositories without source packages) are left out, so `apt-get update`
# does not fail on them.
deb_src_list() {
  local out=$1 to=${2:-} f
  : >"$out"
  for f in /etc/apt/sources.list.d/*.sources; do
    [[ -f "$f" ]] || continue
    # deb822 stanzas are separated by blank lines; keep the Debian ones, with Types: deb-src.
    awk -v cn="$codename" -v to="$to" '
      function flush() {
        if (uris != "" && keep) {
          n = split(suites, s, " "); nu = split(uris, u, " ")
          for (i = 1; i <= n; i++) if (s[i] == cn || (to == "" && index(s[i], cn "-") == 1))
            for (j = 1; j <= nu; j++)
              print "deb-src" (signed != "" ? " [signed-by=" signed "]" : "") " " u[j] " " (to != "" ? to : s[i]) " " comps
        }
        uris = ""; suites = ""; comps = ""; signed = ""; keep = 0
      }
      /^[ \t]*$/ { flush(); next }
      /^#/ { next }
      /^Types:/ { keep = ($0 ~ /(^|[ \t])deb([ \t]|$)/) }
      /^URIs:/ { sub(/^URIs:[ \t]*/, ""); uris = $0 }
      /^Suites:/ { sub(/^Suites:[ \t]*/, ""); suites = $0 }
      /^Components:/ { sub(/^Components:[ \t]*/, ""); comps = $0 }
      /^Signed-By:/ { sub(/^Signed-By:[ \t]*/, ""); signed = $0 }
      END { flush() }' "$f" >>"$out"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -f "$f" ]] || continue
    # one-line format: deb [options] URI suite components...
    awk -v cn="$codename" -v to="$to" '$1 == "deb" {
        i = 2; opts = ""; if ($2 ~ /^\[/) { while ($i !~ /\]$/) { opts = opts $i " "; i++ } opts = opts $i " "; i++ }
        if ($(i+1) == cn || (to == "" && index($(i+1), cn "-") == 1)) { $1 = "deb-src"; if (to != "") $(i+1) = to; print }
      }' "$f" >>"$out"
  done
  [[ -s "$out" ]] || die "no Debian '$codename' entries found in /etc/apt/sources.list{,.d} to derive deb-src from"
}

# apt_state WORK [SUITE]: a private apt state in WORK for deb_src_list's entries, updated; sets apt_opts.
apt_state() {
  local work=$1
  rm -rf "$work"
  mkdir -p "$work/lists/partial" "$work/archives/partial"
  deb_src_list "$work/sources.list" "${2:-}"
  apt_opts=(
    -o Dir::Etc::SourceList="$work/sources.list" -o Dir::Etc::SourceParts=/dev/null
    -o Dir::State::Lists="$work/lists" -o Dir::Cache::Archives="$work/archives"
    -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
    -o APT::Sandbox::User="$(id -un)" -o Debug::NoLocking=1
  )
  apt-get "${apt_opts[@]}" -qq update || die "apt-get update of the derived deb-src lists ($work/sources.list) failed"
}

# fetch_source PACKAGE VERSION TREE WORK: Debian's source package PACKAGE=VERSION unpacked into TREE
# with apt_state's state in WORK: `apt-get source --download-only` and dpkg-source (Debian's
# patches applied; apt has verified the files against the signed indices). A mirror that serves the
# package only in part (this one answers 404 for trixie's meshlab .dsc and Debian patch tarball,
# yet serves its upstream tarball) leaves the upstream tarball the signed Sources index lists:
# fetched by apt-helper, which checks its SHA-256, and unpacked without Debian's patches.
# TREE/.elastica-origin says which.
fetch_source() {
  local package=$1 version=$2 tree=$3 work=$4 dsc uri file size hash
  rm -rf "$tree" "$work/download" && mkdir -p "$work/download"
  if (cd "$work/download" && apt-get "${apt_opts[@]}" -qq source --download-only "$package=$version") 2>"$work/source.err"; then
    dsc=$(ls "$work"/download/*.dsc 2>/dev/null | head -n1)
    [[ -n "$dsc" ]] || die "no .dsc file was downloaded for $package=$version"
    dpkg-source --no-check -x "$dsc" "$tree" >/dev/null || die "dpkg-source could not unpack $dsc"
    echo "Debian source package $package $version, unpacked by dpkg-source (Debian's patches applied)" >"$tree/.elastica-origin"
  else
    log "apt-get source $package=$version failed ($(grep -m1 '^E:' "$work/source.err" || tail -n1 "$work/source.err")); taking its upstream tarball from the signed Sources index"
    rm -rf "$work/download" && mkdir -p "$work/download"
    read -r uri file size hash < <(cd "$work/download" && apt-get "${apt_opts[@]}" -qq --print-uris source "$package=$version" |
                                   awk '$2 ~ /\.orig\.tar\./') || die "the Sources index lists no upstream tarball for $package=$version"
    uri=${uri//\'/}
    /usr/lib/apt/apt-helper "${apt_opts[@]}" download-file "$uri" "$work/download/$file" "$hash" >/dev/null 2>"$work/source.err" ||
      die "could not download $file ($(tail -n1 "$work/source.err"))"
    mkdir -p "$tree"
    tar -xf "$work/download/$file" -C "$tree" --strip-components=1 || die "could not unpack $file"
    echo "upstream tarball $file of Debian's $package $version ($size bytes, $hash as the signed Sources index lists; Debian's patches not applied: the mirror did not serve the .dsc)" >"$tree/.elastica-origin"
  fi
}

# 3a. The installed MeshLab's source (2020.09 on Debian 12): vcglib and the plugin headers the
# plugin is built and run-tested with.
version=$(dpkg-query -W -f='${Version}' meshlab 2>/dev/null || true)
[[ -n "$version" ]] || die "the meshlab package is not installed"
tree="$cache/meshlab-src-$version"
if [[ -f "$tree/.elastica-complete" ]]; then
  log "MeshLab $version source tree ready: $tree"
else
  ((check_only)) && { log "MeshLab source tree not fetched yet ($tree)"; exit 1; }
  command -v dpkg-source >/dev/null || die "dpkg-source not found (package dpkg-dev)"
  log "fetching Debian's meshlab $version source package (about 12 MB) with a private apt state"
  apt_state "$cache/apt-work"
  fetch_source meshlab "$version" "$tree" "$cache/apt-work"
  [[ -f "$tree/vcglib/vcg/complex/complex.h" && -f "$tree/src/common/interfaces.h" ]] \
    || die "unpacked tree $tree lacks vcglib/ or src/common/"
  touch "$tree/.elastica-complete"
  # dpkg-source leaves a copy of the upstream tarball beside the tree it unpacked.
  rm -rf "$cache/apt-work" "$cache"/meshlab_*.orig.tar.*
  log "MeshLab $version source tree ready: $tree"
fi

# 3b. MeshLab 2022.02, Debian 13 (trixie)'s: its source package from the trixie suite of the same
# mirror, for the compile check of the plugin's 2022 API (ctest plugin_meshlab2022_compile). Debian
# 12 cannot install that MeshLab, so it is not run. Cached: once unpacked, no network.
trixie_tree=$(ls -d "$cache"/meshlab-trixie-src-2022.02*/.elastica-complete 2>/dev/null | tail -n1 || true)
if [[ -n "$trixie_tree" ]]; then
  log "MeshLab 2022.02 (Debian 13) source tree ready: ${trixie_tree%/.elastica-complete}"
else
  ((check_only)) && { log "MeshLab 2022.02 (Debian 13) source tree not fetched yet ($cache/meshlab-trixie-src-2022.02*)"; exit 1; }
  log "fetching Debian 13 (trixie)'s meshlab 2022.02 source package (about 7 MB) with a private apt state"
  apt_state "$cache/apt-work-trixie" trixie
  trixie_version=$(apt-cache "${apt_opts[@]}" showsrc meshlab 2>/dev/null | awk '/^Version: 2022\.02/ {print $2}' | sort -V | tail -n1)
  [[ -n "$trixie_version" ]] || die "Debian's trixie suite has no meshlab 2022.02 source package"
  tree="$cache/meshlab-trixie-src-$trixie_version"
  fetch_source meshlab "$trixie_version" "$tree" "$cache/apt-work-trixie"
  [[ -f "$tree/src/vcglib/vcg/complex/complex.h" && -f "$tree/src/common/plugins/interfaces/filter_plugin.h" ]] \
    || die "unpacked tree $tree lacks src/vcglib/ or src/common/plugins/interfaces/filter_plugin.h"
  touch "$tree/.elastica-complete"
  rm -rf "$cache/apt-work-trixie" "$cache"/meshlab_*.orig.tar.*
  log "MeshLab $trixie_version (Debian 13) source tree ready: $tree ($(cat "$tree/.elastica-origin"))"
fi

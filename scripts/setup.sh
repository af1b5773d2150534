#!/usr/bin/env bash
# Elastica set-up from Debian packages only.
#
#   scripts/setup.sh            install missing binary packages, fetch MeshLab's source tree
#   scripts/setup.sh --check    only report what is missing (exit 1 if anything is)
#
# 1. Binary packages (apt-get) that the build, the tests and the MeshLab plugin need.
# 2. Three real sample meshes from Debian's libcgal-demo package (downloaded, not installed).
# 3. Debian's `meshlab` *source* package, the same version as the installed `meshlab` binary (so the
#    plugin ABI matches), unpacked into a cache: it holds vcglib and MeshLab's plugin headers
#    (src/common). The machines have no deb-src lines, so we derive a private apt configuration at
#    run time from the system's own Debian sources (same mirrors, type swapped to deb-src) and use
#    a private list directory: the system's apt configuration is never touched, and no mirror host
#    is written in this repository.
#
# Idempotent: a second run finds everything in place and returns in well under a second.
# Cache location: $ELASTICA_CACHE_DIR, else ${XDG_CACHE_HOME:-$HOME/.cache}/elastica. CMake looks
# in the same place (cmake/FindMeshLabSource.cmake), or takes -DMESHLAB_SOURCE_DIR=/-DVCGLIB_DIR=.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config dpkg-dev          # toolchain; dpkg-source unpacks the source package
  libeigen3-dev libcli11-dev nlohmann-json3-dev       # core numerics, CLI parsing, JSON reports
  libsuitesparse-dev                                   # CHOLMOD: large semi-implicit systems
  libopenblas0-serial                                  # optimised BLAS for CHOLMOD's supernodes (serial: no extra threads)
  libtinyobjloader-dev                                 # OBJ reader (vcglib's is broken in this version)
  libgtest-dev libbenchmark-dev                        # tests and benchmarks
  meshlab qtbase5-dev libqt5opengl5-dev libglew-dev    # the MeshLab plugin and its integration tests
  xvfb xauth                                           # headless MeshLab for the plugin tests
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
)

log() { printf 'setup: %s\n' "$*" >&2; }
die() { printf 'setup: error: %s\n' "$*" >&2; exit 1; }

check_only=0
case "${1:-}" in
  --check) check_only=1 ;;
  -h|--help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
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
# (bench/scan_holes_bench). The restoration tests and benchmarks use them. `apt-get download`
# fetches the package file without installing it (24 MB; no root needed once apt's lists exist).
cgal_meshes=(elephant.off elephant-with-holes.off bunny00.off)
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

# ---------------------------------------------------------------- 3. MeshLab source tree
version=$(dpkg-query -W -f='${Version}' meshlab 2>/dev/null || true)
[[ -n "$version" ]] || die "the meshlab package is not installed"
tree="$cache/meshlab-src-$version"
stamp="$tree/.elastica-complete"

if [[ -f "$stamp" ]]; then
  log "MeshLab $version source tree ready: $tree"
  exit 0
fi
((check_only)) && { log "MeshLab source tree not fetched yet ($tree)"; exit 1; }

command -v dpkg-source >/dev/null || die "dpkg-source not found (package dpkg-dev)"
work="$cache/apt-work"
rm -rf "$work" "$tree"
mkdir -p "$work/lists/partial" "$work/archives/partial" "$work/download"

# Derive deb-src entries from the system's Debian sources. Only entries whose suite is this
# release's codename (or codename-updates/-security) are kept, so third-party repositories
# without source packages do not make `apt-get update` fail.
codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[[ -n "$codename" ]] || die "cannot tell the Debian release (no VERSION_CODENAME in /etc/os-release)"
src_list="$work/sources.list"
: >"$src_list"
for f in /etc/apt/sources.list.d/*.sources; do
  [[ -f "$f" ]] || continue
  # deb822 stanzas are separated by blank lines; keep the Debian ones, with Types: deb-src.
  awk -v cn="$codename" '
    function flush() {
      if (uris != "" && keep) {
        n = split(suites, s, " "); nu = split(uris, u, " ")
        for (i = 1; i <= n; i++) if (s[i] == cn || index(s[i], cn "-") == 1)
          for (j = 1; j <= nu; j++)
            print "deb-src" (signed != "" ? " [signed-by=" signed "]" : "") " " u[j] " " s[i] " " comps
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
    END { flush() }' "$f" >>"$src_list"
done
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [[ -f "$f" ]] || continue
  # one-line format: deb [options] URI suite components...
  awk -v cn="$codename" '$1 == "deb" {
      i = 2; opts = ""; if ($2 ~ /^\[/) { while ($i !~ /\]$/) { opts = opts $i " "; i++ } opts = opts $i " "; i++ }
      if ($(i+1) == cn || index($(i+1), cn "-") == 1) { $1 = "deb-src"; print }
    }' "$f" >>"$src_list"
done
[[ -s "$src_list" ]] || die "no Debian '$codename' entries found in /etc/apt/sources.list{,.d} to derive deb-src from"

apt_opts=(
  -o Dir::Etc::SourceList="$src_list" -o Dir::Etc::SourceParts=/dev/null
  -o Dir::State::Lists="$work/lists" -o Dir::Cache::Archives="$work/archives"
  -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
  -o APT::Sandbox::User="$(id -un)" -o Debug::NoLocking=1
)
log "fetching Debian's meshlab $version source package (about 12 MB) with a private apt state"
apt-get "${apt_opts[@]}" -qq update || die "apt-get update of the derived deb-src lists failed"
(cd "$work/download" && apt-get "${apt_opts[@]}" -qq source --download-only "meshlab=$version") \
  || die "could not download the meshlab=$version source package"
dsc=$(ls "$work"/download/*.dsc 2>/dev/null | head -n1)
[[ -n "$dsc" ]] || die "no .dsc file was downloaded"
# dpkg-source applies Debian's patches; apt has already verified the files against signed indices.
dpkg-source --no-check -x "$dsc" "$tree" >/dev/null || die "dpkg-source could not unpack $dsc"
[[ -f "$tree/vcglib/vcg/complex/complex.h" && -f "$tree/src/common/interfaces.h" ]] \
  || die "unpacked tree $tree lacks vcglib/ or src/common/"
touch "$stamp"
# dpkg-source leaves a copy of the upstream tarball beside the tree it unpacked.
rm -rf "$work" "$cache"/meshlab_*.orig.tar.*
log "MeshLab $version source tree ready: $tree"

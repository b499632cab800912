#!/usr/bin/env bash
# Fetches Debian unstable's libcgal-dev (CGAL 6.x, header-only, with Polygon_mesh_processing::kernel)
# for kergen_bench's optional CGAL 6.2 column, without installing it: the package lists of
# unstable go to a private folder (the system's apt sources and lists are not touched), the .deb
# is downloaded with `apt-get download` and unpacked with `dpkg-deb -x`. The system keeps its own
# CGAL (5.5 on bookworm) for the oracle tests.
#   bash bench/get-cgal62.sh [DEST]      DEST defaults to ~/.cache/kergen/cgal-6.2
# Then: cmake -S . -B build -DKERGEN_CGAL62_DIR=DEST/usr && cmake --build build --target kergen_bench
set -euo pipefail
dest="${1:-$HOME/.cache/kergen/cgal-6.2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/lists/partial" "$work/archives/partial" "$dest"
printf 'deb http://deb.debian.org/debian unstable main\n' >"$work/sources.list"
apt_opts=(-o "Dir::Etc::SourceList=$work/sources.list" -o "Dir::Etc::SourceParts=/dev/null"
  -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work" -o "Dir::Cache::archives=$work/archives"
  -o "APT::Get::List-Cleanup=0" -o "Acquire::Languages=none" -o "APT::Sandbox::User=root")
apt-get "${apt_opts[@]}" update -qq
version="$(apt-cache "${apt_opts[@]}" policy libcgal-dev | awk '/Candidate:/ {print $2}')"
case "$version" in
  6.*) ;;
  *) echo "get-cgal62: unstable offers libcgal-dev '$version', not 6.x" >&2; exit 1 ;;
esac
(cd "$work" && apt-get "${apt_opts[@]}" download "libcgal-dev=$version")
dpkg-deb -x "$work"/libcgal-dev_*.deb "$dest"
test -f "$dest/usr/include/CGAL/Polygon_mesh_processing/kernel.h" ||
  { echo "get-cgal62: libcgal-dev $version has no Polygon_mesh_processing/kernel.h" >&2; exit 1; }
echo "CGAL $version unpacked into $dest (pass -DKERGEN_CGAL62_DIR=$dest/usr to cmake)"

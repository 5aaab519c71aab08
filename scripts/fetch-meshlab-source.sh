#!/usr/bin/env bash
# Fetches the source of the installed Debian `meshlab` package and unpacks it into DEST/source.
# The MeshLab plugin compiles against its src/common headers and the vcglib it bundles: Debian's
# MeshLab ships no headers. Nothing fetched here is part of this repository.
#
# Usage: scripts/fetch-meshlab-source.sh DEST      (CMake runs it with DEST = BUILD/meshlab-src)
#
# The download uses a temporary apt configuration of its own: a sources list holding one deb-src
# entry (the mirror and suite the installed meshlab came from, as `apt-cache madison` reports
# them), its own lists and cache folders. The system's apt sources, lists and cache are left as
# they are. apt checks the files against the mirror's signed Release file.
# Needs the `meshlab` and `dpkg-dev` packages (scripts/install-deps.sh) and network access to a
# Debian mirror; runs as any user. Idempotent: a DEST that already holds the source of the
# installed version is kept, and nothing is downloaded. Prints the unpacked tree on stdout.
set -euo pipefail

dest=${1:?usage: fetch-meshlab-source.sh DEST}
say() { echo "fetch-meshlab-source: $*" >&2; }

version=$(dpkg-query -W -f='${Version}' meshlab 2>/dev/null) || true
if [ -z "$version" ]; then
  say "the meshlab package is not installed"
  exit 1
fi
mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
tree="$dest/source"
stamp="$dest/fetched-version"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$version" ] && [ -f "$tree/src/common/interfaces.h" ]; then
  echo "$tree"
  exit 0
fi
for tool in apt-get dpkg-source; do
  if ! command -v "$tool" >/dev/null; then
    say "$tool is missing (install dpkg-dev)"
    exit 1
  fi
done

# Where the installed version came from: "meshlab | VERSION | URI SUITE/COMPONENT ARCH Packages".
origin=$(apt-cache madison meshlab 2>/dev/null | awk -F' [|] ' -v v="$version" '$2 == v { print $3; exit }')
if [ -n "$origin" ]; then
  read -r uri dist _ <<<"$origin"
  suite=${dist%/*}
  component=${dist#*/}
else
  # No package lists to ask: Debian's main mirror, this release.
  uri=http://deb.debian.org/debian
  suite=$(. /etc/os-release && echo "$VERSION_CODENAME")
  component=main
fi
keyring=/usr/share/keyrings/debian-archive-keyring.gpg

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/lists/partial" "$work/cache/archives/partial" "$work/sources.list.d" "$work/download"
echo "deb-src [signed-by=$keyring] $uri $suite $component" >"$work/sources.list"
apt_options=(
  -o "Dir::Etc::SourceList=$work/sources.list"
  -o "Dir::Etc::SourceParts=$work/sources.list.d"
  -o "Dir::State::Lists=$work/lists"
  -o "Dir::Cache=$work/cache"
  -o "Acquire::Languages=none"
)
# As root, apt would hand the download to its unprivileged _apt user, who cannot enter the
# private temporary folder; the files are checked against the signed index all the same.
if [ "$(id -u)" -eq 0 ]; then
  apt_options+=(-o "APT::Sandbox::User=root")
fi

say "meshlab $version from $uri $suite $component"
apt-get "${apt_options[@]}" -q update >&2
(cd "$work/download" && apt-get "${apt_options[@]}" -q source --download-only "meshlab=$version" >&2)
dsc=$(ls "$work/download"/meshlab_*.dsc)
rm -rf "$tree" "$dest/source.partial"
# --no-check: the .dsc's own signature needs the uploaders' keyring; apt has already verified
# every file against the mirror's signed index.
dpkg-source --no-check --no-copy -x "$dsc" "$dest/source.partial" >&2
mv "$dest/source.partial" "$tree"
echo "$version" >"$stamp"
say "unpacked into $tree"
echo "$tree"

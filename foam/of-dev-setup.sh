#!/bin/bash
# Make an OpenFOAM v1912 development tree (headers as lnInclude folders, wmake, etc/bashrc) that
# matches Debian's openfoam/libopenfoam packages, which ship neither headers nor wmake.
#
#   foam/of-dev-setup.sh [DEST]        default DEST: $OF_DEV_DIR or /opt/of/OpenFOAM-v1912
#
# Steps (about 60 s on 2 cores when the tarball is cached, plus the download the first time):
#   1. the upstream orig tarball of the installed source version (openfoam_1912.200626.orig.tar.bz2,
#      45 MB) is taken from $OF_TARBALL, or from the cache next to DEST, or fetched with
#      `apt-get source --download-only`. deb-src is enabled only for that call, through a private
#      sources file and state dir under <cache>/apt: the system's apt configuration is not touched.
#   2. META-INFO, bin, etc, wmake and src are extracted into DEST; wmake's tools are built and
#      every src/ folder gets its lnInclude (plus the header-only TurbulenceModels folders).
# DEST is built under DEST.partial and renamed at the end, so an interrupted run leaves nothing
# that looks complete; a complete tree is marked with DEST/.of-dev-setup-done and skipped.
# Then, in each shell: export USER=$(id -un); source DEST/etc/bashrc
set -euo pipefail

DEST=${1:-${OF_DEV_DIR:-/opt/of/OpenFOAM-v1912}}
CACHE=$(dirname "$DEST")
STAMP=$DEST/.of-dev-setup-done
P=openfoam-OpenFOAM-v1912.200626          # top folder inside the orig tarball

if [ -f "$STAMP" ]; then
    echo "of-dev-setup: $DEST is ready"
    exit 0
fi
t0=$(date +%s.%N)
mkdir -p "$CACHE"

# --- 1. the orig tarball ---------------------------------------------------------------------
# The source version of the installed package (1912.200626-1 for 1912.200626-1+b1).
SRCVER=$(dpkg-query -W -f='${source:Version}' libopenfoam 2>/dev/null || true)
UPVER=${SRCVER%-*}                        # 1912.200626
TARBALL=${OF_TARBALL:-}
if [ -z "$TARBALL" ]; then
    if [ -n "$UPVER" ] && [ -f "$CACHE/openfoam_$UPVER.orig.tar.bz2" ]; then
        TARBALL=$CACHE/openfoam_$UPVER.orig.tar.bz2
    else
        TARBALL=$(ls "$CACHE"/openfoam_*.orig.tar.bz2 2>/dev/null | head -1 || true)
    fi
fi
if [ -z "$TARBALL" ]; then
    [ -n "$SRCVER" ] || { echo "of-dev-setup: libopenfoam is not installed (apt-get install openfoam libopenfoam)" >&2; exit 1; }
    # The Debian mirror the system uses (first non-security deb line), and its release.
    MIRROR=$(grep -hE '^(URIs:|deb )' /etc/apt/sources.list /etc/apt/sources.list.d/*.list \
                 /etc/apt/sources.list.d/*.sources 2>/dev/null |
             grep -v security | grep -oE 'https?://[^ ]*/debian/?( |$)' | head -1 | tr -d ' ' || true)
    MIRROR=${MIRROR:-http://deb.debian.org/debian}
    SUITE=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
    A=$CACHE/apt
    mkdir -p "$A/sources.list.d" "$A/lists/partial" "$A/cache/archives/partial"
    cat > "$A/sources.list.d/openfoam-src.sources" <<EOF
Types: deb-src
URIs: $MIRROR
Suites: $SUITE $SUITE-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
    APTOPT=(-o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$A/sources.list.d"
            -o Dir::State::Lists="$A/lists" -o Dir::Cache="$A/cache"
            -o APT::Sandbox::User=root -qq)
    echo "of-dev-setup: fetching the openfoam $SRCVER source from $MIRROR ($SUITE, deb-src)"
    apt-get "${APTOPT[@]}" update
    mkdir -p "$A/dl"                      # complete downloads only reach the cache
    ( cd "$A/dl" && { apt-get "${APTOPT[@]}" source --download-only "openfoam=$SRCVER" ||
                      apt-get "${APTOPT[@]}" source --download-only openfoam; } )
    for f in "$A"/dl/openfoam_*.orig.tar.bz2; do mv "$f" "$CACHE/"; TARBALL=$CACHE/${f##*/}; done
    rm -rf "$A"                           # keep only the tarball
fi
[ -f "$TARBALL" ] || { echo "of-dev-setup: no tarball $TARBALL" >&2; exit 1; }
t1=$(date +%s.%N)

# --- 2. extract and prepare ------------------------------------------------------------------
WORK=$DEST.partial
rm -rf "$WORK"
mkdir -p "$WORK"
tar xjf "$TARBALL" -C "$WORK" --strip-components=1 \
    "$P/META-INFO" "$P/bin" "$P/etc" "$P/wmake" "$P/src"
# The bashrc takes WM_PROJECT_DIR from its own location, so build in place under the final name.
rm -rf "$DEST"
mv "$WORK" "$DEST"
t2=$(date +%s.%N)

export USER=${USER:-$(id -un)}
set +eu                                   # OpenFOAM's bashrc fails under `set -u`
# shellcheck disable=SC1091
source "$DEST/etc/bashrc"
set -eu
[ "${WM_PROJECT_DIR:-}" = "$DEST" ] || { echo "of-dev-setup: sourcing $DEST/etc/bashrc failed" >&2; exit 1; }
( cd "$WM_DIR/src" && ./Allmake > "$DEST/log.wmake-tools" 2>&1 ) ||
    { tail "$DEST/log.wmake-tools" >&2; echo "of-dev-setup: building wmake's tools failed" >&2; exit 1; }
# Serially: v1912's `wmakeLnIncludeAll -j` starts its jobs inside a pipeline's subshell, so its
# final `wait` does not wait for them and it can return while links are still being made (a
# fresh machine then failed to find fvMesh.H). Serial takes about 50 s, no slower on 2 cores.
wmakeLnIncludeAll "$FOAM_SRC" > "$DEST/log.lnInclude" 2>&1
for d in TurbulenceModels/phaseIncompressible TurbulenceModels/phaseCompressible; do
    if [ -d "$FOAM_SRC/$d" ]; then wmakeLnInclude -u "$FOAM_SRC/$d" >> "$DEST/log.lnInclude" 2>&1; fi
done
[ -e "$FOAM_SRC/finiteVolume/lnInclude/fvCFD.H" ] ||
    { echo "of-dev-setup: lnInclude folders incomplete (see $DEST/log.lnInclude)" >&2; exit 1; }
touch "$STAMP"
t3=$(date +%s.%N)
awk -v d="$DEST" -v a="$t0" -v b="$t1" -v c="$t2" -v e="$t3" 'BEGIN { printf \
    "of-dev-setup: %s ready (fetch %.1f s, extract %.1f s, wmake tools + lnInclude %.1f s)\n", d, b - a, c - b, e - c }'

#!/usr/bin/env bash
# Installs ensil's .deb into this system with apt-get, checks what it installed, runs the
# installed binary (`ensil --version`, a headless `ensil render` and the workbench window on a
# virtual display), and removes the package again, also when a check fails. Run as root (or with
# sudo available).
#   packaging/test-package.sh DEB
set -euo pipefail
cd "$(dirname "$0")/.."

if [ $# -ne 1 ] || [ ! -f "$1" ]; then
    echo "usage: packaging/test-package.sh path/to/ensil_VERSION_ARCH.deb" >&2
    exit 2
fi
deb=$(realpath "$1")
checks=$PWD/packaging/package_checks.py
app_id=io.github.ensil.ensil
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

step() { echo "test-package: $*"; }
fail() { echo "test-package: FAILED: $*" >&2; exit 1; }

# --- The package file ---------------------------------------------------------------------
version=$(dpkg-deb --field "$deb" Version)
depends=$(dpkg-deb --field "$deb" Depends)
step "ensil $version, $(du -k "$deb" | cut -f1) KiB; Depends: $depends"
# dpkg-shlibdeps found the linked libraries; the rest is declared by hand (debian/cpack.cmake).
for needed in libqt6gui6 libqt6svg6 libgl1-mesa-dri libegl-mesa0 python3-numpy; do
    grep -qE "(^|, )$needed( |,|$)" <<<"$depends" || fail "Depends lacks $needed"
done
contents=$(dpkg-deb --contents "$deb" | awk '{print $6}')
for path in ./usr/bin/ensil \
            ./usr/share/applications/$app_id.desktop \
            ./usr/share/metainfo/$app_id.metainfo.xml \
            ./usr/share/mime/packages/$app_id.xml \
            ./usr/share/icons/hicolor/scalable/apps/$app_id.svg \
            ./usr/share/icons/hicolor/48x48/apps/$app_id.png \
            ./usr/share/icons/hicolor/256x256/apps/$app_id.png \
            ./usr/share/doc/ensil/copyright \
            ./usr/share/doc/ensil/LICENSE \
            ./usr/share/man/man1/ensil.1.gz \
            ./usr/share/man/man1/ensil-render.1.gz \
            ./usr/share/man/man1/ensil-section.1.gz \
            ./usr/share/bash-completion/completions/ensil \
            ./usr/share/zsh/vendor-completions/_ensil \
            ./usr/lib/python3/dist-packages/ensil/__init__.py \
            ./usr/lib/python3/dist-packages/ensil/__init__.pyi; do
    grep -qxF "$path" <<<"$contents" || fail "the package does not hold $path"
done

# On a fresh Debian 12 (simulated: apt with an empty package status), apt-get can resolve every
# dependency of the package from the archive.
if ! ls /var/lib/apt/lists/*_Packages >/dev/null 2>&1; then
    $SUDO apt-get update -qq
fi
fresh_status=$(mktemp)
simulation=$(apt-get -o Dir::State::status="$fresh_status" install --simulate \
                 --no-install-recommends "$deb" 2>&1) || fail "on a fresh system: $simulation"
rm -f "$fresh_status"
grep -q '^Inst ensil ' <<<"$simulation" || fail "apt-get would not install ensil: $simulation"
step "on a fresh system apt-get would install $(grep -c '^Inst ' <<<"$simulation") packages" \
     "(ensil included)"

# --- Install ----------------------------------------------------------------------------------
remove_package() {
    if dpkg-query -W -f='${Status}' ensil 2>/dev/null | grep -q "install ok installed"; then
        step "removing the package"
        DEBIAN_FRONTEND=noninteractive $SUDO apt-get purge -y -qq ensil >/dev/null
    fi
}
remove_package  # a leftover of the same version would make apt-get skip the install
trap remove_package EXIT
step "apt-get install $deb"
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$deb" \
    >/dev/null
[ "$(command -v ensil)" = /usr/bin/ensil ] ||
    fail "ensil on PATH is $(command -v ensil), not /usr/bin/ensil"

# Every shared library the installed binary loads must come from a package that ensil's
# dependencies pull in; that is what makes `apt-get install ./ensil_*.deb` enough on a fresh system.
step "checking that the dependencies cover every library /usr/bin/ensil and the Python module load"
closure=$(apt-cache depends --recurse --installed --no-recommends --no-suggests --no-conflicts \
              --no-breaks --no-replaces --no-enhances ensil | grep -v '^ ' | tr -d '<>' | sort -u)
module=$(ls /usr/lib/python3/dist-packages/ensil/_ensil.*.so)
libraries=$(ldd /usr/bin/ensil "$module" | awk '$2 == "=>" && $3 ~ /^\// {print $3}' | sort -u)
[ -n "$libraries" ] || fail "ldd found no libraries for /usr/bin/ensil"
for library in $libraries; do
    real=$(realpath "$library")
    # usrmerge: dpkg may know the file under /lib or /usr/lib.
    owner=$(dpkg-query --search "$real" "${real#/usr}" 2>/dev/null | head -1 | cut -d: -f1) \
        || true
    [ -n "$owner" ] || fail "no package owns $library"
    grep -qxF "$owner" <<<"$closure" ||
        fail "$library comes from $owner, which ensil's Depends do not pull in"
done

# --- The installed files ------------------------------------------------------------------
# The licence, in Debian's machine-readable form and as the repository's text.
grep -qx 'License: BSD-3-Clause' /usr/share/doc/ensil/copyright ||
    fail "/usr/share/doc/ensil/copyright does not license the files under BSD-3-Clause"
grep -qx 'BSD 3-Clause License' /usr/share/doc/ensil/LICENSE ||
    fail "/usr/share/doc/ensil/LICENSE is not the BSD 3-Clause licence"
installed_version=$(/usr/bin/ensil --version)
step "/usr/bin/ensil --version: $installed_version"
grep -qF "${version%%-*}" <<<"$installed_version" || fail "ensil --version does not say $version"
desktop-file-validate /usr/share/applications/$app_id.desktop
appstreamcli validate --no-net /usr/share/metainfo/$app_id.metainfo.xml
# The shared-mime-info trigger has compiled the package's MIME type into the system database.
python3 "$checks" mime-glob /usr/share/mime '*.ensil' application/x-ensil-project

# The Python module imports from the installed package with Debian's interpreter, outside the
# source tree, and its engine reads the demo.
# No bytecode is written, so that apt-get purge leaves no folder behind.
step "python3 -c 'import ensil'"
(cd / && PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c \
    "import ensil; e = ensil.demo(members=2); print(ensil.__file__, e)") ||
    fail "the installed Python module does not import"

# --- A headless render from the installed binary -------------------------------------------
work=$(mktemp -d)
trap 'rm -rf "$work"; remove_package' EXIT
step "xvfb-run ensil render --demo"
# A private HOME keeps the mesh cache out of the user's.
HOME=$work XDG_RUNTIME_DIR=$work xvfb-run -a -s "-screen 0 1280x1024x24" \
    /usr/bin/ensil render --demo --iso 30 --size 320x240 --out "$work/demo.png"
# The demo's silhouettes cover a good part of the frame in several cluster colours.
python3 "$checks" png "$work/demo.png" --size 320x240 --min-covered 0.05 --min-colours 50
# And on a batch node with no display server at all: Mesa's EGL surfaceless platform.
step "ensil render --demo with no display server"
env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM HOME=$work XDG_RUNTIME_DIR=$work \
    /usr/bin/ensil render --demo --iso 30 --size 320x240 --out "$work/batch.png"
python3 "$checks" png "$work/batch.png" --size 320x240 --min-covered 0.05 --min-colours 50
# A section needs no display server either: Qt's offscreen platform, with the installed fonts.
step "ensil section --demo with no display server"
env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM HOME=$work XDG_RUNTIME_DIR=$work \
    /usr/bin/ensil section --demo --level 250hPa --size 640x360 --out "$work/section.png"
python3 "$checks" png "$work/section.png" --size 640x360 --min-covered 0.05 --min-colours 50
# The workbench window shows the icon: the embedded SVG renders with the installed Qt plugins.
xvfb-run -a -s "-screen 0 1600x1000x24" packaging/window-icon-check.sh /usr/bin/ensil

remove_package
trap 'rm -rf "$work"' EXIT
[ ! -e /usr/bin/ensil ] || fail "/usr/bin/ensil is still there after apt-get purge"
[ ! -e /usr/lib/python3/dist-packages/ensil ] ||
    fail "the Python module is still there after apt-get purge"
if python3 "$checks" mime-glob /usr/share/mime '*.ensil' application/x-ensil-project \
        >/dev/null 2>&1; then
    fail "*.ensil is still mapped after apt-get purge"
fi
step "all checks passed"

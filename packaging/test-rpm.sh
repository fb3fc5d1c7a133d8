#!/usr/bin/env bash
# Inspects ensil's RPM as a Fedora or RHEL user's rpm would see it, without installing it (this
# is a Debian machine): its name, version and licence, the files it holds and the folders it
# must not own, the dependencies rpm found (the linked libraries by soname) and those declared
# (packaging/rpm/cpack.cmake), and the binary inside, unpacked and run (`ensil --version`).
#   packaging/test-rpm.sh RPM
set -euo pipefail
cd "$(dirname "$0")/.."

if [ $# -ne 1 ] || [ ! -f "$1" ]; then
    echo "usage: packaging/test-rpm.sh path/to/ensil-VERSION-RELEASE.ARCH.rpm" >&2
    exit 2
fi
rpm_file=$(realpath "$1")
app_id=io.github.ensil.ensil
step() { echo "test-rpm: $*"; }
fail() { echo "test-rpm: FAILED: $*" >&2; exit 1; }

version=$(sed -n 's/^project(ensil VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
query() { rpm -qp --queryformat "$1" "$rpm_file"; }
[ "$(query '%{NAME}')" = ensil ] || fail "the package is named $(query '%{NAME}')"
[ "$(query '%{VERSION}')" = "$version" ] || fail "version $(query '%{VERSION}'), not $version"
[ "$(query '%{LICENSE}')" = BSD-3-Clause ] || fail "licence $(query '%{LICENSE}')"
query '%{DESCRIPTION}' | grep -q "ensil shows ensembles" || fail "no description"
step "ensil $(query '%{VERSION}-%{RELEASE}.%{ARCH}'), $(du -k "$rpm_file" | cut -f1) KiB"

files=$(rpm -qlp "$rpm_file")
for path in /usr/bin/ensil \
            /usr/share/applications/$app_id.desktop \
            /usr/share/metainfo/$app_id.metainfo.xml \
            /usr/share/mime/packages/$app_id.xml \
            /usr/share/icons/hicolor/scalable/apps/$app_id.svg \
            /usr/share/icons/hicolor/256x256/apps/$app_id.png \
            /usr/share/doc/ensil/LICENSE \
            /usr/share/man/man1/ensil.1.gz \
            /usr/share/bash-completion/completions/ensil \
            /usr/share/zsh/vendor-completions/_ensil \
            /usr/lib/python3/dist-packages/ensil/__init__.py; do
    grep -qxF "$path" <<<"$files" || fail "$path is not in the package"
done
# Folders other packages own (the filesystem package, the desktop, icon and MIME packages).
for folder in /usr /usr/bin /usr/share /usr/share/applications /usr/share/icons \
              /usr/share/icons/hicolor /usr/share/icons/hicolor/48x48/apps /usr/share/man/man1 \
              /usr/share/mime/packages /usr/lib/python3/dist-packages; do
    if grep -qxF "$folder" <<<"$files"; then fail "the package owns the system folder $folder"; fi
done
step "$(wc -l <<<"$files") paths, no system folder owned"

requires=$(rpm -qpR "$rpm_file")
for needed in 'libQt6Widgets.so.6()(64bit)' 'libnetcdf.so.' 'libvtkIOXML-' 'libeccodes.so.' \
              'libproj.so.' 'libudunits2.so.' 'libOpenMeshCore.so.' qt6-qtsvg mesa-dri-drivers \
              mesa-libEGL 'python(abi) = ' python3-numpy; do
    grep -qF "$needed" <<<"$requires" || fail "Requires lacks $needed"
done
step "Requires: $(grep -c . <<<"$requires") entries, the linked libraries by soname among them"

unpacked=$(mktemp -d)
trap 'rm -rf "$unpacked"' EXIT
# rpm2archive (rpm's own, as a tar stream) rather than rpm2cpio: cpio is not installed here.
rpm2archive - <"$rpm_file" | tar -xzf - -C "$unpacked"
said=$(env -u DISPLAY QT_QPA_PLATFORM=offscreen "$unpacked/usr/bin/ensil" --version)
grep -q "ensil $version" <<<"$said" || fail "the unpacked ensil says: $said"
step "the unpacked ensil runs: $(head -1 <<<"$said")"
step "passed"

#!/usr/bin/env bash
# Checks the .tar.gz that build-package.sh writes next to the .deb: it holds the same files as the
# .deb (under ensil-VERSION-Linux/ instead of /usr), and the unpacked ensil runs (its libraries
# come from the system, as packaging/install-deps.sh installs them).
#   packaging/test-tarball.sh TGZ DEB
set -euo pipefail

if [ $# -ne 2 ] || [ ! -f "$1" ] || [ ! -f "$2" ]; then
    echo "usage: packaging/test-tarball.sh ensil-VERSION-Linux.tar.gz ensil_VERSION_ARCH.deb" >&2
    exit 2
fi
tgz=$1
deb=$2
fail() { echo "test-tarball: FAILED: $*" >&2; exit 1; }

top=$(basename "$tgz" .tar.gz)
# Regular files only: the two archives list folders differently.
tar_files=$(tar -tvzf "$tgz" | awk '$1 ~ /^-/ {print $6}' | sed "s|^$top/||" | sort)
deb_files=$(dpkg-deb --contents "$deb" | awk '$1 ~ /^-/ {print $6}' | sed 's|^\./usr/||' | sort)
if [ "$tar_files" != "$deb_files" ]; then
    fail "the tarball and the .deb hold different files:"$'\n'"$(diff <(echo "$tar_files") \
<(echo "$deb_files"))"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tar -xzf "$tgz" -C "$work"
version=$("$work/$top/bin/ensil" --version | head -n 1) || fail "the unpacked ensil does not run"
echo "test-tarball: $(wc -l <<<"$tar_files") files, as in the .deb; $top/bin/ensil: $version"

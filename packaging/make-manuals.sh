#!/bin/sh
# make-manuals.sh ENSIL VERSION FOLDER: writes the manual pages of ensil and of each of its
# commands (ensil.1.gz, ensil-render.1.gz, ...) into FOLDER, made by help2man from the
# programs' own --help, so that a page says exactly what --help says (one source: the option
# tables of the parsers). Each page gets the exit statuses and the other pages under SEE ALSO.
# packaging/CMakeLists.txt runs it at build time; the packages install the pages.
set -eu
if [ $# -ne 3 ]; then
    echo "usage: packaging/make-manuals.sh path/to/ensil VERSION FOLDER" >&2
    exit 2
fi
ensil=$1
version=$2
out=$3
command -v help2man >/dev/null || {
    echo "make-manuals.sh: help2man is missing (packaging/install-deps.sh installs it)" >&2
    exit 1
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# The commands and their one-line descriptions, as `ensil --help` lists them.
"$ensil" --help | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z]*\)  *\(.*\)$/\1 \2/p' \
    >"$work/commands"
[ -s "$work/commands" ] || {
    echo "make-manuals.sh: '$ensil --help' lists no commands" >&2
    exit 1
}
see_also=$(printf '.BR ensil (1)'; while read -r name _; do
    printf ',\n.BR ensil-%s (1)' "$name"
done <"$work/commands")

cat >"$work/sections" <<SECTIONS
[EXIT STATUS]
.TP
.B 0
It did what was asked.
.TP
.B 1
The data or the files could not be used as asked (a file unreadable or damaged, no surface at
the isovalue, an output that cannot be written); the message names the file and the field.
.TP
.B 2
The command line was refused (an unknown option, a value out of its range, options that
exclude each other); the message names the option and what is allowed.
.TP
.B 4
No display server for the workbench, and for \\fBensil render\\fR no EGL either; the message
says how to run it.

[SEE ALSO]
$see_also
.PP
The documents in /usr/share/doc/ensil and https://github.com/ensil/ensil: the workbench, the
command line, Python, and METHODS.md for what each picture and number means.
SECTIONS

page() {  # page NAME DESCRIPTION PROGRAM
    help2man --no-info --no-discard-stderr --version-string="$version" --name="$2" \
        --include="$work/sections" --output="$work/$1.1" "$3"
    gzip -9n -c "$work/$1.1" >"$out/$1.1.gz"
}
page ensil "a workbench for ensembles of 3D isosurfaces drawn as silhouettes" "$ensil"
while read -r name description; do
    # help2man runs one program: a wrapper per command.
    wrapper="$work/ensil-$name"
    printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$ensil" "$name" >"$wrapper"
    chmod +x "$wrapper"
    page "ensil-$name" "$description" "$wrapper"
done <"$work/commands"

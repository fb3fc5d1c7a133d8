#!/bin/sh
# make-command-help.sh ENSIL VERSION FOLDER: writes, from the built ENSIL's own --help (one
# source: the option tables of its parsers, so neither can drift from them):
#   FOLDER/completion/ensil and _ensil  bash and zsh completion of the commands and each one's
#                                       options;
#   FOLDER/man/ensil.1.gz, ensil-COMMAND.1.gz
#                                       manual pages by help2man, with the exit statuses and
#                                       the other pages under SEE ALSO (only where help2man is
#                                       installed; packaging/install-deps.sh installs it).
# packaging/manuals.cmake runs it at build time; the packages install what it writes.
set -eu
if [ $# -ne 3 ]; then
    echo "usage: packaging/make-command-help.sh path/to/ensil VERSION FOLDER" >&2
    exit 2
fi
ensil=$1
version=$2
out=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out/completion"

# The commands and their one-line descriptions, as `ensil --help` lists them.
"$ensil" --help | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z]*\)  *\(.*\)$/\1 \2/p' \
    >"$work/commands"
[ -s "$work/commands" ] || {
    echo "make-command-help.sh: '$ensil --help' lists no commands" >&2
    exit 1
}

# The long and short options a --help lists, one line: "--iso --out -h --help".
options_of() {
    "$ensil" "$@" --help |
        sed -n 's/^  \(-[A-Za-z]\), \(--[a-z][a-z0-9-]*\).*/\1 \2/p; s/^  \(--[a-z][a-z0-9-]*\).*/\1/p' |
        tr '\n' ' ' | sed 's/ $//'
}
commands=$(cut -d ' ' -f 1 "$work/commands" | tr '\n' ' ' | sed 's/ $//')
top=$(options_of)

{
    echo "# bash completion for ensil; made by packaging/make-command-help.sh from ensil's --help."
    echo "_ensil() {"
    echo '    local cur=${COMP_WORDS[COMP_CWORD]} command= options'
    echo '    [ "$COMP_CWORD" -gt 1 ] && command=${COMP_WORDS[1]}'
    echo '    case $command in'
    for name in $commands; do
        echo "        $name) options=\"$(options_of "$name")\" ;;"
    done
    echo "        *) options=\"$top\" ;;"
    echo '    esac'
    echo '    if [[ $cur == -* ]]; then'
    echo '        COMPREPLY=($(compgen -W "$options" -- "$cur"))'
    echo '    elif [ "$COMP_CWORD" -eq 1 ]; then'
    echo "        COMPREPLY=(\$(compgen -W \"$commands\" -- \"\$cur\") \$(compgen -f -- \"\$cur\"))"
    echo '    else'
    echo '        COMPREPLY=($(compgen -f -- "$cur"))'
    echo '    fi'
    echo "}"
    echo "complete -o filenames -F _ensil ensil"
} >"$out/completion/ensil"

{
    echo "#compdef ensil"
    echo "# zsh completion for ensil; made by packaging/make-command-help.sh from ensil's --help."
    echo "local -a options"
    echo 'case $words[2] in'
    for name in $commands; do
        echo "    $name) options=($(options_of "$name")) ;;"
    done
    echo "    *) options=($top) ;;"
    echo "esac"
    echo 'if [[ $PREFIX == -* ]]; then'
    echo '    compadd -- $options'
    echo 'elif (( CURRENT == 2 )); then'
    echo "    compadd -- $commands"
    echo "    _files"
    echo "else"
    echo "    _files"
    echo "fi"
} >"$out/completion/_ensil"

command -v help2man >/dev/null || {
    echo "make-command-help.sh: help2man is missing, so no manual pages" >&2
    exit 0
}
mkdir -p "$out/man"
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
    gzip -9n -c "$work/$1.1" >"$out/man/$1.1.gz"
}
page ensil "a workbench for ensembles of 3D isosurfaces drawn as silhouettes" "$ensil"
while read -r name description; do
    # help2man runs one program: a wrapper per command.
    wrapper="$work/ensil-$name"
    printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$ensil" "$name" >"$wrapper"
    chmod +x "$wrapper"
    page "ensil-$name" "$description" "$wrapper"
done <"$work/commands"

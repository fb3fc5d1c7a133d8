#!/bin/sh
# make-completions.sh ENSIL FOLDER: writes shell completion for ensil into FOLDER: `ensil`
# (bash, for /usr/share/bash-completion/completions) and `_ensil` (zsh, for its
# vendor-completions). Commands and options are read from the program's own --help, so the
# completion offers exactly what the parsers take (one source: their option tables).
# packaging/CMakeLists.txt runs it at build time; CTest's packaging.completion tries it.
set -eu
if [ $# -ne 2 ]; then
    echo "usage: packaging/make-completions.sh path/to/ensil FOLDER" >&2
    exit 2
fi
ensil=$1
out=$2
mkdir -p "$out"

# The long and short options a --help lists, one line: "--iso --out -h --help".
options_of() {
    "$ensil" "$@" --help |
        sed -n 's/^  \(-[A-Za-z]\), \(--[a-z][a-z0-9-]*\).*/\1 \2/p; s/^  \(--[a-z][a-z0-9-]*\).*/\1/p' |
        tr '\n' ' ' | sed 's/ $//'
}
commands=$("$ensil" --help | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z]*\)  .*/\1/p' |
    tr '\n' ' ' | sed 's/ $//')
[ -n "$commands" ] || {
    echo "make-completions.sh: '$ensil --help' lists no commands" >&2
    exit 1
}
top=$(options_of)

{
    echo "# bash completion for ensil; made by packaging/make-completions.sh from ensil's --help."
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
} >"$out/ensil"

{
    echo "#compdef ensil"
    echo "# zsh completion for ensil; made by packaging/make-completions.sh from ensil's --help."
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
} >"$out/_ensil"

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Man pages for tactus-cli, generated from its --help (so they never drift
# from the program): tactus-cli.1 and tactus-cli-COMMAND.1 for each command.
# help2man writes them when it is installed; otherwise a small generator puts
# the --help text under NAME, SYNOPSIS and DESCRIPTION. Pages are gzipped -n
# (no time stamp: the same input gives the same bytes).
#   make_man.sh TACTUS_CLI OUTDIR VERSION
set -euo pipefail
cli=$1 out=$2 version=$3
mkdir -p "$out"
rm -f "$out"/*.1 "$out"/*.1.gz

# The commands, as the program lists them ("  name   description").
commands=$("$cli" --help | awk '/^Subcommands:/{on=1; next} on && /^  [a-z]/{print $1}')
[ -n "$commands" ] || { echo "make_man: no commands found in '$cli --help'" >&2; exit 1; }

summary() {  # one line of what a command does, from the main --help
    "$cli" --help | awk -v c="$1" '/^Subcommands:/{on=1; next} on && $1==c {$1=""; sub(/^ +/, ""); print; exit}'
}

roff_escape() { sed -e 's/\\/\\e/g' -e 's/^\./\\\&./' -e "s/^'/\\\\\\&'/"; }

plain_page() {  # page NAME-IN-TITLE "PROGRAM ARGS" SUMMARY FILE
    local title=$1 prog=$2 what=$3 file=$4
    local upper
    upper=$(echo "$title" | tr '[:lower:]' '[:upper:]')
    {
        echo ".TH $upper 1 \"\" \"tactus-cli $version\" \"User Commands\""
        echo ".SH NAME"
        echo "$title \\- $what" | roff_escape
        echo ".SH SYNOPSIS"
        echo ".B $prog"
        echo "[\\fIOPTIONS\\fR]"
        echo ".SH DESCRIPTION"
        echo ".nf"
        $prog --help | roff_escape
        echo ".fi"
        echo ".SH SEE ALSO"
        echo ".BR tactus-cli (1)"
    } >"$file"
}

page() {  # page TITLE "PROGRAM ARGS" SUMMARY
    local title=$1 prog=$2 what=$3 file="$out/$1.1"
    if command -v help2man >/dev/null; then
        help2man --no-info --no-discard-stderr --version-string="$version" --name="$what" \
                 --output="$file" "$prog" >/dev/null 2>&1 || plain_page "$title" "$prog" "$what" "$file"
    else
        plain_page "$title" "$prog" "$what" "$file"
    fi
    [ -s "$file" ] || { echo "make_man: $file is empty" >&2; exit 1; }
}

page tactus-cli "$cli" "translate, lay out and emboss braille"
for c in $commands; do
    page "tactus-cli-$c" "$cli $c" "$(summary "$c")"
done
gzip -9n "$out"/*.1

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Man pages for tactus-cli, generated from its --help (so they never drift
# from the program): tactus-cli.1 and tactus-cli-COMMAND.1 for each command.
# help2man writes them when it is installed; otherwise a small generator puts
# the --help text under NAME, SYNOPSIS and DESCRIPTION. Pages are gzipped -n
# (no time stamp: the same input gives the same bytes).
# The desktop app's page, tactus.1, comes from its --help too when GUI (the
# built `tactus`) is given; it runs on Qt's offscreen platform (no display).
#   make_man.sh TACTUS_CLI OUTDIR VERSION [GUI]
set -euo pipefail
cli=$1 out=$2 version=$3 gui=${4:-}
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

# help2man names a command page after the program line, "tactus-cli emboss";
# whatis (lexgrog, lintian's bad-whatis-entry) wants one word, the page's own
# name: tactus-cli-emboss, as in git-commit(1).
own_name() {  # own_name TITLE FILE
    local title=$1 file=$2 upper
    upper=$(echo "$title" | tr '[:lower:]' '[:upper:]')
    sed -i -e "s/^\.TH \"\{0,1\}TACTUS-CLI\"\{0,1\} /.TH \"$upper\" /" \
           -e "/^\.SH NAME/{n;s/^tactus-cli ${title#tactus-cli-} \\\\-/$title \\\\-/}" "$file"
}

page tactus-cli "$cli" "translate, lay out and emboss braille"
for c in $commands; do
    page "tactus-cli-$c" "$cli $c" "$(summary "$c")"
    own_name "tactus-cli-$c" "$out/tactus-cli-$c.1"
done
if [ -n "$gui" ]; then
    runtime=$(mktemp -d)
    QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=$runtime \
        page tactus "$gui" "braille editor and embosser print manager"
    rmdir "$runtime"
fi
gzip -9n "$out"/*.1

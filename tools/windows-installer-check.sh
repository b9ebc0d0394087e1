#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The Windows installer installed, used and uninstalled under Wine, in a fresh
# Wine prefix (docs/windows.md):
#  1. `tactus-<version>-win64.exe /S /D=C:\Tactus` installs silently, and the
#     installed folder holds the program, its tables, the samples and licences;
#     the program imports only Windows' own DLLs (no MinGW runtime DLL);
#  2. drive Z: (the build machine's /, where a build-tree program finds
#     Debian's tables) is taken out of the prefix, so the installed program can
#     only use what was installed beside it;
#  3. its `--version` and, on every installed sample document, `layout --to brf` (BRF)
#     and `plan` must be byte-identical to the Linux CLI's on the same files,
#     and `emboss --device sim` of firmware-note.md must end with the same
#     "embossed N passes" line; a document of 4893 blocks (Genesis to Numbers,
#     bible-kjv) laid out with 1 and with 2 translation workers (on Windows,
#     the installed program started again) must give the Linux BRF;
#  4. `Uninstall.exe /S` removes the installed folder.
# Usage: tools/windows-installer-check.sh [INSTALLER]
#        (default: the one build/windows/package holds; tools/windows-build.sh package)
# Environment: LINUX_CLI (default build/default/app/tactus-cli), KEEP_PREFIX=1
#              keeps the Wine prefix (its path is printed).
# Exit status: 0 all the same, 1 a difference or a failed step (shown), 2 something missing.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
installer=${1:-$(ls "$root"/build/windows/package/tactus-*-win64.exe 2>/dev/null | tail -1)}
linux=${LINUX_CLI:-"$root/build/default/app/tactus-cli"}
wine=$(command -v wine64 || command -v wine || { [ -x /usr/lib/wine/wine64 ] && echo /usr/lib/wine/wine64; } || true)
wineserver=$(command -v wineserver || { [ -x /usr/lib/wine/wineserver64 ] && echo /usr/lib/wine/wineserver64; } || true)
objdump=x86_64-w64-mingw32-objdump
say() { echo "windows-installer-check: $*"; }
[ -n "$installer" ] && [ -f "$installer" ] || { say "no installer (tools/windows-build.sh package)" >&2; exit 2; }
[ -x "$linux" ] || { say "no Linux CLI at $linux" >&2; exit 2; }
[ -n "$wine" ] && [ -n "$wineserver" ] || { say "no Wine (apt-get install wine64)" >&2; exit 2; }
command -v $objdump >/dev/null 2>&1 || { say "$objdump not found (apt-get install binutils-mingw-w64-x86-64)" >&2; exit 2; }

work=$(mktemp -d)
export WINEPREFIX="$work/prefix" WINEDEBUG="${WINEDEBUG:--all}"
cleanup() {
    "$wineserver" -k 2>/dev/null || true
    if [ "${KEEP_PREFIX:-0}" = 1 ]; then say "Wine prefix kept: $WINEPREFIX"; else rm -rf "$work"; fi
}
trap cleanup EXIT
status=0
fail() { say "$*" >&2; status=1; }
same() {  # same WHAT LINUX_FILE WINDOWS_FILE
    if cmp -s "$2" "$3"; then
        say "$1: identical ($(wc -c <"$2") bytes)"
    else
        fail "$1: DIFFERENT"
        diff "$2" "$3" | head -20 >&2 || true
    fi
}

# 1. Install silently into C:\Tactus (the installer's own default is
#    C:\Program Files\Tactus; /D must be its last argument).
start=$(date +%s)
"$wine" wineboot --init >/dev/null 2>&1
"$wineserver" -w
say "fresh Wine prefix: $(( $(date +%s) - start )) s"
dir="$WINEPREFIX/drive_c/Tactus"
start=$(date +%s)
"$wine" "$installer" /S '/D=C:\Tactus' || { say "the installer failed (exit $?)" >&2; exit 1; }
"$wineserver" -w
say "installed $(basename "$installer") in $(( $(date +%s) - start )) s: $(find "$dir" -type f | wc -l) files, $(du -sh "$dir" | cut -f1)"
for f in tactus-cli.exe Uninstall.exe share/liblouis/tables/unicode.dis share/liblouis/tables/en-ueb-g2.ctb \
         samples/welcome.md licences/Tactus-GPL-3.0-or-later.txt licences/liblouis-LGPL-2.1-or-later.txt; do
    [ -f "$dir/$f" ] || fail "not installed: $f"
done
[ $status = 0 ] || exit 1
dlls=$($objdump -p "$dir/tactus-cli.exe" | sed -n 's/^[[:space:]]*DLL Name: //p' | sort -u | tr '\n' ' ')
say "tactus-cli.exe imports: $dlls"
case " $dlls" in
    *" lib"*|*zlib*) fail "tactus-cli.exe needs a DLL the installer does not carry" ;;
esac

# 2. Nothing of the build machine is visible any more.
rm -f "$WINEPREFIX/dosdevices/z:"
if "$wine" cmd /c 'dir Z:\' >/dev/null 2>&1; then fail "drive Z: is still there"; fi

# 3. The installed program against the Linux one.
cli='C:\Tactus\tactus-cli.exe'
out="$work/out"
mkdir -p "$out"
"$linux" --version >"$out/version.linux"
"$wine" "$cli" --version >"$out/version.windows" || fail "tactus-cli.exe --version failed"
same "--version ($(cat "$out/version.linux"))" "$out/version.linux" "$out/version.windows"
for sample in "$dir"/samples/*; do
    name=$(basename "$sample")
    same "installed sample $name against resources/samples" "$root/resources/samples/$name" "$sample"
    # The documents only. README.md describes the folder; its hyphenated words
    # ("GPL-3.0-or-later") break differently: Wine's Uniscribe offers no break
    # after a hyphen where ICU does (docs/windows.md, the build without ICU).
    [ "$name" = README.md ] && continue
    # Each sample with the table it is written for (resources/samples/README.md).
    case $name in
        chinese-tw.*) table=zh-tw.ctb ;;
        chinese-cn.*) table=zhcn-g1.ctb ;;
        *) table=en-ueb-g2.ctb ;;
    esac
    "$linux" layout --table "$table" --to brf "$root/resources/samples/$name" >"$out/$name.brf.linux" 2>"$out/$name.err.linux" ||
        fail "Linux layout of $name failed: $(cat "$out/$name.err.linux")"
    "$wine" "$cli" layout --table "$table" --to brf "C:\\Tactus\\samples\\$name" >"$out/$name.brf.windows" 2>"$out/$name.err.windows" ||
        fail "Windows layout of $name failed: $(tr -d '\r' <"$out/$name.err.windows")"
    same "layout --table $table --to brf $name" "$out/$name.brf.linux" "$out/$name.brf.windows"
    "$linux" plan --table "$table" "$root/resources/samples/$name" >"$out/$name.plan.linux" 2>/dev/null ||
        fail "Linux plan of $name failed"
    "$wine" "$cli" plan --table "$table" "C:\\Tactus\\samples\\$name" >"$out/$name.plan.windows" 2>"$out/$name.err.windows" ||
        fail "Windows plan of $name failed: $(tr -d '\r' <"$out/$name.err.windows")"
    same "plan --table $table $name" "$out/$name.plan.linux" "$out/$name.plan.windows"
done
# What Tactus itself reads from the tables folder, beside what liblouis reads
# (liblouis on Windows falls back on <program folder>/share/liblouis/tables by
# itself): with en-us-g2.ctb, a table without metadata of its own, EBAE's note
# indicator comes from the metadata of the table it includes, and whether a
# word may switch to computer braille as a whole (its compbrl rules) from the
# table files; on a 27- and a 12-cell line (long words divided). A program
# that reads only the folder it was built for writes the wrong note indicator
# once drive Z: is gone (checked). No "http://": a line may break after its
# "//" with ICU and not with Wine's Uniscribe (docs/windows.md).
printf '%s\n\n%s\n\n%s\n' \
    'Transcribers characteristically hyphenate extraordinarily incomprehensible constitutional arrangements.' \
    'Write to example.com or tactus.org for more.[^1]' '[^1]: A note.' >"$out/tables.md"
cp "$out/tables.md" "$WINEPREFIX/drive_c/tables.md"
for cells in 12 27; do
    what="layout --table en-us-g2.ctb --cells $cells --to brf (long words, web names, a note)"
    "$linux" layout --table en-us-g2.ctb --cells $cells --to brf "$out/tables.md" >"$out/tables.$cells.linux" 2>/dev/null ||
        fail "Linux $what failed"
    "$wine" "$cli" layout --table en-us-g2.ctb --cells $cells --to brf 'C:\tables.md' >"$out/tables.$cells.windows" 2>"$out/tables.err.windows" ||
        fail "Windows $what failed: $(tr -d '\r' <"$out/tables.err.windows")"
    same "$what" "$out/tables.$cells.linux" "$out/tables.$cells.windows"
done
# A document big enough for translation workers (4000 blocks or more): the
# first four books of the King James Version (Debian's bible-kjv), 4893
# verses. On Windows a worker is the installed tactus-cli.exe started again,
# finding its tables beside itself: with 1 and with 2 workers, the Linux BRF.
if command -v bible >/dev/null 2>&1; then
    start=$(date +%s)
    bible -f gen1:1-num36:13 >"$out/kjv.txt"
    cp "$out/kjv.txt" "$WINEPREFIX/drive_c/kjv.txt"
    "$linux" layout --to brf "$out/kjv.txt" >"$out/kjv.linux" 2>/dev/null || fail "Linux layout of kjv.txt failed"
    for n in 1 2; do
        "$wine" "$cli" layout --workers $n --to brf 'C:\kjv.txt' >"$out/kjv.$n.windows" 2>"$out/kjv.err.windows" ||
            fail "Windows layout --workers $n of kjv.txt failed: $(tr -d '\r' <"$out/kjv.err.windows")"
        same "layout --workers $n --to brf kjv.txt (Genesis to Numbers, $(wc -l <"$out/kjv.txt") verses)" \
            "$out/kjv.linux" "$out/kjv.$n.windows"
    done
    say "translation workers: $(( $(date +%s) - start )) s"
else
    fail "no bible-kjv (apt-get install bible-kjv) for the translation workers' document"
fi
"$linux" emboss --device sim "$root/resources/samples/firmware-note.md" 2>&1 | grep '^embossed ' >"$out/emboss.linux" || true
"$wine" "$cli" emboss --device sim 'C:\Tactus\samples\firmware-note.md' 2>&1 | tr -d '\r' | grep '^embossed ' >"$out/emboss.windows" || true
[ -s "$out/emboss.linux" ] || fail "the Linux CLI printed no 'embossed' line"
same "emboss --device sim firmware-note.md: $(cat "$out/emboss.linux")" "$out/emboss.linux" "$out/emboss.windows"

# 4. Uninstall. NSIS's uninstaller copies itself to a temporary folder and
#    runs from there: wait for every process of the prefix to end.
"$wine" 'C:\Tactus\Uninstall.exe' /S || fail "Uninstall.exe failed"
"$wineserver" -w
if [ -e "$dir" ]; then
    fail "the uninstaller left $(find "$dir" | wc -l) entries in C:\\Tactus: $(find "$dir" | head -5 | tr '\n' ' ')"
else
    say "uninstalled: C:\\Tactus is gone"
fi
[ $status = 0 ] && say "all the same" || say "DIFFERENCES (above)" >&2
exit $status

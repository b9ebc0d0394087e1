#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the .deb with CPack from a finished build and checks it:
#   - its file list (dpkg-deb -c): programs, CUPS backend (mode 0755: cupsd
#     runs it as lp) and filter, PPD and MIME types, desktop file, icon,
#     AppStream metadata, udev rule, tmpfiles entry, man pages, copyright,
#     changelog; nothing outside /usr; no unstripped program;
#   - its control data: maintainer scripts, dependencies found by dpkg-shlibdeps;
#   - the man pages: every option each --help names is in the page;
#   - the validators: appstreamcli, appstream-util, desktop-file-validate,
#     cupstestppd, and lintian with only the exceptions docs/packaging.md
#     documents (packaging/lintian-exceptions);
#   - the install: into a clean Debian 12 chroot (clean_chroot.sh) with apt,
#     which must find every dependency in Debian alone; there the installed
#     tactus-cli runs the main job (the bundled sample embossed on the built-in
#     simulator) and must report and plan exactly what the build's tactus-cli
#     does; the backend runs as lp; the app starts; purge leaves nothing.
#   deb_test.sh BUILD_DIR SOURCE_DIR
# Without root or debootstrap the install is skipped (exit 77, ctest's
# SKIP_RETURN_CODE) after every other check has passed.
set -euo pipefail

if [ "${1:-}" = --in-chroot ]; then
    # Phase two, inside a private mount namespace (mounts vanish with it):
    #   deb_test.sh --in-chroot ROOT EXPECTED_DIR APT_CACHE
    root=$2 expected=$3 apt_cache=$4
    mount -t proc proc "$root/proc"
    mount --rbind /dev "$root/dev"
    mkdir -p "$apt_cache"
    mount --bind "$apt_cache" "$root/var/cache/apt/archives"
    failures=0
    check() { if "$@"; then echo "ok   $*"; else echo "FAIL $*"; failures=$((failures + 1)); fi; }
    in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin LC_ALL=C.UTF-8 HOME=/root "$@"; }
    installed() {
        in_root sh -c 'apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends /tmp/tactus.deb' \
            >"$expected/apt.log" 2>&1 || { tail -n 30 "$expected/apt.log"; return 1; }
    }
    check installed
    check in_root sh -c 'dpkg-query -W -f "\${Status}" tactus | grep -q "install ok installed"'
    check in_root sh -c 'test "$(stat -c "%U:%G %a" /var/spool/tactus)" = "lp:lp 2775"'
    sample=/usr/share/doc/tactus/examples/welcome.md
    # The main job: same last line (passes, bytes sent) as the build's program.
    in_root tactus-cli emboss --device 'sim?speed=max' "$sample" >"$expected/emboss.installed" 2>&1 || true
    check bash -c "tail -n 1 '$expected/emboss.installed' | grep -q '^embossed '"
    check cmp -s <(tail -n 1 "$expected/emboss.installed") <(tail -n 1 "$expected/emboss.build")
    # ... and the same plan, strike for strike (liblouis tables from liblouis-data).
    in_root tactus-cli plan --json "$sample" >"$expected/plan.installed" 2>/dev/null || true
    check cmp "$expected/plan.installed" "$expected/plan.build"
    # cupsd runs the backend as lp: discovery works as lp.
    check in_root runuser -u lp -- /usr/lib/cups/backend/tactus
    # The app's libraries all resolve on a clean system.
    check bash -c "chroot '$root' env QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=/tmp tactus --version 2>/dev/null | grep -q '^tactus '"
    # Purge: every file the package brought is gone, and the spool too.
    in_root dpkg-query -L tactus | while read -r f; do [ -f "$root$f" ] && echo "$f"; done >"$expected/files" || true
    check test -s "$expected/files"
    check in_root sh -c 'DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq tactus >/dev/null'
    check bash -c "! while read -r f; do [ -e '$root'\"\$f\" ] && echo \"left: \$f\"; done <'$expected/files' | grep ."
    check test ! -e "$root/var/spool/tactus"
    exit "$failures"
fi

build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { if "$@"; then echo "ok   $*"; else echo "FAIL $*"; failures=$((failures + 1)); fi; }

(cd "$build" && cpack --config CPackConfig.cmake -B "$work/pkg" >"$work/cpack.log" 2>&1) || {
    cat "$work/cpack.log"; echo "FAIL cpack"; exit 1; }
deb=$(ls "$work"/pkg/*.deb)
echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB)"
dpkg-deb -c "$deb" >"$work/list"
has() { grep -qE "$1" "$work/list"; }

gui=no
[ -x "$build/app/gui/tactus" ] && gui=yes
check has ' \./usr/bin/tactus-cli$'
if [ "$gui" = yes ]; then
    check has ' \./usr/bin/tactus$'
    check has ' \./usr/share/applications/tactus\.desktop$'
    check has ' \./usr/share/icons/hicolor/scalable/apps/tactus\.svg$'
    check has ' \./usr/share/man/man1/tactus\.1\.gz$'
fi
check has '^-rwxr-xr-x .* \./usr/lib/cups/backend/tactus$'
check has '^-rwxr-xr-x .* \./usr/lib/cups/filter/tactus-layout$'
check has ' \./usr/share/cups/mime/tactus\.types$'
check has ' \./usr/share/ppd/tactus/tactus\.ppd$'
check has ' \./usr/share/metainfo/org\.tactus\.Tactus\.metainfo\.xml$'
check has ' \./usr/lib/udev/rules\.d/60-tactus-embosser\.rules$'
check has ' \./usr/lib/tmpfiles\.d/tactus\.conf$'
check has ' \./usr/share/man/man1/tactus-cli\.1\.gz$'
check has ' \./usr/share/man/man1/tactus-cli-emboss\.1\.gz$'
check has ' \./usr/share/man/man1/tactus-cli-queue\.1\.gz$'
check has ' \./usr/share/doc/tactus/copyright$'
check has ' \./usr/share/doc/tactus/changelog\.gz$'
check has ' \./usr/share/doc/tactus/examples/welcome\.md$'
# Nothing outside /usr (the spool folder is made by tmpfiles/postinst).
check bash -c "! grep -vE ' \./(usr(/.*)?)?/?$' '$work/list'"

dpkg-deb -I "$deb" >"$work/info"
check grep -q 'Depends:.*liblouis' "$work/info"
check grep -q 'Depends:.*libcups2' "$work/info"
check grep -qE '^ *[0-9]+ bytes, +[0-9]+ lines +\* +postinst ' "$work/info"
check grep -qE '^ *[0-9]+ bytes, +[0-9]+ lines +\* +postrm ' "$work/info"

root="$work/root"
dpkg-deb -x "$deb" "$root"
# Stripped programs: a program with debug info is ten times the size (70 MB).
for p in usr/bin/tactus-cli usr/lib/cups/backend/tactus usr/lib/cups/filter/tactus-layout; do
    check bash -c "file '$root/$p' | grep -q ', stripped'"
done

# Man pages: generated from --help, so every long option each --help names
# must be in the page (rendered, as man shows it).
man_has_options() {  # man_has_options PAGE PROGRAM [COMMAND]
    local page=$1; shift
    local rendered missing=""
    rendered=$(zcat "$root/usr/share/man/man1/$page.1.gz" | MANWIDTH=200 man -l - 2>/dev/null | col -b)
    for opt in $("$@" --help 2>/dev/null | grep -oE -- '--[a-z][a-z0-9-]+' | sort -u); do
        grep -qF -- "$opt" <<<"$rendered" || missing="$missing $opt"
    done
    [ -z "$missing" ] || { echo "  $page lacks:$missing"; return 1; }
}
cli_build="$build/app/tactus-cli"
check man_has_options tactus-cli "$cli_build"
commands=$("$cli_build" --help | awk '/^Subcommands:/{on=1; next} on && /^  [a-z]/{print $1}')
for c in $commands; do
    check man_has_options "tactus-cli-$c" "$cli_build" "$c"
done
check bash -c "zcat '$root/usr/share/man/man1/tactus-cli-emboss.1.gz' | man -l - 2>/dev/null | col -b | grep -q -- '--device'"
# whatis finds each page under its own name.
for page in "$root"/usr/share/man/man1/*.1.gz; do
    name=$(basename "$page" .1.gz)
    check bash -c "lexgrog '$page' | grep -q ': \"$name - '"
done

if command -v appstreamcli >/dev/null; then
    check appstreamcli validate --no-net "$root/usr/share/metainfo/org.tactus.Tactus.metainfo.xml"
fi
if command -v appstream-util >/dev/null; then
    # Strict validation's one documented exception: no <url> (Tactus has no
    # homepage yet). Anything else it reports fails.
    appstream-util validate --nonet "$root/usr/share/metainfo/org.tactus.Tactus.metainfo.xml" >"$work/appstream" 2>&1 || true
    check bash -c "! grep '^•' '$work/appstream' | grep -v 'tag-missing *: <url> is not present'"
    check appstream-util validate-relax --nonet "$root/usr/share/metainfo/org.tactus.Tactus.metainfo.xml"
fi
if [ "$gui" = yes ] && command -v desktop-file-validate >/dev/null; then
    # Clean: not even a hint.
    check bash -c "desktop-file-validate '$root/usr/share/applications/tactus.desktop' >'$work/desktop' 2>&1 && ! [ -s '$work/desktop' ]"
    cat "$work/desktop"
fi
if command -v cupstestppd >/dev/null; then
    # -R: the filter the PPD names is looked up in the package, not on this machine.
    check cupstestppd -R "$root" -W translations "$root/usr/share/ppd/tactus/tactus.ppd"
fi
if command -v lintian >/dev/null; then
    # Only the documented exceptions (docs/packaging.md) may remain.
    lintian --no-tag-display-limit --suppress-tags-from-file "$src/packaging/lintian-exceptions" "$deb" >"$work/lintian" 2>&1 || true
    check bash -c "! grep -E '^[EW]:' '$work/lintian'"
    grep -E '^[EW]:' "$work/lintian" || true
fi

# The main job and its plan from the build's program, to compare with the installed one.
expected="$work/expected"
mkdir -p "$expected"
"$cli_build" emboss --device 'sim?speed=max' "$src/resources/samples/welcome.md" >"$expected/emboss.build" 2>&1 || true
"$cli_build" plan --json "$src/resources/samples/welcome.md" >"$expected/plan.build" 2>/dev/null || true
check bash -c "tail -n 1 '$expected/emboss.build' | grep -q '^embossed '"

if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s) before the install"
    exit 1
fi

# The install into a clean Debian 12 chroot.
chroot_dir="$work/chroot"
set +e
"$src/tests/packaging/clean_chroot.sh" "$chroot_dir"
made=$?
set -e
if [ "$made" -eq 77 ]; then
    echo "SKIP the install into a clean chroot (see above); the rest passed"
    exit 77
fi
[ "$made" -eq 0 ] || { echo "FAIL clean_chroot.sh"; exit 1; }
cp "$deb" "$chroot_dir/tmp/tactus.deb"
set +e
unshare --mount --propagation private bash "$0" --in-chroot "$chroot_dir" "$expected" \
    "${TACTUS_CHROOT_CACHE:-/var/cache/tactus-ci}/archives"
in_chroot=$?
set -e
failures=$((failures + in_chroot))
echo "$failures failure(s)"
[ "$failures" -eq 0 ]

#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the .deb with CPack from a finished build and checks it:
#   - its file list (dpkg-deb -c): programs, CUPS backend (mode 0755: cupsd
#     runs it as lp) and filter, PPD and MIME types, desktop file, icon,
#     AppStream metadata, udev rule, tmpfiles entry, man pages, copyright;
#   - its control data: maintainer scripts, dependencies found by dpkg-shlibdeps;
#   - the metadata validators: appstreamcli, desktop-file-validate, cupstestppd;
#     lintian with the exceptions docs/packaging.md documents, and nothing else;
#   - the main job from the unpacked binaries (dpkg -x into a scratch root:
#     installing into this shared CI machine is not done; see docs/packaging.md).
#   deb_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { if "$@"; then echo "ok   $*"; else echo "FAIL $*"; failures=$((failures + 1)); fi; }

(cd "$build" && cpack --config CPackConfig.cmake -B "$work/pkg" >"$work/cpack.log" 2>&1) || {
    cat "$work/cpack.log"; echo "FAIL cpack"; exit 1; }
deb=$(ls "$work"/pkg/*.deb)
echo "package: $(basename "$deb")"
dpkg-deb -c "$deb" >"$work/list"
has() { grep -qE "$1" "$work/list"; }

gui=no
[ -x "$build/app/gui/tactus" ] && gui=yes
check has ' \./usr/bin/tactus-cli$'
if [ "$gui" = yes ]; then
    check has ' \./usr/bin/tactus$'
    check has ' \./usr/share/applications/tactus\.desktop$'
    check has ' \./usr/share/icons/hicolor/scalable/apps/tactus\.svg$'
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
check has ' \./usr/share/doc/tactus/examples/welcome\.md$'
# Nothing outside /usr (the spool folder is made by tmpfiles/postinst).
check bash -c "! grep -vE ' \./(usr(/.*)?)?/?$' '$work/list'"

dpkg-deb -I "$deb" >"$work/info"
check grep -q 'Depends:.*liblouis' "$work/info"
check grep -q 'Depends:.*libcups2' "$work/info"
check grep -qE '^ *[0-9]+ bytes, +[0-9]+ lines +\* postinst' "$work/info"

root="$work/root"
dpkg-deb -x "$deb" "$root"
if command -v appstreamcli >/dev/null; then
    check appstreamcli validate --no-net "$root/usr/share/metainfo/org.tactus.Tactus.metainfo.xml"
fi
if [ "$gui" = yes ] && command -v desktop-file-validate >/dev/null; then
    check desktop-file-validate "$root/usr/share/applications/tactus.desktop"
fi
if command -v cupstestppd >/dev/null; then
    check cupstestppd -W translations "$root/usr/share/ppd/tactus/tactus.ppd"
fi
check bash -c "zcat '$root/usr/share/man/man1/tactus-cli-emboss.1.gz' | grep -q -- '--device'"
if command -v lintian >/dev/null; then
    # Only the documented exceptions (docs/packaging.md) may remain.
    lintian --no-tag-display-limit --suppress-tags-from-file "$src/packaging/lintian-exceptions" "$deb" >"$work/lintian" 2>&1 || true
    check bash -c "! grep -E '^[EW]:' '$work/lintian'"
    grep -E '^[EW]:' "$work/lintian" || true
fi

# The main job from the unpacked programs.
cli="$root/usr/bin/tactus-cli"
check "$cli" --version
check bash -c "'$cli' emboss --device 'sim?speed=max' '$root/usr/share/doc/tactus/examples/welcome.md' | tail -n 1 | grep -q '^embossed '"
check bash -c "'$root/usr/lib/cups/backend/tactus' >/dev/null"   # discovery runs (any cables listed)

echo "$failures failure(s)"
[ "$failures" -eq 0 ]

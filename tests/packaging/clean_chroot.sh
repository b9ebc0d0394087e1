#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A clean Debian 12 (bookworm) root file system in DIR, for installing the
# .deb as a school machine would (docs/packaging.md).
#   clean_chroot.sh DIR
# debootstrap --variant=minbase (debootstrap's default mirror) takes about
# 2 minutes and 200 MB, so the fresh tree is kept as a tar in the cache
# (TACTUS_CHROOT_CACHE, default /var/cache/tactus-ci) and later calls only
# unpack it: a few seconds. A cache older than 30 days is made again (security
# updates come from apt-get update inside the chroot in any case).
# Needs root (debootstrap, mknod) and debootstrap; exit 77 says why not.
set -euo pipefail
dir=$1
cache=${TACTUS_CHROOT_CACHE:-/var/cache/tactus-ci}
tar_file="$cache/bookworm-minbase.tar"

[ "$(id -u)" -eq 0 ] || { echo "clean_chroot: needs root" >&2; exit 77; }
command -v debootstrap >/dev/null || { echo "clean_chroot: debootstrap is not installed (tools/install-deps.sh)" >&2; exit 77; }

mkdir -p "$cache"
if [ ! -s "$tar_file" ] || [ -n "$(find "$tar_file" -mtime +30)" ]; then
    fresh=$(mktemp -d "$cache/fresh.XXXXXX")
    trap 'rm -rf "$fresh"' EXIT
    echo "clean_chroot: debootstrap bookworm (minbase) into the cache" >&2
    if ! debootstrap --variant=minbase bookworm "$fresh/root" >"$fresh/log" 2>&1; then
        tail -n 20 "$fresh/log" >&2
        echo "clean_chroot: debootstrap failed (no Debian mirror reachable?)" >&2
        exit 1
    fi
    tar -C "$fresh/root" -cf "$fresh/root.tar" .
    mv "$fresh/root.tar" "$tar_file"   # atomic: a concurrent run sees the old or the new tar
fi
mkdir -p "$dir"
tar -C "$dir" -xf "$tar_file"
# Start no service from a maintainer script in the chroot (invoke-rc.d, deb-systemd-invoke).
printf '#!/bin/sh\nexit 101\n' >"$dir/usr/sbin/policy-rc.d"
chmod 0755 "$dir/usr/sbin/policy-rc.d"
cp /etc/resolv.conf "$dir/etc/resolv.conf"

#!/usr/bin/env bash
# Installs everything Tactus needs to build, test and run on Debian 12.
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  SUDO=sudo
fi
packages=(
  build-essential cmake ninja-build pkg-config clang-16 libclang-rt-16-dev
  liblouis-dev liblouis-bin liblouis-data
  libserialport-dev libhidapi-dev libieee1284-3-dev libsqlite3-dev
  libpugixml-dev libpng-dev libjpeg62-turbo-dev nlohmann-json3-dev libcli11-dev libuchardet-dev libicu-dev
  libmd4c-dev libzip-dev libgumbo-dev pandoc libgtest-dev libgmock-dev googletest libeigen3-dev
  qt6-base-dev qt6-charts-dev qt6-svg-dev qt6-tools-dev qt6-tools-dev-tools
  qt6-l10n-tools libgl-dev
  libxml2-utils bible-kjv time
  # The word-recall check of DOCX and ODT import (tests/import/word_recall.py).
  pandoc
  cups-daemon cups-client cups-bsd libcups2-dev
  help2man desktop-file-utils appstream appstream-util lintian dpkg-dev file man-db
  # The .deb test installs the package into a clean Debian 12 chroot.
  debootstrap
  xvfb xauth xdotool at-spi2-core python3-pyatspi dbus dbus-x11 imagemagick
  # The Orca-in-the-loop tests (tests/accessibility/orca_*.py): the real screen
  # reader and a window manager, which window activation events need.
  orca openbox
  # The 89C52 firmware (firmware/): SDCC, and the s51 emulator with its pty bridge.
  sdcc sdcc-ucsim socat
  # The Windows build made here and its installer checked under Wine
  # (tools/windows-build.sh, tools/windows-installer-check.sh).
  g++-mingw-w64-x86-64 libz-mingw-w64-dev nsis wine64
)
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq "${packages[@]}" >/dev/null

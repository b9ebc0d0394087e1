# SPDX-License-Identifier: GPL-3.0-or-later
# liblouis is not in vcpkg's registry. The library is built from the sources
# Tactus keeps in third_party/liblouis by the same small CMake project the
# MinGW build uses (cmake/windows-deps/liblouis), so every Windows build
# translates with the same code; its tables come from the same release tag,
# which third_party/ does not keep (the Linux and MinGW builds read Debian's
# liblouis-data).
set(VCPKG_LIBRARY_LINKAGE static)
set(TACTUS_ROOT "${CMAKE_CURRENT_LIST_DIR}/../../../..")

vcpkg_from_git(
    OUT_SOURCE_PATH TABLES_SOURCE
    URL https://github.com/liblouis/liblouis
    REF f628d16ab5fb82160e92b07fe4d9ed96fbab325e  # v3.24.0, as third_party/README.md
)

vcpkg_cmake_configure(
    SOURCE_PATH "${TACTUS_ROOT}/cmake/windows-deps/liblouis"
    # liblouis.pc's tablesdir: where Tactus's configure step finds the tables.
    OPTIONS "-DLOUIS_TABLESDIR=\${prefix}/share/liblouis/tables"
)
vcpkg_cmake_install()
file(INSTALL "${TABLES_SOURCE}/tables/" DESTINATION "${CURRENT_PACKAGES_DIR}/share/liblouis/tables")
vcpkg_fixup_pkgconfig()
file(REMOVE_RECURSE "${CURRENT_PACKAGES_DIR}/debug/include")
vcpkg_install_copyright(FILE_LIST "${TACTUS_ROOT}/third_party/liblouis/COPYING.LESSER")

# SPDX-License-Identifier: GPL-3.0-or-later
# libserialport is not in vcpkg's registry: built from the sources Tactus
# keeps in third_party/libserialport by the MinGW build's own small CMake
# project (cmake/windows-deps/libserialport), Windows backend only.
set(VCPKG_LIBRARY_LINKAGE static)
set(TACTUS_ROOT "${CMAKE_CURRENT_LIST_DIR}/../../../..")
vcpkg_cmake_configure(SOURCE_PATH "${TACTUS_ROOT}/cmake/windows-deps/libserialport")
vcpkg_cmake_install()
vcpkg_fixup_pkgconfig()
file(REMOVE_RECURSE "${CURRENT_PACKAGES_DIR}/debug/include")
vcpkg_install_copyright(FILE_LIST "${TACTUS_ROOT}/third_party/libserialport/COPYING")

# Included by cpack through CPACK_PROJECT_CONFIG_FILE (written by CMakeLists.txt, which sets
# CASTELJAU_ELF_FILES: the build tree's `casteljau` program, the two modules it carries inside
# it (apps/cli/module_images.cpp) and, when built, the Python module). Runs dpkg-shlibdeps on those and prepends their
# shared-library dependencies to CPACK_DEBIAN_PACKAGE_DEPENDS. CPack's own
# CPACK_DEBIAN_PACKAGE_SHLIBDEPS runs `file` on every packaged file first (about 120,
# mostly headers: about 11 s of CPU of the 13 s a package took, measured in session 12);
# dpkg-shlibdeps itself takes under 2 s.
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
find_program(CASTELJAU_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT CASTELJAU_DPKG_SHLIBDEPS)
  message(FATAL_ERROR "the Debian package needs dpkg-shlibdeps (Debian package dpkg-dev: scripts/install-deps.sh)")
endif()
set(existing)
foreach(elf IN LISTS CASTELJAU_ELF_FILES)
  if(EXISTS "${elf}")
    list(APPEND existing "${elf}")
  endif()
endforeach()
if(NOT existing)
  return()  # a package without the program and the module (headers and static libraries)
endif()
# dpkg-shlibdeps reads debian/control from its working directory.
set(work "${CPACK_PACKAGE_DIRECTORY}/_CPack_Packages/shlibdeps")
file(MAKE_DIRECTORY "${work}/debian")
file(WRITE "${work}/debian/control" "Source: ${CPACK_PACKAGE_NAME}\n\nPackage: ${CPACK_PACKAGE_NAME}\nArchitecture: any\n")
execute_process(COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C ${CASTELJAU_DPKG_SHLIBDEPS} --ignore-missing-info -O ${existing}
                WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "shlibs:Depends=")
  message(FATAL_ERROR "dpkg-shlibdeps failed (${rc}) on ${existing}:\n${out}\n${err}")
endif()
string(REGEX REPLACE ".*shlibs:Depends=([^\n]*).*" "\\1" shlibs "${out}")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${shlibs}, ${CPACK_DEBIAN_PACKAGE_DEPENDS}")

# Installs the build tree into a scratch prefix, then configures, builds and runs the
# consumer example against it with find_package(casteljau): the package config works
# for a user's project, and the installed `casteljau` program answers a request and starts
# the server. Then builds the Debian package (CPack, as `make package`) and checks that it holds exactly
# the files `cmake --install` lays out, under /usr, and that its program runs.
# Run as: cmake -DBUILD_DIR=.. -DSOURCE_DIR=.. -DWORK_DIR=.. -P check_install.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

# The program's answer to one request; the midpoint of the cubic below is (2, 1.5) by
# de Casteljau (1/8 (0 + 3 + 9 + 4), 1/8 (0 + 6 + 6 + 0)).
set(request "${WORK_DIR}/request.json")
file(WRITE "${request}" [=[{"curve": {"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}, "t": [0.5]}]=])
function(check_program exe)
  run("${exe}" eval "${request}")
  if(NOT run_output MATCHES [=[^{"points":\[\[2\.0,1\.5\]\]}]=])
    message(FATAL_ERROR "${exe} eval answered: ${run_output}")
  endif()
endfunction()

# `casteljau serve` loads its module (casteljau-serve.so, carried inside the program: one file
# installed): the server starts and prints its address, and is stopped as soon as it has (at
# most 5 s later; a fixed `timeout 3` held a test slot idle for 3 s per check). The shell
# answers 0 only if the address came and the server was still running when stopped.
set(serve_log "${WORK_DIR}/serve.log")
function(check_serve exe)
  execute_process(COMMAND sh -c [=[
"$1" serve --port 0 >"$2" 2>&1 & pid=$!
i=0
while [ $i -lt 100 ] && ! grep -q "http://" "$2"; do sleep 0.05; i=$((i + 1)); done
kill $pid 2>/dev/null || exit 3
wait $pid
grep -q "http://" "$2"]=] sh "${exe}" "${serve_log}" RESULT_VARIABLE rc)
  file(READ "${serve_log}" out)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^casteljau serve: http://127\\.0\\.0\\.1:[0-9]+/")
    message(FATAL_ERROR "${exe} serve (${rc}): ${out}")
  endif()
endfunction()

# `casteljau glyph` loads the fonts module (casteljau-fonts.so, inside the program too): the
# outline of a space in DejaVu Sans is empty, its advance 651 font units.
set(glyph_request "${WORK_DIR}/glyph.json")
file(WRITE "${glyph_request}" [=[{"font": "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "text": " "}]=])
function(check_glyph exe)
  run("${exe}" glyph "${glyph_request}")
  if(NOT run_output MATCHES [=["advance":651\.0,"curve":null]=])
    message(FATAL_ERROR "${exe} glyph answered: ${run_output}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
check_program("${prefix}/bin/casteljau")
check_serve("${prefix}/bin/casteljau")
check_glyph("${prefix}/bin/casteljau")
# No build type (no optimisation): the check is that the package's targets configure, compile
# and link; -O3 would only add about 8 s of CPU to every make test. With clang (installed for
# the sanitizer build) when present: 8.4 s of CPU against g++'s 13.4 s (session 12); the
# headers meet g++ in every other build.
find_program(clangxx clang++)
set(compiler)
if(clangxx)
  set(compiler -DCMAKE_CXX_COMPILER=${clangxx})
endif()
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/consumer" -B "${consumer_build}"
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE= ${compiler})
run(${CMAKE_COMMAND} --build "${consumer_build}")
run("${consumer_build}/consumer")
message(STATUS "${run_output}")

# The Debian package.
set(deb_dir "${WORK_DIR}/deb")
file(MAKE_DIRECTORY "${deb_dir}")
execute_process(COMMAND cpack -G DEB -B "${deb_dir}" --config "${BUILD_DIR}/CPackConfig.cmake"
                WORKING_DIRECTORY "${BUILD_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cpack failed (${rc}):\n${out}\n${err}")
endif()
file(GLOB debs "${deb_dir}/casteljau_*.deb")
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one casteljau_*.deb in ${deb_dir}, found: ${debs}")
endif()
run(dpkg-deb --field "${debs}" Package Depends)
# libc6, libstdc++6 and libharfbuzz0b from dpkg-shlibdeps on the program and its modules (the
# fonts module links HarfBuzz for glyph kerning), libeigen3-dev from the package's declared list.
if(NOT run_output MATCHES "Package: casteljau" OR NOT run_output MATCHES "libeigen3-dev" OR NOT run_output MATCHES "libc6 \\(>="
   OR NOT run_output MATCHES "libstdc\\+\\+6 \\(>=" OR NOT run_output MATCHES "libharfbuzz0b")
  message(FATAL_ERROR "unexpected package fields:\n${run_output}")
endif()
set(root "${WORK_DIR}/deb_root")
run(dpkg-deb -x "${debs}" "${root}")
file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
file(GLOB_RECURSE packaged RELATIVE "${root}/usr" "${root}/usr/*")
list(SORT installed)
list(SORT packaged)
if(NOT installed STREQUAL packaged)
  message(FATAL_ERROR "the package's files under /usr differ from cmake --install's:\ninstall: ${installed}\npackage: ${packaged}")
endif()
check_program("${root}/usr/bin/casteljau")
check_serve("${root}/usr/bin/casteljau")
check_glyph("${root}/usr/bin/casteljau")

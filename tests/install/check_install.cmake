# Installs the build tree into a scratch prefix (cmake --install), builds the Debian package
# (CPack, as `make package`) and installs it as a user does, with dpkg, into a scratch root
# whose dpkg database is a copy of this machine's: dpkg checks the package's Depends against
# the packages really installed and its files against theirs, without touching the system.
# Then: the package's files are those `cmake --install` laid out, under /usr; every shared
# library its ELF files (and the modules the program carries inside it) need belongs to a
# Debian package named in Depends (objdump, ldd and dpkg-query: not dpkg-shlibdeps, which
# wrote the field); its program answers --version, --help, a request, `serve` and `glyph`;
# its Python module imports and evaluates; examples/consumer configures, builds and runs
# against its headers and CMake package (find_package(casteljau)); dpkg removes it, leaving
# no file.
# Run as: cmake -DBUILD_DIR=.. -DSOURCE_DIR=.. -DWORK_DIR=.. -DMODULES=a.so;b.so -P check_install.cmake
# (MODULES: the server and fonts modules the program embeds; PYTHON: the interpreter, when
# the package carries the Python module).
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

# The program is checked once, from the package: its files are cmake --install's (below).
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")

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
set(fields "${run_output}")
if(NOT fields MATCHES "Package: casteljau\n")
  message(FATAL_ERROR "unexpected package fields:\n${fields}")
endif()
string(REGEX REPLACE ".*Depends: ([^\n]*).*" "\\1" depends "${fields}")
# The development packages a user's project needs (casteljauConfig.cmake finds them; HarfBuzz
# through pkg-config), and the interpreter the Python module was built for.
foreach(needed libeigen3-dev nlohmann-json3-dev libpugixml-dev libfreetype-dev libharfbuzz-dev pkg-config)
  if(NOT depends MATCHES "(^|, )${needed}( |,|$)")
    message(FATAL_ERROR "Depends lacks ${needed}: ${depends}")
  endif()
endforeach()
if(PYTHON AND NOT depends MATCHES "python3 \\(>= [0-9.]+~\\), python3 \\(<< [0-9.]+\\), python3-numpy")
  message(FATAL_ERROR "Depends lacks the Python module's interpreter and numpy: ${depends}")
endif()

# The scratch root: a copy of this machine's dpkg database (the status of every package, their
# file lists, diversions, stat overrides and trigger interests; not the lock files, which only
# root may read) and, of the package's directories, those this machine has (/usr, /usr/bin,
# ...), each holding a file as it does here: dpkg neither creates nor removes them (on a
# scratch root without them it rewrites the file list of every package that owns one, about
# 950 files with two fsyncs each: 5-8 s idle per install or removal). dpkg runs as it would
# for a user, with these differences: --root (the scratch root and its database),
# --force-not-root (CI may run unprivileged; as root it changes nothing), --no-triggers (no
# other package's trigger runs; the package has no maintainer scripts, so nothing is run in
# or outside the root), its log in the work directory (not /var/log/dpkg.log). The sbin
# directories join PATH: dpkg refuses to run without ldconfig and start-stop-daemon on it (an
# unprivileged PATH often lacks them). cp copies the 950 file lists in 0.15 s, file(COPY) in 1.3 s.
set(root "${WORK_DIR}/dpkg-root")
set(admin "${root}/var/lib/dpkg")
file(MAKE_DIRECTORY "${admin}/updates" "${admin}/info" "${admin}/triggers")
foreach(f status diversions statoverride)
  if(EXISTS "/var/lib/dpkg/${f}")
    file(COPY "/var/lib/dpkg/${f}" DESTINATION "${admin}")
  endif()
endforeach()
file(GLOB lists "/var/lib/dpkg/info/*.list")
run(cp ${lists} "${admin}/info")
file(GLOB triggers "/var/lib/dpkg/triggers/*")
list(FILTER triggers EXCLUDE REGEX "/Lock$")
if(triggers)
  run(cp ${triggers} "${admin}/triggers")
endif()
file(GLOB_RECURSE directories LIST_DIRECTORIES true RELATIVE "${prefix}" "${prefix}/*")
foreach(d "" ${directories})
  if(IS_DIRECTORY "${prefix}/${d}" AND IS_DIRECTORY "/usr/${d}")
    file(WRITE "${root}/usr/${d}/.placeholder" "")
  endif()
endforeach()
set(dpkg ${CMAKE_COMMAND} -E env "PATH=$ENV{PATH}:/usr/sbin:/sbin" dpkg "--root=${root}" --force-not-root
    --no-triggers "--log=${WORK_DIR}/dpkg.log")
run(${dpkg} --install "${debs}")
run(dpkg-query "--admindir=${admin}" --show "--showformat=\${Status}" casteljau)
if(NOT run_output STREQUAL "install ok installed")
  message(FATAL_ERROR "dpkg left the package ${run_output}")
endif()

file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
file(GLOB_RECURSE packaged RELATIVE "${root}/usr" "${root}/usr/*")
list(FILTER packaged EXCLUDE REGEX "(^|/)\\.placeholder$")
list(SORT installed)
list(SORT packaged)
if(NOT installed STREQUAL packaged)
  message(FATAL_ERROR "the package's files under /usr differ from cmake --install's:\ninstall: ${installed}\npackage: ${packaged}")
endif()

set(exe "${root}/usr/bin/casteljau")
# Depends names the owner of every shared library an ELF file of the package needs directly
# (its NEEDED entries, resolved by ldd; the system's files under /lib are /usr/lib's on a
# merged /usr, and dpkg knows each under one of the two names).
file(GLOB elves "${exe}" "${root}/usr/lib/python3/dist-packages/casteljau/*.so")
list(APPEND elves ${MODULES})
set(libraries)
foreach(elf IN LISTS elves)
  run(objdump -p "${elf}")
  string(REGEX MATCHALL "NEEDED +[^\n]+" needed "${run_output}")
  run(ldd "${elf}")
  set(resolved "${run_output}")
  foreach(entry IN LISTS needed)
    string(REGEX REPLACE "NEEDED +" "" name "${entry}")
    string(REGEX REPLACE "([.+])" "\\\\\\1" name_pattern "${name}")
    if(name MATCHES "/")
      set(path "${name}")
    elseif(resolved MATCHES "\t${name_pattern} => ([^ ]+) ")
      set(path "${CMAKE_MATCH_1}")
    elseif(resolved MATCHES "\t(/[^ ]*/${name_pattern}) \\(")  # the dynamic loader
      set(path "${CMAKE_MATCH_1}")
    else()
      message(FATAL_ERROR "ldd does not resolve ${name}, needed by ${elf}:\n${resolved}")
    endif()
    list(APPEND libraries "${path}")
  endforeach()
endforeach()
list(REMOVE_DUPLICATES libraries)
set(candidates)
foreach(path IN LISTS libraries)
  string(REGEX REPLACE "^/usr/" "/" other "${path}")
  if(other STREQUAL path)
    set(other "/usr${path}")
  endif()
  list(APPEND candidates "${path}" "${other}")
endforeach()
# dpkg-query answers 1 when some of the names are nobody's; each library is checked below.
execute_process(COMMAND dpkg-query --search ${candidates} OUTPUT_VARIABLE owners ERROR_QUIET)
foreach(path IN LISTS libraries)
  string(REGEX REPLACE "^/usr/" "/" short "${path}")
  string(REGEX REPLACE "([.+])" "\\\\\\1" short "${short}")
  if(NOT owners MATCHES "(^|\n)([^:\n, ]+)(:[a-z0-9]+)?: (/usr)?${short}\n")
    message(FATAL_ERROR "no Debian package holds ${path}:\n${owners}")
  endif()
  set(owner "${CMAKE_MATCH_2}")
  string(REGEX REPLACE "([.+])" "\\\\\\1" owner_pattern "${owner}")
  if(NOT depends MATCHES "(^|, )${owner_pattern}( |,|$)")
    message(FATAL_ERROR "${path} belongs to ${owner}, which Depends lacks: ${depends}")
  endif()
endforeach()

run("${exe}" --version)
if(NOT run_output MATCHES "^casteljau [0-9]+\\.[0-9]+\\.[0-9]+\n$")
  message(FATAL_ERROR "${exe} --version answered: ${run_output}")
endif()
run("${exe}" --help)
if(NOT run_output MATCHES "Usage: casteljau" OR NOT run_output MATCHES "\n  eval ")
  message(FATAL_ERROR "${exe} --help answered: ${run_output}")
endif()
check_program("${exe}")
check_serve("${exe}")
check_glyph("${exe}")

# The Python module from the package, with the package's directory first on the path: the
# cubic's midpoint again.
if(PYTHON)
  run(${CMAKE_COMMAND} -E env "PYTHONPATH=${root}/usr/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1
      "${PYTHON}" -c "import casteljau\nprint(casteljau.__file__)\nprint(casteljau.Bezier([[0, 0], [1, 2], [3, 2], [4, 0]])(0.5).tolist())")
  if(NOT run_output STREQUAL "${root}/usr/lib/python3/dist-packages/casteljau/__init__.py\n[2.0, 1.5]\n")
    message(FATAL_ERROR "the package's Python module answered: ${run_output}")
  endif()
endif()

# A user's project against the package's headers and CMake package. No build type (no
# optimisation): the check is that the package's targets configure, compile and link; -O3
# would only add about 8 s of CPU to every make test. With clang (installed for the sanitizer
# build) when present: 8.4 s of CPU against g++'s 13.4 s (session 12); the headers meet g++ in
# every other build.
find_program(clangxx clang++)
set(compiler)
if(clangxx)
  set(compiler -DCMAKE_CXX_COMPILER=${clangxx})
endif()
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/consumer" -B "${consumer_build}"
    -DCMAKE_PREFIX_PATH=${root}/usr -DCMAKE_BUILD_TYPE= ${compiler})
run(${CMAKE_COMMAND} --build "${consumer_build}")
run("${consumer_build}/consumer")
message(STATUS "${run_output}")

run(${dpkg} --remove casteljau)
file(GLOB_RECURSE left "${root}/usr/*")
list(FILTER left EXCLUDE REGEX "/\\.placeholder$")
if(left)
  message(FATAL_ERROR "dpkg --remove left: ${left}")
endif()

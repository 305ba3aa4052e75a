# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCOMPILER=... [-DLAUNCHER=...]
#       [-DCXX_FLAGS=...] [-DLINKER_FLAGS=...] -P install_test.cmake
# Installs this build into a fresh prefix, then checks what a user and a packager get from it:
# 1. the installed program, run from an unrelated folder with no data folder named, lists the lessons of its own
#    prefix's share/impulse-lab and resolves a shipped case from there;
# 2. a small project of someone else's (consumer/) configures with find_package(impulse-lab), builds against the
#    installed engine and formats libraries and headers, and resolves a case: the sphere of sphere_ground.json
#    leaves at 2.5 m/s (5 m/s in, restitution 0.5: v' = -c v = 2.5, the case's own description).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error
                  WORKING_DIRECTORY ${WORK_DIR}/elsewhere)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "${command} failed (${result}):\n${output}\n${error}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/elsewhere)
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

foreach(file bin/impulse-lab share/impulse-lab/lessons/01-impulse-is-a-velocity-change.md
        share/impulse-lab/scenes/cases/ruler.json share/impulse-lab/schemas/trace.schema.json
        share/impulse-lab/docs/trace-format.md share/man/man1/impulse-lab.1
        share/bash-completion/completions/impulse-lab share/doc/impulse-lab/LICENSE
        include/impulse-lab/world/world.hpp include/impulse-lab/formats/scene_file.hpp
        lib/cmake/impulse-lab/impulse-lab-config.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "the install holds no ${file}")
  endif()
endforeach()

# 1. The program finds its data from its own location, not from the build or the checkout.
set(ENV{IMPULSE_LAB_DATA_DIR} "")
set(ENV{XDG_CONFIG_HOME} ${WORK_DIR}/config)
run(${prefix}/bin/impulse-lab lesson)
if(NOT output MATCHES "Lessons in ${prefix}/share/impulse-lab/lessons" OR NOT output MATCHES "13  Friction against")
  message(FATAL_ERROR "the installed program did not list its own lessons:\n${output}")
endif()
run(${prefix}/bin/impulse-lab resolve ${prefix}/share/impulse-lab/scenes/cases/sphere_ground.json)

# 2. A consumer project against the installed libraries.
set(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${COMPILER} -DCMAKE_BUILD_TYPE=Release)
if(LAUNCHER)
  list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
if(CXX_FLAGS)
  list(APPEND configure "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
endif()
run(${configure})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/consumer ${prefix}/share/impulse-lab/scenes/cases/sphere_ground.json)
if(NOT output STREQUAL "velocity after: 0.000000 2.500000 0.000000\n")
  message(FATAL_ERROR "the consumer resolved the case wrongly: ${output}")
endif()
message(STATUS "installed into ${prefix}; the program found its lessons; the consumer printed ${output}")

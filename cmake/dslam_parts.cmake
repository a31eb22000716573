# dslam_part(): declares one part of dslam (a folder under src/, include/dslam/ and test/) and
# checks the layering rule at configure time.
#
#   dslam_part(NAME [DEPENDS part...])
#
# Sets DSLAM_<NAME>_DEPENDS (the direct dependencies, as library targets dslam_<part>) and
# DSLAM_<NAME>_ALLOWED (the part itself and every part below it, transitively), then adds
# src/<NAME>/CMakeLists.txt (the library) and, with testing on, test/<NAME>/CMakeLists.txt.
# The build fails when a file in src/<NAME>/ or include/dslam/<NAME>/ includes a header of a part
# outside DSLAM_<NAME>_ALLOWED, or when a part other than `ros` includes a ROS header.

set(DSLAM_ROS_HEADER_REGEX
  "#include [<\"](ros|nodelet|pluginlib|tf2_ros|tf2_eigen|cv_bridge|image_transport|message_filters|sensor_msgs|nav_msgs|geometry_msgs|visualization_msgs|std_msgs|std_srvs|pcl_conversions|dslam/[A-Z][A-Za-z]*\\.h)")

function(dslam_check_includes name)
  file(GLOB_RECURSE files CONFIGURE_DEPENDS
    ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp ${PROJECT_SOURCE_DIR}/src/${name}/*.h
    ${PROJECT_SOURCE_DIR}/include/dslam/${name}/*.h)
  foreach(file ${files})
    file(STRINGS ${file} lines REGEX "^#include [<\"]dslam/")
    foreach(line ${lines})
      if(line MATCHES "^#include [<\"]dslam/([a-z_]+)/")
        list(FIND DSLAM_${name}_ALLOWED ${CMAKE_MATCH_1} found)
        if(found EQUAL -1)
          message(FATAL_ERROR "layering: ${file} includes part '${CMAKE_MATCH_1}', which part "
                              "'${name}' may not use (allowed: ${DSLAM_${name}_ALLOWED})")
        endif()
      endif()
    endforeach()
    if(NOT name STREQUAL "ros")
      file(STRINGS ${file} ros_lines REGEX "${DSLAM_ROS_HEADER_REGEX}")
      if(ros_lines)
        message(FATAL_ERROR "layering: ${file} (part '${name}') includes ROS: ${ros_lines}")
      endif()
    endif()
  endforeach()
endfunction()

macro(dslam_part name)
  cmake_parse_arguments(DSLAM_PART "" "" "DEPENDS" ${ARGN})
  set(DSLAM_${name}_DEPENDS "")
  set(DSLAM_${name}_ALLOWED ${name})
  foreach(dep ${DSLAM_PART_DEPENDS})
    if(NOT DEFINED DSLAM_${dep}_ALLOWED)
      message(FATAL_ERROR "part '${name}' depends on '${dep}', which is not declared before it")
    endif()
    list(APPEND DSLAM_${name}_DEPENDS dslam_${dep})
    list(APPEND DSLAM_${name}_ALLOWED ${DSLAM_${dep}_ALLOWED})
  endforeach()
  list(REMOVE_DUPLICATES DSLAM_${name}_ALLOWED)
  dslam_check_includes(${name})
  add_subdirectory(src/${name})
  if(CATKIN_ENABLE_TESTING AND EXISTS ${PROJECT_SOURCE_DIR}/test/${name}/CMakeLists.txt)
    add_subdirectory(test/${name})
  endif()
endmacro()

# DSLAM_SANITIZE (cache variable: thread, address, undefined or empty): every dslam library, tool
# and gtest is compiled with the kind's -fsanitize flags, -g -O1 and linked with them; per target,
# never a global flag, so gtest and other packages built in the workspace stay as they are.
#   thread     -fsanitize=thread
#   address    -fsanitize=address,undefined,float-cast-overflow with -fno-sanitize-recover for the
#              UB checks: AddressSanitizer (and LeakSanitizer) plus UndefinedBehaviorSanitizer,
#              where undefined behaviour aborts the program like a memory error (a report that
#              cannot be overlooked); float-cast-overflow (a double out of an int's range cast to
#              int) is not in GCC's `undefined` group.
#   undefined  the UB part of `address` alone.
# scripts/sanitize.sh configures it in a workspace of its own (build/tsan, build/asan, ...).
set(DSLAM_SANITIZE "" CACHE STRING "sanitizer of the dslam targets: thread, address, undefined")
if(DSLAM_SANITIZE AND NOT DSLAM_SANITIZE MATCHES "^(thread|address|undefined)$")
  message(FATAL_ERROR "DSLAM_SANITIZE=${DSLAM_SANITIZE}: use thread, address or undefined")
endif()
set(DSLAM_UB_CHECKS undefined,float-cast-overflow)
if(DSLAM_SANITIZE STREQUAL "address")
  set(DSLAM_SANITIZE_FLAGS
    -fsanitize=address,${DSLAM_UB_CHECKS} -fno-sanitize-recover=${DSLAM_UB_CHECKS})
elseif(DSLAM_SANITIZE STREQUAL "undefined")
  set(DSLAM_SANITIZE_FLAGS
    -fsanitize=${DSLAM_UB_CHECKS} -fno-sanitize-recover=${DSLAM_UB_CHECKS})
elseif(DSLAM_SANITIZE)
  set(DSLAM_SANITIZE_FLAGS -fsanitize=${DSLAM_SANITIZE})
endif()

# DSLAM_NODE_ALLOCATOR: the link items that make jemalloc (Debian's libjemalloc-dev) the malloc of
# dslam_odometry_node, linked first and kept although the node calls none of its functions by
# name, so that its malloc serves the whole process: glibc's malloc fragments over hours of frames
# (the long run's resident size grew 1.1 MB a minute with a flat heap; TESTING.md "Long run of the
# ROS node"). Empty in sanitizer builds, which keep the sanitizer's malloc.
find_library(DSLAM_JEMALLOC_LIBRARY NAMES jemalloc)
if(NOT DSLAM_JEMALLOC_LIBRARY)
  message(FATAL_ERROR "jemalloc not found: install Debian's libjemalloc-dev (scripts/setup.sh)")
endif()
set(DSLAM_NODE_ALLOCATOR)
if(NOT DSLAM_SANITIZE)
  # --export-dynamic-symbol: jemalloc finds the executable's malloc_conf (its options) only in
  # the dynamic symbol table.
  set(DSLAM_NODE_ALLOCATOR
    -Wl,--push-state,--no-as-needed ${DSLAM_JEMALLOC_LIBRARY} -Wl,--pop-state
    -Wl,--export-dynamic-symbol=malloc_conf)
endif()

function(dslam_sanitize target)
  if(DSLAM_SANITIZE)
    target_compile_options(${target} PRIVATE ${DSLAM_SANITIZE_FLAGS} -g -O1 -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE ${DSLAM_SANITIZE_FLAGS})
  endif()
endfunction()

# dslam_test(NAME SOURCES... LIBRARIES libs...): a gtest of the part's test folder, linked with
# gtest_main; tests include their shared helpers as "support/..." and "<part>/...".
function(dslam_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBRARIES" ${ARGN})
  catkin_add_gtest(${name} ${T_SOURCES})
  target_link_libraries(${name} ${T_LIBRARIES} gtest_main)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/test)
  # DSLAM_SOURCE_DIR (the repository's path, for tests that read its files) only on the sources
  # that use it or include a helper that does: an absolute path in the command line keeps
  # ccache from reusing an object compiled in another checkout (scripts/workspace.sh sets
  # CCACHE_BASEDIR for the others).
  foreach(source ${T_SOURCES})
    file(STRINGS ${CMAKE_CURRENT_SOURCE_DIR}/${source} uses
         REGEX "DSLAM_SOURCE_DIR|fuzz/replay.h|support/generated_block.h|support/message_fields.h")
    if(uses)
      set_property(SOURCE ${source} APPEND PROPERTY
        COMPILE_DEFINITIONS DSLAM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    endif()
  endforeach()
  dslam_sanitize(${name})
endfunction()

# dslam_library(PART SOURCES... [LINK libs...]): the part's library dslam_<PART>, linked with the
# libraries of the parts it DEPENDS on (public) and LINK (external libraries), and installed.
function(dslam_library part)
  cmake_parse_arguments(L "" "" "SOURCES;LINK" ${ARGN})
  add_library(dslam_${part} ${L_SOURCES})
  target_include_directories(dslam_${part} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  target_link_libraries(dslam_${part} PUBLIC ${DSLAM_${part}_DEPENDS} ${L_LINK})
  # Every symbol resolved at link time: a declaration defined in another part's library that
  # this one does not link fails the build, not the nodelet's loading.
  target_link_options(dslam_${part} PRIVATE -Wl,--no-undefined)
  # Calls inside the library bind to its own functions (no interposition by another shared
  # object), so GCC may inline them: CGAL's Delaunay code in dslam_static_points runs about 1.3x
  # faster (docs/benchmarks/speed.md, "Delaunay graph"); results are the same.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(dslam_${part} PRIVATE -fno-semantic-interposition)
  endif()
  dslam_sanitize(dslam_${part})
  install(TARGETS dslam_${part}
    ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
    LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
    RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
endfunction()

# dslam_tool(NAME SOURCES... LINK libs...): an executable NAME installed to the package's lib
# folder (`rosrun dslam NAME`). Its target is NAME_main (dslam_eval and dslam_synth are also
# the names of part libraries).
function(dslam_tool name)
  cmake_parse_arguments(E "" "" "SOURCES;LINK" ${ARGN})
  add_executable(${name}_main ${E_SOURCES})
  set_target_properties(${name}_main PROPERTIES OUTPUT_NAME ${name})
  target_link_libraries(${name}_main ${E_LINK})
  dslam_sanitize(${name}_main)
  install(TARGETS ${name}_main RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endfunction()

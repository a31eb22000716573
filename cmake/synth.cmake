# Area `synth`: synthetic RGB-D sequences with exact ground truth (dslam_synth).
target_sources(dslam_core PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_actors.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_camera_motion.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_geometry.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_pattern.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_render.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_room.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_scenario.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_sensor.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_sequence.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_texture.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_walker.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synth_writer.cpp)

add_executable(dslam_synth ${CMAKE_CURRENT_SOURCE_DIR}/src/tools/synth_main.cpp)
target_link_libraries(dslam_synth dslam_core)
list(APPEND DSLAM_TOOLS dslam_synth)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_synth
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/synth_render_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/synth_sequence_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/synth_texture_test.cpp)
  target_link_libraries(test_synth dslam_core gtest_main)
endif()

# Area eval: ground-truth corrections, trajectory metrics (ATE, RPE, coverage), dslam_eval tool.
target_sources(dslam_core PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/groundtruth_correction.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/trajectory_metrics.cpp)

add_executable(dslam_eval ${CMAKE_CURRENT_SOURCE_DIR}/src/tools/eval_main.cpp)
target_link_libraries(dslam_eval dslam_core)
list(APPEND DSLAM_TOOLS dslam_eval)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_eval
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/groundtruth_correction_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/trajectory_metrics_test.cpp)
  target_link_libraries(test_eval dslam_core gtest_main)
endif()

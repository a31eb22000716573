# Odometry front end: local map, tracking, front-end static points, offline runner.
target_sources(dslam_core PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/front_end_static_points.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/local_map_matching.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/map_point_creation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/motion_model.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/odometry.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/odometry_steps.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/pose_estimation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/run_statistics.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/segmentation_score.cpp)

add_executable(dslam_run_dataset ${CMAKE_CURRENT_SOURCE_DIR}/src/tools/run_dataset_main.cpp)
target_link_libraries(dslam_run_dataset dslam_core)
list(APPEND DSLAM_TOOLS dslam_run_dataset)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_odometry
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/motion_model_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/segmentation_score_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/static_labels_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/map_point_creation_test.cpp)
  target_link_libraries(test_odometry dslam_core gtest_main)
endif()

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_odometry_regression
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/odometry_regression_test.cpp)
  target_link_libraries(test_odometry_regression dslam_core gtest_main)
endif()

# Area `features`: RGB-D point measurement model, ORB extraction, descriptor matching and
# motion-only pose estimation (Ceres). Included by the top-level CMakeLists after dslam_core.
find_package(Ceres REQUIRED)

target_sources(dslam_core PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/depth_uncertainty.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/features.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/matching.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/pose_optimizer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/robust_pose.cpp)
target_link_libraries(dslam_core PRIVATE Ceres::ceres)

add_executable(dslam_features_bench ${CMAKE_CURRENT_SOURCE_DIR}/src/tools/features_bench_main.cpp)
target_link_libraries(dslam_features_bench dslam_core)
list(APPEND DSLAM_TOOLS dslam_features_bench)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_features
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/depth_uncertainty_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/features_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/matching_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/pose_optimizer_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/robust_pose_test.cpp)
  target_link_libraries(test_features dslam_core gtest_main)
endif()

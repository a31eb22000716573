# Area `features`: RGB-D point measurement model, ORB extraction, descriptor matching and
# motion-only pose estimation (Ceres). Included by the top-level CMakeLists after dslam_core.
find_package(Ceres REQUIRED)

target_sources(dslam_core PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/depth_uncertainty.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/features.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/matching.cpp)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_features
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/depth_uncertainty_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/features_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/matching_test.cpp)
  target_link_libraries(test_features dslam_core gtest_main)
endif()

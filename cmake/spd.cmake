# Static point determination (spd): Delaunay graph, inconsistent edge culling, segmentation.
find_package(CGAL REQUIRED)

target_sources(dslam_core PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/point_graph.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/correlation_measurements.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/correlation_problem.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/direct_edge_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/segmentation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/static_points.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/core/synthetic_scene.cpp)
target_link_libraries(dslam_core PRIVATE CGAL::CGAL)

add_executable(dslam_spd_bench ${CMAKE_CURRENT_SOURCE_DIR}/src/tools/spd_bench_main.cpp)
target_link_libraries(dslam_spd_bench dslam_core)
list(APPEND DSLAM_TOOLS dslam_spd_bench)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_spd
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/point_graph_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/correlation_problem_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/segmentation_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/core/static_points_test.cpp)
  target_link_libraries(test_spd dslam_core gtest_main)
endif()

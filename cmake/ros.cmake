# ROS layer: dslam/OdometryNodelet (library dslam_ros), the dslam_odometry_node executable,
# FrameStatus message / SaveTrajectory service (generated in the top-level CMakeLists before
# catkin_package()), gtests of the conversions and rostests under test/rostest/.
add_library(dslam_ros
  ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/conversions.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/frame_publisher.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/odometry_nodelet.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/param_loader.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/visualisation.cpp)
target_include_directories(dslam_ros PUBLIC ${catkin_INCLUDE_DIRS} ${CATKIN_DEVEL_PREFIX}/include)
target_link_libraries(dslam_ros dslam_core ${catkin_LIBRARIES})
add_dependencies(dslam_ros ${PROJECT_NAME}_generate_messages_cpp)

add_executable(dslam_odometry_node ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/odometry_node_main.cpp)
target_include_directories(dslam_odometry_node PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(dslam_odometry_node ${catkin_LIBRARIES})
list(APPEND DSLAM_TOOLS dslam_odometry_node)
list(APPEND DSLAM_PYTHON_TOOLS scripts/bag_runner)
install(TARGETS dslam_ros
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_ros
    ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/conversions_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/latest_slot_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/param_loader_test.cpp)
  target_link_libraries(test_ros dslam_ros gtest_main)
  find_package(rostest REQUIRED)
  add_rostest(${CMAKE_CURRENT_SOURCE_DIR}/test/rostest/odometry_bag.test)
  add_rostest(${CMAKE_CURRENT_SOURCE_DIR}/test/rostest/openni2_remap.test)
endif()

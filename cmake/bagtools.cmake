# bagtools: Python tools for datasets and trajectories (scripts/, see docs/readme/bagtools.md).
#   tum_to_bag       TUM RGB-D folder -> rosbag with the official TUM topics
#   plot_trajectory  estimate vs ground truth PNG with SE(3)-aligned ATE RMSE
# Both import the helper package scripts/dslam_tools (found beside the script in devel and
# install space).
list(APPEND DSLAM_PYTHON_TOOLS scripts/tum_to_bag scripts/plot_trajectory)
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/scripts/dslam_tools
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}
  FILES_MATCHING PATTERN "*.py")

if(CATKIN_ENABLE_TESTING)
  catkin_add_nosetests(${CMAKE_CURRENT_SOURCE_DIR}/test/python/test_bagtools.py)
endif()

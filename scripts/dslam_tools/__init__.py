"""Python helpers shared by dslam's Python tools (tum_to_bag, plot_trajectory) and their tests.

Modules: dataset (TUM folder lists, camera.yaml, exact stamps), trajectory (TUM trajectories,
stamp association, Umeyama SE(3) alignment, ATE, Bonn ground-truth correction), tum_bag (TUM folder
-> rosbag conversion), plotting (trajectory figure), progress (text progress bar).
"""

"""Python helpers shared by dslam's Python tools (tum_to_bag, plot_trajectory) and their tests.

Modules: dataset (TUM folder lists, camera.yaml, exact stamps), trajectory (runs the C++ tool
dslam_eval, which associates, aligns, measures and corrects ground truth, and reads its outputs),
tum_bag (TUM folder -> rosbag conversion), plotting (trajectory figure), progress (text progress
bar), speed_report (the numbers and table of scripts/speed_benchmark.py).
"""

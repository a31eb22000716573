"""Trajectory evaluation for the Python tools, done by the C++ tool dslam_eval.

Stamp association, SE(3) alignment, ATE and the Bonn ground-truth correction exist only in C++
(src/eval/, src/io/, run by src/tools/eval_main.cpp; docs/readme/eval.md); this module runs
dslam_eval and reads back what it writes, so plots, tests and the official numbers always agree.
"""

import json
import os
import subprocess
import sys
import tempfile

import numpy as np

TOOL_NAME = "dslam_eval"


def _candidate_folders():
    """Folders that may hold dslam_eval, most specific first (see find_dslam_eval)."""
    package_folder = os.path.dirname(os.path.abspath(__file__))  # .../dslam_tools
    folders = [os.path.dirname(package_folder)]
    if sys.argv and sys.argv[0]:
        folders.append(os.path.dirname(os.path.abspath(sys.argv[0])))
    try:
        from catkin.find_in_workspaces import find_in_workspaces
        folders.extend(find_in_workspaces(search_dirs=["libexec"], project="dslam"))
    except ImportError:
        pass
    return [f for i, f in enumerate(folders) if f not in folders[:i]]  # first of duplicates


def find_dslam_eval():
    """Path of the dslam_eval executable, looked up in this order:
    1. beside the dslam_tools folder: install space puts the scripts, dslam_tools and the C++
       executables all in lib/dslam (CMakeLists.txt, cmake/dslam_parts.cmake dslam_tool);
    2. beside the running program (sys.argv[0]): in devel space `rosrun dslam plot_trajectory`
       runs devel/lib/dslam/plot_trajectory, catkin's relay to the source script, which sits
       beside the devel-space executables;
    3. the package's libexec folders (lib/dslam) of the sourced workspaces (CMAKE_PREFIX_PATH),
       as `rosrun` finds executables (catkin's find_in_workspaces).
    Raises IOError when none of them holds an executable dslam_eval."""
    folders = _candidate_folders()
    for folder in folders:
        path = os.path.join(folder, TOOL_NAME)
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    raise IOError("%s not found in %s; build the workspace and source its devel/setup.bash" %
                  (TOOL_NAME, ", ".join(folders)))


def read_tum_positions(path):
    """Stamps [N] s and positions [N,3] m of a TUM trajectory file written by dslam_eval
    (`timestamp tx ty tz qx qy qz qw` lines, '#' comments)."""
    rows = np.loadtxt(path, comments="#", ndmin=2).reshape(-1, 8)
    return rows[:, 0], rows[:, 1:4]


def evaluate(groundtruth, trajectory, camera="", max_dt=0.02):
    """Runs dslam_eval on the ground truth and the estimate (TUM files) with --json,
    --write-groundtruth, --save-aligned and --save-groundtruth, and returns a dict:
      metrics      the --json numbers (ate_rmse_m, associated_poses, groundtruth_correction, ...)
      groundtruth  (stamps [N] s, positions [N,3] m): the ground truth after the correction
      aligned      (stamps [M] s, positions [M,3] m): the associated estimated poses moved into
                   the ground truth's world by the ATE alignment
      matched      (stamps [M] s, positions [M,3] m): their ground-truth poses (same order)
      errors       [M] m: |aligned - matched| per pair, from the 6-decimal TUM files
    `camera` is a camera.yaml (its groundtruth_correction is applied) or empty; max_dt is the
    association tolerance [s]. Raises RuntimeError with dslam_eval's message when it fails."""
    with tempfile.TemporaryDirectory(prefix="dslam_eval_") as work:
        out = {name: os.path.join(work, name) for name in
               ("metrics.json", "groundtruth.txt", "aligned.txt", "matched.txt")}
        command = [find_dslam_eval(), "--groundtruth", groundtruth, "--trajectory", trajectory,
                   "--max-dt", repr(float(max_dt)), "--json", out["metrics.json"],
                   "--write-groundtruth", out["groundtruth.txt"],
                   "--save-aligned", out["aligned.txt"], "--save-groundtruth", out["matched.txt"]]
        if camera:
            command += ["--camera", camera]
        process = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 universal_newlines=True)
        if process.returncode != 0:
            raise RuntimeError(process.stderr.strip() or "%s exited with status %d" %
                               (TOOL_NAME, process.returncode))
        with open(out["metrics.json"]) as handle:
            result = {"metrics": json.load(handle)}
        for key in ("groundtruth", "aligned", "matched"):
            result[key] = read_tum_positions(out[key + ".txt"])
    result["errors"] = np.linalg.norm(result["aligned"][1] - result["matched"][1], axis=1)
    return result

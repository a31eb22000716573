"""Figure of an estimated trajectory against ground truth (matplotlib Agg, no display needed)."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

AXIS_NAMES = "xyz"


def choose_plane(positions, plane="auto"):
    """Axis indices (a, b) of the top view: the two axes of `positions` [N,3] with the largest
    extent (max - min), in x-y-z order, for plane 'auto'; else the named plane, e.g. 'xy'."""
    if plane != "auto":
        return tuple(AXIS_NAMES.index(c) for c in plane)
    extent = positions.max(axis=0) - positions.min(axis=0)
    return tuple(sorted(np.argsort(extent)[-2:].tolist()))


def _top_view(axes, gt_xyz, est_xyz, plane):
    a, b = plane
    axes.plot(gt_xyz[:, a], gt_xyz[:, b], "-", color="0.25", lw=1.5, label="ground truth")
    axes.plot(est_xyz[:, a], est_xyz[:, b], "-", color="tab:red", lw=1.2,
              label="estimate (aligned)")
    axes.plot(gt_xyz[0, a], gt_xyz[0, b], "o", color="0.25", ms=6, label="start")
    axes.plot(est_xyz[0, a], est_xyz[0, b], "o", color="tab:red", ms=4)
    axes.set_xlabel("%s [m]" % AXIS_NAMES[a])
    axes.set_ylabel("%s [m]" % AXIS_NAMES[b])
    axes.set_aspect("equal", adjustable="datalim")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize=8)
    axes.set_title("top view (%s-%s plane)" % (AXIS_NAMES[a], AXIS_NAMES[b]))


def _over_time(figure, grid, gt_t, gt_xyz, est_t, est_xyz, errors):
    axes_list = []
    for row in range(3):
        axes = figure.add_subplot(grid[row, 1], sharex=axes_list[0] if axes_list else None)
        axes.plot(gt_t, gt_xyz[:, row], "-", color="0.25", lw=1.5)
        axes.plot(est_t, est_xyz[:, row], "-", color="tab:red", lw=1.0)
        axes.set_ylabel("%s [m]" % AXIS_NAMES[row])
        axes.grid(True, alpha=0.3)
        axes_list.append(axes)
    axes = figure.add_subplot(grid[3, 1], sharex=axes_list[0])
    axes.plot(est_t, errors * 100.0, "-", color="tab:blue", lw=1.0)
    axes.set_ylim(bottom=0.0)
    axes.set_ylabel("error [cm]")
    axes.set_xlabel("time [s]")
    axes.grid(True, alpha=0.3)
    for each in axes_list:
        plt.setp(each.get_xticklabels(), visible=False)


def plot_trajectories(output, result, title="", plane="auto"):
    """Writes a PNG: top view (see choose_plane) and x, y, z and the position error over time
    (seconds since the first ground-truth stamp). `result` is trajectory.evaluate()'s dict: the
    (corrected) ground truth is drawn whole, the estimate as its associated poses aligned to the
    ground truth, the error per associated pose."""
    gt_stamps, gt_xyz = result["groundtruth"]
    est_stamps, est_xyz = result["aligned"]
    origin = gt_stamps[0] if len(gt_stamps) else 0.0
    figure = plt.figure(figsize=(13, 6.5), dpi=100)
    grid = figure.add_gridspec(4, 2, width_ratios=[1.0, 1.25], hspace=0.15, wspace=0.25)
    _top_view(figure.add_subplot(grid[:, 0]), gt_xyz, est_xyz, choose_plane(gt_xyz, plane))
    _over_time(figure, grid, gt_stamps - origin, gt_xyz, est_stamps - origin, est_xyz,
               result["errors"])
    heading = "ATE RMSE %.4f m over %d poses (SE(3) aligned)" % (
        result["metrics"]["ate_rmse_m"], result["metrics"]["associated_poses"])
    figure.suptitle(heading if not title else "%s\n%s" % (title, heading), fontsize=11)
    figure.savefig(output, bbox_inches="tight")
    plt.close(figure)

"""TUM trajectories and the small amount of maths needed to compare two of them.

Poses are 4x4 numpy arrays T_world_camera (map camera-frame points into the world frame),
stamps in seconds. The official metrics come from the C++ tool dslam_eval; these helpers serve
plots and tests.
"""

import numpy as np

# Bonn RGB-D Dynamic dataset: groundtruth.txt holds the motion-capture marker pose. The documented
# camera pose is T_cam = T_ROS * T_gt * T_ROS * T_M (see /work/shared/data/README.md).
BONN_T_ROS = np.array([[-1.0, 0.0, 0.0, 0.0],
                       [0.0, 0.0, 1.0, 0.0],
                       [0.0, 1.0, 0.0, 0.0],
                       [0.0, 0.0, 0.0, 1.0]])
BONN_T_M_RAW = np.array([[1.0157, 0.1828, -0.2389, 0.0113],
                         [0.0009, -0.8431, -0.6413, -0.0098],
                         [-0.3009, 0.6147, -0.8085, 0.0111],
                         [0.0, 0.0, 0.0, 1.0]])


def quaternion_to_matrix(qx, qy, qz, qw):
    """Rotation matrix of a (not necessarily unit) quaternion; raises ValueError for a zero one."""
    q = np.array([qw, qx, qy, qz], dtype=float)
    norm = np.linalg.norm(q)
    if not norm > 1e-9:
        raise ValueError("zero quaternion")
    w, x, y, z = q / norm
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def matrix_to_quaternion(rotation):
    """Unit quaternion (qx, qy, qz, qw) of a rotation matrix, qw >= 0."""
    r = np.asarray(rotation, dtype=float)
    # The largest of the four squared components gives a well-conditioned division.
    squares = np.array([1 + r[0, 0] + r[1, 1] + r[2, 2], 1 + r[0, 0] - r[1, 1] - r[2, 2],
                        1 - r[0, 0] + r[1, 1] - r[2, 2], 1 - r[0, 0] - r[1, 1] + r[2, 2]])
    i = int(np.argmax(squares))
    s = 2.0 * np.sqrt(max(squares[i], 1e-300))
    if i == 0:
        q = [(r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s, s / 4]
    elif i == 1:
        q = [s / 4, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s, (r[2, 1] - r[1, 2]) / s]
    elif i == 2:
        q = [(r[0, 1] + r[1, 0]) / s, s / 4, (r[1, 2] + r[2, 1]) / s, (r[0, 2] - r[2, 0]) / s]
    else:
        q = [(r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, s / 4, (r[1, 0] - r[0, 1]) / s]
    q = np.array(q) / np.linalg.norm(q)
    return q if q[3] >= 0 else -q


def read_tum_trajectory(path):
    """Reads `timestamp tx ty tz qx qy qz qw` lines ('#' comments) -> (stamps [N] s,
    poses [N,4,4] T_world_camera), sorted by stamp. Raises ValueError naming file and line."""
    rows = []
    with open(path) as handle:
        for number, line in enumerate(handle, 1):
            fields = line.replace(",", " ").split()
            if not fields or fields[0].startswith("#"):
                continue
            try:
                values = [float(v) for v in fields[:8]]
                if len(values) != 8:
                    raise ValueError("too few fields")
                rotation = quaternion_to_matrix(*values[4:8])
            except ValueError as error:
                raise ValueError("%s:%d: expected 'timestamp tx ty tz qx qy qz qw' (%s)" %
                                 (path, number, error))
            pose = np.eye(4)
            pose[:3, :3] = rotation
            pose[:3, 3] = values[1:4]
            rows.append((values[0], pose))
    rows.sort(key=lambda row: row[0])
    stamps = np.array([row[0] for row in rows], dtype=float)
    poses = np.array([row[1] for row in rows], dtype=float).reshape(-1, 4, 4)
    return stamps, poses


def write_tum_trajectory(path, stamps, poses):
    """Writes poses [N,4,4] with stamps [N] s in TUM format."""
    with open(path, "w") as handle:
        handle.write("# timestamp tx ty tz qx qy qz qw\n")
        for stamp, pose in zip(stamps, poses):
            q = matrix_to_quaternion(pose[:3, :3])
            handle.write("%.6f %.6f %.6f %.6f %.7f %.7f %.7f %.7f\n" %
                         ((stamp,) + tuple(pose[:3, 3]) + tuple(q)))


def associate(stamps_a, stamps_b, max_dt=0.02):
    """Pairs stamps of two sorted arrays by nearest time within max_dt [s], each stamp used at
    most once, greedily by smallest difference (as TUM's associate.py). Returns two index arrays
    (into a and into b), ordered by the stamp of a."""
    stamps_a = np.asarray(stamps_a, dtype=float)
    stamps_b = np.asarray(stamps_b, dtype=float)
    lows = np.searchsorted(stamps_b, stamps_a - max_dt, side="left")
    highs = np.searchsorted(stamps_b, stamps_a + max_dt, side="right")
    candidates = []
    for i, (low, high) in enumerate(zip(lows, highs)):
        for j in range(low, high):
            candidates.append((abs(stamps_a[i] - stamps_b[j]), i, j))
    candidates.sort()
    used_a, used_b, pairs = set(), set(), []
    for _, i, j in candidates:
        if i not in used_a and j not in used_b:
            used_a.add(i)
            used_b.add(j)
            pairs.append((i, j))
    pairs.sort()
    index_a = np.array([p[0] for p in pairs], dtype=int)
    index_b = np.array([p[1] for p in pairs], dtype=int)
    return index_a, index_b


def umeyama_se3(source, target):
    """Closed-form rigid alignment without scale (Umeyama 1991): the 4x4 T minimising
    sum |target_i - (R source_i + t)|^2 for point arrays [N,3] (N >= 3, not collinear)."""
    source = np.asarray(source, dtype=float)
    target = np.asarray(target, dtype=float)
    if source.shape != target.shape or source.shape[0] < 3:
        raise ValueError("need at least 3 corresponding points, got %d" % source.shape[0])
    mean_s, mean_t = source.mean(axis=0), target.mean(axis=0)
    covariance = (target - mean_t).T.dot(source - mean_s) / source.shape[0]
    u, _, vt = np.linalg.svd(covariance)
    sign = np.diag([1.0, 1.0, np.sign(np.linalg.det(u) * np.linalg.det(vt)) or 1.0])
    transform = np.eye(4)
    transform[:3, :3] = u.dot(sign).dot(vt)
    transform[:3, 3] = mean_t - transform[:3, :3].dot(mean_s)
    return transform


def transform_poses(transform, poses):
    """Left-multiplies every pose [N,4,4] by the 4x4 transform (changes the world frame)."""
    return np.einsum("ij,njk->nik", transform, poses)


def nearest_rotation(matrix):
    """The rotation matrix nearest to a 3x3 matrix in the Frobenius norm (SVD projection)."""
    u, _, vt = np.linalg.svd(matrix)
    sign = np.diag([1.0, 1.0, np.sign(np.linalg.det(u.dot(vt))) or 1.0])
    return u.dot(sign).dot(vt)


def bonn_marker_to_camera(poses):
    """Bonn ground truth correction: marker poses [N,4,4] -> colour camera poses
    T_cam = T_ros * T_gt * T_ros * T_m, T_m's rotation projected to the nearest rotation."""
    t_m = BONN_T_M_RAW.copy()
    t_m[:3, :3] = nearest_rotation(BONN_T_M_RAW[:3, :3])
    return np.einsum("ij,njk,kl->nil", BONN_T_ROS, poses, BONN_T_ROS.dot(t_m))


def align_and_ate(gt_stamps, gt_poses, est_stamps, est_poses, max_dt=0.02):
    """Associates estimate to ground truth by nearest stamp (max_dt [s]), aligns the estimate's
    positions with umeyama_se3 and returns a dict: T_gt_est (4x4), est_aligned [N,4,4] (all
    estimate poses moved into the ground-truth world), index_gt, index_est, errors [M] m,
    ate_rmse [m]. Raises ValueError when fewer than 3 poses associate."""
    index_est, index_gt = associate(est_stamps, gt_stamps, max_dt)
    if len(index_est) < 3:
        raise ValueError("only %d poses associate within %.3f s (need 3)" %
                         (len(index_est), max_dt))
    gt_xyz = gt_poses[index_gt, :3, 3]
    transform = umeyama_se3(est_poses[index_est, :3, 3], gt_xyz)
    aligned = transform_poses(transform, est_poses)
    errors = np.linalg.norm(aligned[index_est, :3, 3] - gt_xyz, axis=1)
    return {"T_gt_est": transform, "est_aligned": aligned, "index_gt": index_gt,
            "index_est": index_est, "errors": errors,
            "ate_rmse": float(np.sqrt(np.mean(errors ** 2)))}

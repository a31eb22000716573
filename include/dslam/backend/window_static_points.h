#pragma once
// Back-end static point determination (paper Sec. V-A "Static Point Determination in the Back
// End", Algorithm 1): after a new keyframe, the marked points measured in the window keyframes
// covisible with it form one Delaunay graph; every edge is tested with all its point-correlation
// measurements z_ijk = y_ik - y_jk in those keyframes (paper Eq. meas_con_imp), the graph is cut
// at the inconsistent edges, and the points of components other than the largest-volume one
// lose their mark. It runs before local bundle adjustment, so BA uses the points that stayed
// marked (local_bundle_adjustment.h).
//
// The edge test and the rules that keep it from degenerating are the front end's
// (static_points.h): with the default method "direct" an edge is consistent when its K
// world-frame measurements agree within the chi-square quantile with 3(K-1) dof, so the test
// gets stronger with every keyframe that measures the edge; an edge measured in fewer than
// static_points.min_edge_measurements keyframes connects nothing; a component is only unmarked
// when a tested edge ties it to the static component. Two rules of the window's own: a component
// of fewer than backend.spd_min_dynamic_points points keeps its marks, and when a component that
// would lose its marks holds more points than the static one nothing is unmarked (the reasons
// are at ComponentsLosingMarks, window_static_points.cpp). Keyframe poses are held fixed, so each
// measurement only needs its keyframe's rotation (the translation cancels).

#include "dslam/core/config.h"
#include "dslam/tracking/backend_status.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Runs Algorithm 1 on the window of `map` for its newest keyframe and unmarks the points found
/// moving (see the top of this file), but for frozen ones (Map::Freeze), which keep their marks.
/// Uses config.static_points for the test and config.backend for the window. Deterministic. Returns
/// what it did (WindowStaticPointsStats, tracking/backend_status.h).
WindowStaticPointsStats DetermineStaticPointsInWindow(const Config& config, Map* map);

}  // namespace dslam

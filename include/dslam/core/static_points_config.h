#pragma once
// Config section `static_points`: static point determination (static_points.h). A member of the
// one Config tree (config.h).

#include <string>

#include "dslam/core/config_field.h"

namespace dslam {

/// Static point determination (paper Sec. IV, V-A): Delaunay graph, inconsistent edge culling,
/// largest-volume component. See static_points.h and docs/readme/spd.md. Units, ranges and
/// meanings of the fields are given in Fields() (printed by `dslam_config_doc`).
struct StaticPointsConfig {
  bool enabled = true;
  std::string method = "direct";
  double chi2_threshold = 11.34;
  double direct_probability = 0.99;
  double min_inlier_fraction = 1.0;
  int min_edge_measurements = 2;
  int max_graph_points = 0;
  int min_static_points = 10;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(Flag("enabled", "static point determination on; off = static-world baseline"), s.enabled);
    // least_squares: rounds of linear least squares of J_p + one-way chi-square culling (at most
    // 4 rounds, a prior of 1 m per coordinate: CullingOptions' defaults); direct: per-edge
    // consistency test of the world-frame measurements, no optimisation.
    v(Choice("method", {"least_squares", "direct"},
             "edge test: least_squares (culling rounds) or direct"),
      s.method);
    v(Field("chi2_threshold", "-", 0.1, 1000.0,
            "3-dof squared Mahalanobis outlier threshold (7.81: 95%, 11.34: 99%)"),
      s.chi2_threshold);
    // Probability of the chi-square quantile with 3(K-1) dof.
    v(Field("direct_probability", "-", 0.5, 0.999999,
            "chi-square quantile probability of the direct edge test"),
      s.direct_probability);
    v(Field("min_inlier_fraction", "-", 0.0, 1.0,
            "an edge with a smaller share of inlier measurements is inconsistent"),
      s.min_inlier_fraction);
    // A point with only untested edges keeps its label (kUnverified). 0 or 1: every edge connects
    // (paper).
    v(Field("min_edge_measurements", "-", 0, 1000,
            "edges measured in fewer frames are untested and connect nothing"),
      s.min_edge_measurements);
    // The Delaunay graph's cost grows faster than linearly with its points; above this count
    // the front end builds it over a subset (every unsettled point, verified static points spread
    // evenly over the image), and the points left out take the static/dynamic label of their
    // nearest graph point (graph_subset.h). 0: no cap (default: 500 roughly halves the static
    // room's determination time but changes the fragile walking trajectories; docs/readme/spd.md).
    v(Field("max_graph_points", "-", 0, 1000000,
            "front end: graph points at most (0: no cap); the rest take a neighbour's label"),
      s.max_graph_points);
    // Components of fewer than 4 points never compete (StaticSelectionOptions' default).
    v(Field("min_static_points", "-", 1, 1000000,
            "largest-volume component smaller than this: no static decision"),
      s.min_static_points);
  }
};

}  // namespace dslam

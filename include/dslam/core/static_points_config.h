#pragma once
// Config section `static_points`: static point determination (static_points.h). A member of the
// one Config tree (config.h).

#include <string>

#include "dslam/core/config_field.h"

namespace dslam {

/// Static point determination (paper Sec. IV, V-A): Delaunay graph, inconsistent edge culling,
/// largest-volume component. See static_points.h and docs/readme/spd.md.
struct StaticPointsConfig {
  /// false: every static point determination is switched off (the static-world baseline).
  bool enabled = true;
  /// Edge test: "least_squares" (rounds of linear LS of J_p + one-way chi-square culling) or
  /// "direct" (per-edge consistency test of the world-frame measurements, no optimisation).
  std::string method = "direct";
  /// [-] solve + cull rounds of the least-squares method (stops early when nothing changes).
  int max_rounds = 4;
  /// [-] squared Mahalanobis threshold per 3-dof measurement (7.81: 95%, 11.34: 99%).
  double chi2_threshold = 11.34;
  /// [-] probability of the chi-square quantile (3(K-1) dof) of the direct test.
  double direct_probability = 0.99;
  /// [m] sigma of the weak prior anchoring each point to its initial estimate.
  double prior_sigma_m = 1.0;
  /// [-] an edge is inconsistent when fewer than this share of its measurements are inliers.
  double min_inlier_fraction = 1.0;
  /// [-] an edge measured in fewer frames is untested: it connects nothing, and a point with only
  /// untested edges keeps its label (kUnverified). 0 or 1: every edge connects (paper).
  int min_edge_measurements = 2;
  /// [-] components with fewer points never count as the static one.
  int min_component_points = 4;
  /// [-] if the largest-volume component has fewer points, no static component is chosen.
  int min_static_points = 10;
  /// [-] second / largest component volume above this flags the selection as ambiguous.
  double ambiguity_ratio = 0.7;

  template <typename Self, typename Visitor>
  static void Fields(Self& s, Visitor&& v) {
    v(FieldInfo{"enabled", "-", 0, 1,
                "static point determination on; off = static-world baseline", {}},
      s.enabled);
    v(FieldInfo{"method", "-", 0, 0,
                "edge test: least_squares (culling rounds) or direct", {"least_squares", "direct"}},
      s.method);
    v(FieldInfo{"max_rounds", "-", 1, 50, "solve + cull rounds (least_squares)", {}}, s.max_rounds);
    v(FieldInfo{"chi2_threshold", "-", 0.1, 1000.0,
                "3-dof squared Mahalanobis outlier threshold (7.81: 95%, 11.34: 99%)", {}},
      s.chi2_threshold);
    v(FieldInfo{"direct_probability", "-", 0.5, 0.999999,
                "chi-square quantile probability of the direct edge test", {}},
      s.direct_probability);
    v(FieldInfo{"prior_sigma_m", "m", 1e-3, 1e6, "sigma of the prior anchoring each point", {}},
      s.prior_sigma_m);
    v(FieldInfo{"min_inlier_fraction", "-", 0.0, 1.0,
                "an edge with a smaller share of inlier measurements is inconsistent", {}},
      s.min_inlier_fraction);
    v(FieldInfo{"min_edge_measurements", "-", 0, 1000,
                "edges measured in fewer frames are untested and connect nothing", {}},
      s.min_edge_measurements);
    v(FieldInfo{"min_component_points", "-", 1, 1000000,
                "smaller components are never chosen as static", {}},
      s.min_component_points);
    v(FieldInfo{"min_static_points", "-", 1, 1000000,
                "largest-volume component smaller than this: no static decision", {}},
      s.min_static_points);
    v(FieldInfo{"ambiguity_ratio", "-", 0.0, 1.0,
                "second/largest volume above this flags an ambiguous choice", {}},
      s.ambiguity_ratio);
  }
};

}  // namespace dslam

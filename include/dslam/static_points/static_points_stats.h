#pragma once
// The counts and times of one static point determination (static_points.h), a plain struct apart
// from the algorithm's headers: the back end's status (tracking/backend_status.h) embeds it.

namespace dslam {

/// Wall-clock time per step [ms] and counts of one DetermineStaticPoints call.
struct StaticPointsStats {
  double graph_ms = 0.0;       ///< [ms] Delaunay triangulation
  double culling_ms = 0.0;     ///< [ms] measurements, solves and culling
  double components_ms = 0.0;  ///< [ms] connected components and volumes
  double total_ms = 0.0;       ///< [ms] everything
  int points = 0;              ///< [-] input points
  int edges = 0;               ///< [-] graph edges
  int culled_edges = 0;        ///< [-] inconsistent edges removed
  int measurements = 0;        ///< [-] point-correlation measurements z_ijk
  int rounds = 0;              ///< [-] least-squares rounds (0 for the direct test)
  int components = 0;          ///< [-] connected components (singletons included)
  int static_points = 0;       ///< [-] points labelled kStatic
  int dynamic_points = 0;      ///< [-] points labelled kDynamic
  int isolated_points = 0;     ///< [-] points labelled kIsolated
};

}  // namespace dslam

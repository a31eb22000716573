#include "dslam/static_points/point_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include "dslam/static_points/segmentation.h"

namespace dslam {
namespace {

std::vector<Eigen::Vector3d> CubeWithCentre() {
  std::vector<Eigen::Vector3d> points;
  for (int c = 0; c < 8; ++c) points.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  points.emplace_back(0.5, 0.5, 0.5);
  return points;
}

bool HasEdge(const std::vector<GraphEdge>& edges, int i, int j) {
  for (const GraphEdge& e : edges) {
    if (e.i == i && e.j == j) return true;
  }
  return false;
}

// Every tetrahedron contains the centre (4 corners' circumsphere contains it), so the edges are
// the 12 cube edges, one diagonal per face (6) and the 8 centre-corner edges: 26.
TEST(PointGraph, CubeWithCentreHasKnownEdges) {
  const auto edges = BuildDelaunayGraph(CubeWithCentre());
  EXPECT_EQ(edges.size(), 26u);
  for (int c = 0; c < 8; ++c) EXPECT_TRUE(HasEdge(edges, c, 8)) << c;
  for (int a = 0; a < 8; ++a) {
    for (int b = a + 1; b < 8; ++b) {
      const int differing = __builtin_popcount(a ^ b);
      if (differing == 1) {
        EXPECT_TRUE(HasEdge(edges, a, b)) << a << "-" << b;  // cube edge
      }
      if (differing == 3) {
        EXPECT_FALSE(HasEdge(edges, a, b)) << a << "-" << b;  // space diagonal
      }
    }
  }
  for (const GraphEdge& e : edges) EXPECT_LT(e.i, e.j);
}

TEST(PointGraph, FewPoints) {
  EXPECT_TRUE(BuildDelaunayGraph({}).empty());
  EXPECT_TRUE(BuildDelaunayGraph({Eigen::Vector3d(1, 2, 3)}).empty());
  EXPECT_EQ(BuildDelaunayGraph({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)}).size(), 1u);
  const auto triangle = BuildDelaunayGraph(
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)});
  EXPECT_EQ(triangle.size(), 3u);
}

TEST(PointGraph, CollinearPointsFormAChain) {
  std::vector<Eigen::Vector3d> points;
  for (int i : {3, 0, 4, 1, 2}) points.emplace_back(i, 2.0 * i, 3.0 * i);  // exactly collinear
  const auto edges = BuildDelaunayGraph(points);
  ASSERT_EQ(edges.size(), 4u);
  // Neighbours along the line: 0-1 (points 1,3), 1-2 (3,4), 2-3 (4,0), 3-4 (0,2).
  EXPECT_TRUE(HasEdge(edges, 1, 3));
  EXPECT_TRUE(HasEdge(edges, 3, 4));
  EXPECT_TRUE(HasEdge(edges, 0, 4));
  EXPECT_TRUE(HasEdge(edges, 0, 2));
}

TEST(PointGraph, CoplanarPointsGiveA2DTriangulation) {
  // A 3x3 grid in the plane z = 2: 12 grid edges plus one diagonal per cell (4) = 16.
  std::vector<Eigen::Vector3d> points;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) points.emplace_back(c, r, 2.0);
  }
  const auto edges = BuildDelaunayGraph(points);
  EXPECT_EQ(edges.size(), 16u);
  const auto component = ConnectedComponents(9, edges, {});
  for (int c : component) EXPECT_EQ(c, 0);
}

TEST(PointGraph, DuplicatesAndNonFinitePoints) {
  auto points = CubeWithCentre();
  points.push_back(points[3]);  // index 9 duplicates corner 3
  points.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0, 0);  // index 10
  const auto edges = BuildDelaunayGraph(points);
  EXPECT_EQ(edges.size(), 27u);
  EXPECT_TRUE(HasEdge(edges, 3, 9));
  for (const GraphEdge& e : edges) EXPECT_NE(e.j, 10);
  const auto component = ConnectedComponents(11, edges, {});
  EXPECT_EQ(component[9], component[0]);
  EXPECT_NE(component[10], component[0]);
}

TEST(PointGraph, RandomCloudIsConnectedWithDelaunayDensity) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points(500);
  for (auto& p : points) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
  const auto edges = BuildDelaunayGraph(points);
  const auto component = ConnectedComponents(500, edges, {});
  for (int c : component) ASSERT_EQ(c, 0);
  // Random 3D Delaunay: mean vertex degree ~15.5 inside, lower on the hull.
  const double mean_degree = 2.0 * edges.size() / points.size();
  EXPECT_GT(mean_degree, 10.0);
  EXPECT_LT(mean_degree, 16.0);
}

// The Delaunay edges by their definition: the edges of every tetrahedron whose circumsphere holds
// no other point (random points: in general position), sorted and unique.
std::vector<GraphEdge> BruteForceDelaunayEdges(const std::vector<Eigen::Vector3d>& p) {
  const int n = static_cast<int>(p.size());
  std::vector<GraphEdge> edges;
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      for (int c = b + 1; c < n; ++c) {
        for (int d = c + 1; d < n; ++d) {
          // Centre x of the sphere through the four: 2 (q - p_a) . x = |q|^2 - |p_a|^2.
          Eigen::Matrix3d A;
          Eigen::Vector3d rhs;
          const int others[3] = {b, c, d};
          for (int r = 0; r < 3; ++r) {
            A.row(r) = 2.0 * (p[others[r]] - p[a]).transpose();
            rhs(r) = p[others[r]].squaredNorm() - p[a].squaredNorm();
          }
          const Eigen::Vector3d centre = A.partialPivLu().solve(rhs);
          const double radius2 = (p[a] - centre).squaredNorm();
          bool empty = true;
          for (int k = 0; k < n && empty; ++k) {
            if (k != a && k != b && k != c && k != d) {
              empty = (p[k] - centre).squaredNorm() > radius2;
            }
          }
          if (!empty) continue;
          const int v[4] = {a, b, c, d};
          for (int i = 0; i < 4; ++i) {
            for (int j = i + 1; j < 4; ++j) edges.push_back(GraphEdge{v[i], v[j]});
          }
        }
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

TEST(PointGraph, EdgesAreThoseOfTheEmptyCircumsphereTetrahedra) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {5, 12, 30}) {
    std::vector<Eigen::Vector3d> points(n);
    for (auto& p : points) p = Eigen::Vector3d(u(rng), u(rng), 0.3 * u(rng));
    const std::vector<GraphEdge> edges = BuildDelaunayGraph(points);
    const std::vector<GraphEdge> expected = BruteForceDelaunayEdges(points);
    ASSERT_EQ(edges.size(), expected.size()) << n << " points";
    for (size_t k = 0; k < edges.size(); ++k) {
      EXPECT_EQ(edges[k].i, expected[k].i);
      EXPECT_EQ(edges[k].j, expected[k].j);
    }
  }
}

TEST(PointGraph, LargeCloudHasTheSameDensity) {  // above 4096 points: the other edge collection
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points(5000);
  for (auto& p : points) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
  const auto edges = BuildDelaunayGraph(points);
  EXPECT_TRUE(std::is_sorted(edges.begin(), edges.end()));
  EXPECT_EQ(std::adjacent_find(edges.begin(), edges.end()), edges.end());
  const auto component = ConnectedComponents(5000, edges, {});
  for (int c : component) ASSERT_EQ(c, 0);
  const double mean_degree = 2.0 * edges.size() / points.size();
  EXPECT_GT(mean_degree, 13.0);
  EXPECT_LT(mean_degree, 16.0);
}

}  // namespace
}  // namespace dslam

#include "dslam/tracking/relocalisation.h"

#include "dslam/features/matching.h"

namespace dslam {

std::vector<PointId> WindowMarkedPoints(const Map& map) {
  std::vector<PointId> out;
  for (PointId id : map.LocalPoints({})) {
    if (map.Find(id)->marked) out.push_back(id);
  }
  return out;
}

std::vector<PointMatch> MatchByDescriptor(const Map& map, const std::vector<PointId>& points,
                                          const FrameFeatures& features,
                                          const DescriptorMatchRules& rules) {
  std::vector<int> query_feature;
  cv::Mat query;
  for (size_t f = 0; f < features.features.size(); ++f) {
    if (!features.features[f].measurement) continue;
    query_feature.push_back(static_cast<int>(f));
    query.push_back(features.descriptors.row(static_cast<int>(f)));
  }
  std::vector<PointId> train_point;
  cv::Mat train;
  for (PointId id : points) {
    const MapPoint* point = map.Find(id);
    if (point == nullptr || point->descriptor.empty()) continue;
    train_point.push_back(id);
    train.push_back(point->descriptor);
  }
  std::vector<PointMatch> out;
  for (const DescriptorMatch& m :
       MatchBruteForce(query, train, rules.max_distance_bits, rules.ratio)) {
    out.push_back({train_point[m.train], query_feature[m.query]});
  }
  return out;
}

}  // namespace dslam

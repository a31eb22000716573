#include "dslam/place_recognition/place_database.h"

#include <algorithm>
#include <stdexcept>

namespace dslam {

void PlaceDatabase::Add(int id, const BowVector& words) {
  for (const auto& [word, weight] : words) {
    if (weight < 0.0) throw std::invalid_argument("PlaceDatabase::Add: negative word weight");
  }
  Erase(id);
  BowVector normalised = words;
  NormaliseL1(&normalised);
  for (const auto& [word, weight] : normalised) {
    if (weight > 0.0) index_[word].push_back({id, weight});
  }
  images_.emplace(id, std::move(normalised));
}

bool PlaceDatabase::Erase(int id) {
  const auto image = images_.find(id);
  if (image == images_.end()) return false;
  for (const auto& [word, weight] : image->second) {
    const auto postings = index_.find(word);
    if (postings == index_.end()) continue;
    std::vector<Posting>& list = postings->second;
    list.erase(
        std::remove_if(list.begin(), list.end(), [id](const Posting& p) { return p.id == id; }),
        list.end());
    if (list.empty()) index_.erase(postings);
  }
  images_.erase(image);
  return true;
}

void PlaceDatabase::Clear() {
  images_.clear();
  index_.clear();
}

std::unordered_map<int, PlaceDatabase::Sums> PlaceDatabase::Accumulate(
    const BowVector& query, const std::function<bool(int id)>& exclude) const {
  BowVector normalised = query;
  NormaliseL1(&normalised);
  std::unordered_map<int, Sums> sums;
  for (const auto& [word, weight] : normalised) {
    if (weight <= 0.0) continue;
    const auto postings = index_.find(word);
    if (postings == index_.end()) continue;
    for (const Posting& p : postings->second) {
      const auto [entry, first] = sums.try_emplace(p.id);
      Sums& s = entry->second;
      if (first && exclude) s.excluded = exclude(p.id);
      if (s.excluded) continue;
      ++s.shared_words;
      // For L1-normalised non-negative vectors ScoreL1 is the sum of min(x, y) over the words.
      s.score += std::min(weight, p.weight);
    }
  }
  return sums;
}

std::vector<PlaceCandidate> PlaceDatabase::Query(const BowVector& query,
                                                 const PlaceQueryOptions& options) const {
  std::vector<PlaceCandidate> candidates;
  for (const auto& [id, s] : Accumulate(query, options.exclude)) {
    if (s.excluded || s.shared_words < options.min_shared_words || s.score < options.min_score)
      continue;
    candidates.push_back({id, std::min(1.0, s.score), s.shared_words});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const PlaceCandidate& a, const PlaceCandidate& b) {
              return a.score != b.score ? a.score > b.score : a.id < b.id;
            });
  if (options.max_results > 0 && candidates.size() > static_cast<size_t>(options.max_results)) {
    candidates.resize(options.max_results);
  }
  return candidates;
}

}  // namespace dslam

#pragma once
// An inverted index of images (keyframes) by their bag of words (bow_vector.h): for each word the
// images that contain it, so that a query scores only the images sharing a word with it.

#include <cstddef>
#include <functional>
#include <unordered_map>
#include <vector>

#include "dslam/place_recognition/bow_vector.h"

namespace dslam {

/// One image found by PlaceDatabase::Query.
struct PlaceCandidate {
  int id = -1;           ///< the id given to Add
  double score = 0.0;    ///< ScoreL1 with the query, in (0, 1]
  int shared_words = 0;  ///< words of the query that the image contains too
};

/// Options of PlaceDatabase::Query.
struct PlaceQueryOptions {
  int max_results = 10;                 ///< at most this many candidates (<= 0: all)
  double min_score = 0.0;               ///< only candidates with score >= this
  int min_shared_words = 1;             ///< only candidates with at least this many shared words
  std::function<bool(int id)> exclude;  ///< images for which it returns true are skipped
};

/// Images by integer id and the inverted index over their words.
class PlaceDatabase {
 public:
  /// Adds image `id` with its bag of words (weights >= 0; stored L1-normalised); an image already
  /// there with that id is replaced. Throws std::invalid_argument on a negative weight.
  void Add(int id, const BowVector& words);

  /// Removes image `id`; false when it is not there.
  bool Erase(int id);

  bool Contains(int id) const { return images_.count(id) > 0; }  ///< image `id` was added
  std::size_t size() const { return images_.size(); }            ///< number of images
  void Clear();                                                  ///< removes every image

  /// The images that share a word with `query` and pass `options`, best score first (ties: lower
  /// id), scored with ScoreL1 over the shared words only.
  std::vector<PlaceCandidate> Query(const BowVector& query,
                                    const PlaceQueryOptions& options = {}) const;

 private:
  struct Posting {
    int id;         // image
    double weight;  // the word's L1-normalised weight in that image
  };
  struct Sums {
    double score = 0.0;
    int shared_words = 0;
    bool excluded = false;  // the query's exclude said so (asked once per image)
  };
  /// Per image sharing a word with `query`: its score and shared words (none for an excluded
  /// image, whose `exclude` is asked once).
  std::unordered_map<int, Sums> Accumulate(const BowVector& query,
                                           const std::function<bool(int id)>& exclude) const;

  std::unordered_map<int, BowVector> images_;               // id -> normalised words
  std::unordered_map<WordId, std::vector<Posting>> index_;  // word -> images containing it
};

}  // namespace dslam

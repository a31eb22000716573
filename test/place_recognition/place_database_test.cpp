#include "dslam/place_recognition/place_database.h"

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/place_recognition/vocabulary.h"
#include "place_recognition/random_descriptors.h"

namespace dslam {
namespace {

// 60 images of 150 descriptors, image i from planted centres 16i .. 16i + 15 (3 bits flipped),
// a vocabulary trained on them, and every image in the database under id 100 + index.
class PlaceDatabaseTest : public testing::Test {
 protected:
  void SetUp() override {
    std::mt19937 rng(4);
    const cv::Mat centres = test::RandomDescriptors(1000, &rng);
    for (int i = 0; i < 60; ++i) {
      const cv::Mat own = centres.rowRange(16 * i, 16 * i + 16);
      images_.push_back(test::ImageFromCentres(own, 150, 3, &rng));
    }
    vocabulary_ = Vocabulary::Train(images_, {10, 3, 10, 1});
    for (int i = 0; i < 60; ++i) database_.Add(100 + i, vocabulary_.Transform(images_[i]));
    query_ = vocabulary_.Transform(test::FlipBits(images_[17], 3, &rng));
  }

  std::vector<cv::Mat> images_;
  Vocabulary vocabulary_;
  PlaceDatabase database_;
  BowVector query_;  // a noisy copy of image 17 (id 117)
};

TEST_F(PlaceDatabaseTest, FindsTheRightImageFirst) {
  const std::vector<PlaceCandidate> found = database_.Query(query_, {5, 0.0, 1, {}});
  ASSERT_EQ(found.size(), 5u);
  EXPECT_EQ(found[0].id, 117);
  EXPECT_GT(found[0].score, found[1].score + 0.2);
  for (size_t i = 1; i < found.size(); ++i) EXPECT_GE(found[i - 1].score, found[i].score);
}

TEST_F(PlaceDatabaseTest, ScoresEqualScoreL1AndOnlyImagesSharingAWordAreReturned) {
  const std::vector<PlaceCandidate> all = database_.Query(query_, {0, 0.0, 1, {}});
  for (const PlaceCandidate& c : all) {
    const BowVector image = vocabulary_.Transform(images_[c.id - 100]);
    EXPECT_NEAR(c.score, ScoreL1(query_, image), 1e-12) << c.id;
    EXPECT_GT(c.shared_words, 0);
  }
  int sharing = 0;
  for (const cv::Mat& image : images_) sharing += ScoreL1(query_, vocabulary_.Transform(image)) > 0;
  EXPECT_EQ(static_cast<int>(all.size()), sharing);
}

TEST_F(PlaceDatabaseTest, RespectsExclusionThresholdsAndErase) {
  const auto excluded = database_.Query(query_, {3, 0.0, 1, [](int id) { return id == 117; }});
  ASSERT_FALSE(excluded.empty());
  EXPECT_NE(excluded[0].id, 117);
  const auto strong = database_.Query(query_, {0, 0.5, 1, {}});
  ASSERT_EQ(strong.size(), 1u);
  EXPECT_EQ(strong[0].id, 117);
  EXPECT_TRUE(database_.Erase(117));
  EXPECT_FALSE(database_.Erase(117));
  EXPECT_FALSE(database_.Contains(117));
  EXPECT_EQ(database_.size(), 59u);
  for (const PlaceCandidate& c : database_.Query(query_, {0, 0.0, 1, {}})) EXPECT_NE(c.id, 117);
  database_.Add(5, query_);
  EXPECT_EQ(database_.Query(query_, {1, 0.0, 1, {}})[0].id, 5);
  EXPECT_NEAR(database_.Query(query_, {1, 0.0, 1, {}})[0].score, 1.0, 1e-12);
  database_.Clear();
  EXPECT_TRUE(database_.Query(query_).empty());
}

TEST_F(PlaceDatabaseTest, ExcludeIsAskedOncePerImage) {
  // The query's exclude may look the image up in a map: it is asked once per image sharing a
  // word with the query, not once per shared word.
  std::map<int, int> asked;
  const auto exclude = [&asked](int id) { return ++asked[id], id % 2 == 0; };
  const std::vector<PlaceCandidate> found = database_.Query(query_, {0, 0.0, 1, exclude});
  const std::vector<PlaceCandidate> all = database_.Query(query_, {0, 0.0, 1, {}});
  ASSERT_FALSE(asked.empty());
  for (const auto& [id, times] : asked) EXPECT_EQ(times, 1) << id;
  EXPECT_EQ(asked.size(), all.size());
  size_t odd = 0;
  for (const PlaceCandidate& c : all) odd += c.id % 2 != 0;
  EXPECT_EQ(found.size(), odd);
  for (const PlaceCandidate& c : found) EXPECT_NE(c.id % 2, 0);
}

TEST_F(PlaceDatabaseTest, QueryCountsTheCommonWords) {
  const std::vector<PlaceCandidate> found = database_.Query(query_, {0, 0.0, 1, {}});
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].id, 117);
  int most = 0;
  for (const PlaceCandidate& c : found) {
    const BowVector image = vocabulary_.Transform(images_[c.id - 100]);
    int common = 0;
    for (const auto& [word, weight] : query_) common += image.count(word) > 0 ? 1 : 0;
    EXPECT_EQ(c.shared_words, common) << c.id;
    most = std::max(most, c.shared_words);
  }
  EXPECT_EQ(found[0].shared_words, most);
  for (const PlaceCandidate& c : database_.Query(query_, {0, 0.0, most, {}})) {
    EXPECT_EQ(c.shared_words, most);
  }
}

TEST(PlaceDatabaseAddTest, ReplacesAnImageAndRejectsNegativeWeights) {
  PlaceDatabase database;
  database.Add(1, {{3, 1.0}});
  database.Add(1, {{4, 1.0}});
  EXPECT_EQ(database.size(), 1u);
  EXPECT_TRUE(database.Query({{3, 1.0}}).empty());
  EXPECT_EQ(database.Query({{4, 2.0}}).size(), 1u);
  EXPECT_THROW(database.Add(2, {{3, -1.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace dslam

#include "dslam/place_recognition/vocabulary.h"

#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "dslam/features/features.h"
#include "place_recognition/random_descriptors.h"
#include "support/textured_frame.h"

namespace dslam {
namespace {

std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string TempPath(const std::string& name) {
  return testing::TempDir() + "/place_recognition_" + name;
}

// Images of 150 descriptors drawn from 200 planted centres with 3 bits flipped.
std::vector<cv::Mat> PlantedImages(int count, const cv::Mat& centres, std::mt19937* rng) {
  std::vector<cv::Mat> images;
  for (int i = 0; i < count; ++i) images.push_back(test::ImageFromCentres(centres, 150, 3, rng));
  return images;
}

TEST(VocabularyTest, ClusteringRecoversPlantedClusters) {
  std::mt19937 rng(7);
  const cv::Mat centres = test::RandomDescriptors(8, &rng);
  std::vector<cv::Mat> images;  // one image per cluster: 30 copies of its centre, 8 bits flipped
  for (int c = 0; c < centres.rows; ++c) {
    images.push_back(test::FlipBits(cv::repeat(centres.row(c), 30, 1), 8, &rng));
  }
  const Vocabulary vocabulary = Vocabulary::Train(images, {8, 1, 10, 1});
  ASSERT_EQ(vocabulary.num_words(), 8u);
  std::set<WordId> words;
  for (int c = 0; c < centres.rows; ++c) {
    const WordId word = vocabulary.WordOf(centres.ptr<std::uint8_t>(c));
    words.insert(word);
    for (int r = 0; r < images[c].rows; ++r) {
      EXPECT_EQ(vocabulary.WordOf(images[c].ptr<std::uint8_t>(r)), word) << c << " " << r;
    }
    // Each word is in one image of eight: idf = ln(8).
    EXPECT_NEAR(vocabulary.WordWeight(word), std::log(8.0), 1e-12);
  }
  EXPECT_EQ(words.size(), 8u);
}

TEST(VocabularyTest, TreeHasTheRequestedShape) {
  std::mt19937 rng(3);
  const Vocabulary vocabulary =
      Vocabulary::Train(PlantedImages(20, test::RandomDescriptors(200, &rng), &rng), {4, 3, 10, 1});
  EXPECT_EQ(vocabulary.branching(), 4);
  EXPECT_EQ(vocabulary.levels(), 3);
  EXPECT_LE(vocabulary.num_words(), 64u);
  EXPECT_GT(vocabulary.num_words(), 32u);
  EXPECT_LT(vocabulary.num_words(), vocabulary.num_nodes());
}

TEST(VocabularyTest, TransformScoresItselfOneAndANoisyCopyAboveAnUnrelatedImage) {
  std::mt19937 rng(11);
  const cv::Mat centres = test::RandomDescriptors(200, &rng);
  const std::vector<cv::Mat> images = PlantedImages(30, centres, &rng);
  const Vocabulary vocabulary = Vocabulary::Train(images, {10, 2, 10, 1});
  const cv::Mat image = test::ImageFromCentres(centres.rowRange(0, 100), 150, 3, &rng);
  const cv::Mat unrelated = test::ImageFromCentres(centres.rowRange(100, 200), 150, 3, &rng);
  const BowVector v = vocabulary.Transform(image);
  EXPECT_NEAR(ScoreL1(v, v), 1.0, 1e-12);
  const double noisy = ScoreL1(v, vocabulary.Transform(test::FlipBits(image, 3, &rng)));
  const double other = ScoreL1(v, vocabulary.Transform(unrelated));
  EXPECT_GT(noisy, 0.6);
  EXPECT_GT(noisy, other + 0.3);
  double sum = 0.0;
  for (const auto& [word, weight] : v) sum += weight;
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(VocabularyTest, TrainingOnOrbFeaturesIsByteIdentical) {
  const PinholeCamera camera = test::TestCamera();
  std::vector<cv::Mat> images;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    images.push_back(ExtractFeatures(test::TexturedFrame(camera, seed, 2.0), {}, {}).descriptors);
  }
  const VocabularyParams params{6, 3, 10, 1};
  const std::string a = TempPath("train_a.bin");
  const std::string b = TempPath("train_b.bin");
  const Vocabulary first = Vocabulary::Train(images, params);
  first.Save(a);
  Vocabulary::Train(images, params).Save(b);
  EXPECT_EQ(FileBytes(a), FileBytes(b));
  EXPECT_GT(first.num_words(), 100u);
  EXPECT_NE(Vocabulary::Train(images, {6, 3, 10, 2}).identity(), first.identity());
}

TEST(VocabularyTest, RejectsBadInput) {
  std::mt19937 rng(1);
  const std::vector<cv::Mat> images{test::RandomDescriptors(10, &rng)};
  EXPECT_THROW(Vocabulary::Train(images, {1, 3, 10, 1}), std::invalid_argument);
  EXPECT_THROW(Vocabulary::Train({cv::Mat()}, {}), std::invalid_argument);
  EXPECT_THROW(Vocabulary::Train({cv::Mat(3, 32, CV_32FC1)}, {}), std::invalid_argument);
  EXPECT_THROW(Vocabulary().Transform(images[0]), std::logic_error);
  const Vocabulary vocabulary = Vocabulary::Train(images, {2, 2, 10, 1});
  EXPECT_THROW(vocabulary.Transform(cv::Mat(3, 16, CV_8UC1)), std::invalid_argument);
  EXPECT_TRUE(vocabulary.Transform(cv::Mat()).empty());
}

}  // namespace
}  // namespace dslam

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "dslam/place_recognition/vocabulary.h"
#include "place_recognition/random_descriptors.h"

namespace dslam {
namespace {

// The committed vocabulary as docs/tools-and-data.md states it ("Place recognition").
constexpr int kCommittedBranching = 10;
constexpr int kCommittedLevels = 5;
constexpr std::size_t kCommittedNodes = 109431;
constexpr std::size_t kCommittedWords = 98366;
constexpr std::uint64_t kCommittedIdentity = 0x723a8e39b1688a18ull;

std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void WriteBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

class VocabularyFileTest : public testing::Test {
 protected:
  void SetUp() override {
    std::mt19937 rng(2);
    const cv::Mat centres = test::RandomDescriptors(100, &rng);
    for (int i = 0; i < 10; ++i) images_.push_back(test::ImageFromCentres(centres, 80, 4, &rng));
    vocabulary_ = Vocabulary::Train(images_, {5, 3, 10, 1});
    vocabulary_.Save(path_);
  }

  // Loads `bytes` written to a file of its own; the message of the exception, or "".
  std::string LoadError(const std::string& bytes) {
    const std::string path = testing::TempDir() + "/place_recognition_broken.bin";
    WriteBytes(path, bytes);
    try {
      Vocabulary::Load(path);
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      return e.what();
    }
    return "";
  }

  std::vector<cv::Mat> images_;
  Vocabulary vocabulary_;
  const std::string path_ = testing::TempDir() + "/place_recognition_saved.bin";
};

TEST_F(VocabularyFileTest, RoundTripGivesTheSameVocabulary) {
  const Vocabulary loaded = Vocabulary::Load(path_);
  EXPECT_EQ(loaded.identity(), vocabulary_.identity());
  EXPECT_NE(loaded.identity(), 0u);
  EXPECT_EQ(loaded.branching(), 5);
  EXPECT_EQ(loaded.levels(), 3);
  EXPECT_EQ(loaded.num_nodes(), vocabulary_.num_nodes());
  EXPECT_EQ(loaded.num_words(), vocabulary_.num_words());
  for (const cv::Mat& image : images_) {
    EXPECT_EQ(loaded.Transform(image), vocabulary_.Transform(image));
  }
  const std::string again = testing::TempDir() + "/place_recognition_again.bin";
  loaded.Save(again);
  EXPECT_EQ(FileBytes(again), FileBytes(path_));
  EXPECT_EQ(FileBytes(path_).size(), 40 + 44 * vocabulary_.num_nodes());
  EXPECT_EQ(FormatIdentity(0x00ab0000000000cdull), "00ab0000000000cd");
}

TEST_F(VocabularyFileTest, RefusesTruncatedCorruptAndForeignFiles) {
  const std::string bytes = FileBytes(path_);
  EXPECT_NE(LoadError(bytes.substr(0, bytes.size() - 10)).find("truncated"), std::string::npos);
  EXPECT_NE(LoadError(bytes.substr(0, 30)).find("truncated"), std::string::npos);
  EXPECT_NE(LoadError(bytes.substr(0, 4)).find("truncated"), std::string::npos);
  std::string magic = bytes;
  magic[0] = 'X';
  EXPECT_NE(LoadError(magic).find("wrong magic"), std::string::npos);
  std::string version = bytes;
  version[8] = 2;
  EXPECT_NE(LoadError(version).find("unsupported format version 2"), std::string::npos);
  std::string flipped = bytes;
  flipped[bytes.size() - 5] ^= 1;
  EXPECT_NE(LoadError(flipped).find("corrupt"), std::string::npos);
  EXPECT_NE(LoadError(bytes + "x").find("corrupt"), std::string::npos);
  const std::string missing = testing::TempDir() + "/place_recognition_missing.bin";
  EXPECT_THROW(Vocabulary::Load(missing), std::runtime_error);
}

TEST_F(VocabularyFileTest, FailedSaveLeavesNoTemporaryFile) {
  const std::filesystem::path dir = testing::TempDir() + "/place_recognition_dir";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "target" / "inside");  // rename onto it fails
  EXPECT_THROW(vocabulary_.Save((dir / "target").string()), std::runtime_error);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename(), "target");
  }
  EXPECT_THROW(vocabulary_.Save((dir / "missing" / "v.bin").string()), std::runtime_error);
  EXPECT_THROW(Vocabulary().Save(path_), std::logic_error);
}

TEST(CommittedVocabularyTest, HasTheDocumentedParametersAndIdentity) {
  const Vocabulary vocabulary = Vocabulary::Load(DefaultVocabularyPath());
  EXPECT_EQ(vocabulary.branching(), kCommittedBranching);
  EXPECT_EQ(vocabulary.levels(), kCommittedLevels);
  EXPECT_EQ(vocabulary.num_words(), kCommittedWords);
  EXPECT_EQ(vocabulary.num_nodes(), kCommittedNodes);
  EXPECT_EQ(FormatIdentity(vocabulary.identity()), FormatIdentity(kCommittedIdentity));
}

}  // namespace
}  // namespace dslam

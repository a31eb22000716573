// SaveKeyFrameMap / LoadKeyFrameMap: every field round trips, images within the documented
// rounding, saves replace files only when complete, the writer refuses what the reader would,
// CheckCompatible names a foreign camera or vocabulary.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "dslam/core/binary_io.h"
#include "dslam/map_file/keyframe_map_file.h"
#include "map_file/sample_map.h"
#include "support/thrown_message.h"

namespace dslam {
namespace {

using test::SampleMapFile;

std::filesystem::path TempDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Expects `loaded` to be `saved` after the depth rounding of keyframe_map_file.h.
void ExpectSameImages(const KeyFrameImages& saved, const KeyFrameImages& loaded) {
  ASSERT_EQ(loaded.colour.type(), saved.colour.type());
  EXPECT_EQ(cv::norm(saved.colour, loaded.colour, cv::NORM_INF), 0.0);
  ASSERT_EQ(loaded.depth_m.type(), CV_32FC1);
  ASSERT_EQ(loaded.depth_m.size(), saved.depth_m.size());
  for (int r = 0; r < saved.depth_m.rows; ++r) {
    for (int c = 0; c < saved.depth_m.cols; ++c) {
      const float d = saved.depth_m.at<float>(r, c);
      const float l = loaded.depth_m.at<float>(r, c);
      if (std::isfinite(d) && d >= 0.0005f && d < 65.5f) {
        EXPECT_NEAR(l, d, 0.0005 + 1e-6) << r << "," << c;
      } else {
        EXPECT_EQ(l, 0.0f) << r << "," << c << " saved " << d;
      }
    }
  }
}

TEST(KeyFrameMapFile, RoundTripKeepsEveryField) {
  const KeyFrameMapFile saved = SampleMapFile(7, 4, true);
  const std::string path = (TempDir("kfm_round_trip") / "map.bin").string();
  SaveKeyFrameMap(path, saved);
  const KeyFrameMapFile loaded = LoadKeyFrameMap(path);
  EXPECT_EQ(loaded.vocabulary_identity, saved.vocabulary_identity);
  test::ExpectSameMap(saved, loaded);
  ASSERT_EQ(loaded.images.size(), 2u);  // keyframes 0 and 2 (grey): ids 5 and 9
  for (const auto& [id, images] : saved.images) {
    ASSERT_EQ(loaded.images.count(id), 1u) << id;
    ExpectSameImages(images, loaded.images.at(id));
  }
  EXPECT_EQ(loaded.images.at(9).colour.type(), CV_8UC1);
  // Contents byte-for-byte: the loaded map writes the same bytes.
  EXPECT_EQ(SerialiseKeyFrameMap(loaded), SerialiseKeyFrameMap(saved));
}

TEST(KeyFrameMapFile, EmptyMapAndNoImagesRoundTrip) {
  const KeyFrameMapFile saved = SampleMapFile(0, 0, false);
  const std::string bytes = SerialiseKeyFrameMap(saved);
  EXPECT_EQ(bytes.size(), kKeyFrameMapHeaderBytes);
  const KeyFrameMapFile loaded = ParseKeyFrameMap(bytes);
  test::ExpectSameMap(saved, loaded);
  EXPECT_TRUE(loaded.images.empty());
}

TEST(KeyFrameMapFile, LoadedContentsMakeAMap) {
  const KeyFrameMapFile loaded = ParseKeyFrameMap(SerialiseKeyFrameMap(SampleMapFile(7, 4, false)));
  const Map map = Map::FromContents(loaded.contents);
  EXPECT_EQ(map.size(), 7u);
  EXPECT_EQ(map.num_keyframes(), 4u);
  // Keyframe 0 (id 5) lists points 0, 2, 4, 6 (ids 1, 7, 13, 19) and id 999, which is dropped.
  ASSERT_NE(map.FindKeyFrame(5), nullptr);
  EXPECT_EQ(map.FindKeyFrame(5)->points, (std::vector<PointId>{1, 7, 13, 19}));
  EXPECT_EQ(map.Find(7)->observing_keyframes, 2);  // point 2: keyframes 0 and 2
}

TEST(KeyFrameMapFile, WriterRefusesWhatTheReaderWould) {
  const auto refused = [](const KeyFrameMapFile& file) {
    return test::ThrownMessage<std::invalid_argument>([&] { SerialiseKeyFrameMap(file); });
  };
  KeyFrameMapFile file = SampleMapFile(3, 2, false);
  std::swap(file.contents.points[0], file.contents.points[1]);
  EXPECT_NE(refused(file).find("map point id 1 is negative or not above"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.contents.keyframes[1].id = file.contents.keyframes[0].id;
  EXPECT_NE(refused(file).find("keyframe id 5 is negative"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.contents.keyframes[1].T_world_camera.translation().x() = NAN;
  EXPECT_NE(refused(file).find("keyframe 7 has a non-finite pose"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.contents.keyframes[0].T_world_camera.linear() *= 1.01;
  EXPECT_NE(refused(file).find("rotation is not one"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.contents.points[2].descriptor = cv::Mat(1, 16, CV_8U, cv::Scalar(1));
  EXPECT_NE(refused(file).find("map point 7 has a descriptor"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.images[6] = test::SampleImages(0);
  EXPECT_NE(refused(file).find("images of keyframe 6, not in the map"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.images[5] = test::SampleImages(0);
  file.images[5].depth_m = file.images[5].depth_m(cv::Rect(0, 0, 8, 6)).clone();
  EXPECT_NE(refused(file).find("keyframe 5 has a depth image"), std::string::npos);
}

TEST(KeyFrameMapFile, FailedSaveLeavesTheOldFile) {
  const std::filesystem::path dir = TempDir("kfm_failed_save");
  const std::string path = (dir / "map.bin").string();
  SaveKeyFrameMap(path, SampleMapFile(2, 1, false));
  const std::string old_bytes = ReadWholeFile(path, "test");
  // The path is a folder: the rename fails, the folder and nothing else stays.
  std::filesystem::create_directories(dir / "folder" / "inside");
  const std::string folder = (dir / "folder").string();
  const std::string message = test::ThrownMessage<std::runtime_error>(
      [&] { SaveKeyFrameMap(folder, SampleMapFile(2, 1, false)); });
  EXPECT_NE(message.find(folder), std::string::npos) << message;
  // The temporary file cannot be made (a folder of its name): map.bin stays as it was.
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  std::filesystem::create_directories(temporary + "/inside");
  const std::string cannot_write = test::ThrownMessage<std::runtime_error>(
      [&] { SaveKeyFrameMap(path, SampleMapFile(5, 3, true)); });
  EXPECT_EQ(cannot_write, "SaveKeyFrameMap: cannot write " + temporary);
  EXPECT_EQ(ReadWholeFile(path, "test"), old_bytes);
  std::filesystem::remove_all(temporary);
  // A folder that cannot be written (not for root, which may write anyway): map.bin stays.
  if (::geteuid() != 0) {
    ::chmod(dir.c_str(), 0500);
    EXPECT_THROW(SaveKeyFrameMap(path, SampleMapFile(5, 3, true)), std::runtime_error);
    ::chmod(dir.c_str(), 0700);
  }
  // A failure while serialising (invalid content) leaves the file alone too.
  KeyFrameMapFile bad = SampleMapFile(2, 1, false);
  bad.contents.points[0].id = -3;
  EXPECT_THROW(SaveKeyFrameMap(path, bad), std::invalid_argument);
  EXPECT_EQ(ReadWholeFile(path, "test"), old_bytes);
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"folder", "map.bin"}));
  EXPECT_THROW(SaveKeyFrameMap((dir / "missing" / "m.bin").string(), SampleMapFile(1, 1, false)),
               std::runtime_error);
}

TEST(KeyFrameMapFile, CheckCompatibleNamesForeignCameraAndVocabulary) {
  const KeyFrameMapFile file = SampleMapFile(1, 1, false);
  EXPECT_EQ(CheckCompatible(file, test::SampleCamera(), file.vocabulary_identity), "");
  const PinholeCamera other(16, 12, 20.5, 21.25, 7.75, 5.6, test::SampleCamera().distortion());
  const std::string camera = CheckCompatible(file, other, file.vocabulary_identity);
  EXPECT_EQ(camera.rfind("recorded with another camera (16x12 fx 20.5 fy 21.25 cx 7.75 cy 5.5 ", 0),
            0u)
      << camera;
  EXPECT_NE(camera.find(") than this run's (16x12 fx 20.5 fy 21.25 cx 7.75 cy 5.6 "),
            std::string::npos)
      << camera;
  const PinholeCamera undistorted(16, 12, 20.5, 21.25, 7.75, 5.5);
  EXPECT_NE(CheckCompatible(file, undistorted, file.vocabulary_identity), "");
  EXPECT_EQ(CheckCompatible(file, test::SampleCamera(), 0x0123456789abcdefull),
            "recorded with vocabulary 723a8e39b1688a18 but this run uses 0123456789abcdef");
}

}  // namespace
}  // namespace dslam

// SaveKeyFrameMap / LoadKeyFrameMap: every field round trips, images within the documented
// rounding, saves replace files only when complete (concurrent saves too, the previous file kept
// on request), the writer refuses what the reader would (covariances not positive definite, ids
// and frame indices near INT_MAX), version 1 files load with a warning, CheckCompatible names a
// foreign camera, vocabulary or ORB / depth noise settings.
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/core/binary_io.h"
#include "dslam/core/config.h"
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

// The message of SaveKeyFrameMap(path, file) with the process's file size limit `bytes`
// (SIGXFSZ ignored: a write past it fails as on a full disk), the limit restored after it.
std::string SaveWithFileSizeLimit(const std::string& path, const KeyFrameMapFile& file,
                                  rlim_t bytes) {
  struct rlimit old_limit;
  ::getrlimit(RLIMIT_FSIZE, &old_limit);
  struct rlimit limit = old_limit;
  limit.rlim_cur = bytes;
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  ::setrlimit(RLIMIT_FSIZE, &limit);
  const std::string message =
      test::ThrownMessage<std::runtime_error>([&] { SaveKeyFrameMap(path, file); });
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  return message;
}

// The names in `dir`, sorted.
std::vector<std::string> Names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(KeyFrameMapFile, RoundTripKeepsEveryField) {
  const KeyFrameMapFile saved = SampleMapFile(7, 4, true);
  const std::string path = (TempDir("kfm_round_trip") / "map.bin").string();
  SaveKeyFrameMap(path, saved);
  const KeyFrameMapFile loaded = LoadKeyFrameMap(path);
  EXPECT_EQ(GetLittleEndian(ReadWholeFile(path, "test"), 8, 4), kKeyFrameMapVersion);
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
  EXPECT_EQ(kKeyFrameMapHeaderBytes, 180u);
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

TEST(KeyFrameMapFile, WriterRefusesCovariancesAndSigmasThatAreNotPositive) {
  const auto refused = [](const KeyFrameMapFile& file) {
    return test::ThrownMessage<std::invalid_argument>([&] { SerialiseKeyFrameMap(file); });
  };
  const std::string point = "map point 4 has a covariance (cov_world) that is not symmetric";
  KeyFrameMapFile file = SampleMapFile(3, 2, false);
  file.contents.points[1].cov_world(0, 1) += 1e-4;  // not symmetric
  EXPECT_NE(refused(file).find(point), std::string::npos) << refused(file);
  file.contents.points[1].cov_world = -Eigen::Matrix3d::Identity();
  EXPECT_NE(refused(file).find(point), std::string::npos);
  file.contents.points[1].cov_world = Eigen::Vector3d(1e-4, 1e-4, 0.0).asDiagonal();
  EXPECT_NE(refused(file).find(point), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.contents.keyframes[0].information(2, 2) = -1.0;
  EXPECT_NE(refused(file).find("keyframe 5 has an information matrix that is neither zero "
                               "(unknown) nor symmetric positive definite"),
            std::string::npos);
  file.contents.keyframes[0].information.setZero();  // unknown (a first keyframe): kept
  EXPECT_NO_THROW(SerialiseKeyFrameMap(file));
  PointMeasurement& m = file.contents.keyframes[0].measurements.by_point.at(4);
  m.depth_sigma_m = 0.0;
  EXPECT_NE(refused(file).find("keyframe 5 has a measurement of point 4 that has depth_sigma_m 0, "
                               "not > 0"),
            std::string::npos);
  m.depth_sigma_m = -0.01;
  EXPECT_NE(refused(file).find("depth_sigma_m -0.01, not > 0"), std::string::npos);
  m.depth_sigma_m = 0.01;
  m.covariance = Eigen::Matrix3d::Zero();
  EXPECT_NE(refused(file).find("keyframe 5 has a measurement of point 4 that has a covariance "
                               "that is not symmetric positive definite"),
            std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.settings->orb_levels = 0;
  EXPECT_NE(refused(file).find("settings: features.num_levels 0, not >= 1"), std::string::npos);
  file = SampleMapFile(3, 2, false);
  file.settings->depth_noise.pixel_sigma_px = 0.0;
  EXPECT_NE(refused(file).find("settings: depth_noise.pixel_sigma_px 0, not finite and > 0"),
            std::string::npos);
}

TEST(KeyFrameMapFile, IdsAndFrameIndicesNearTheirLimitAreRefused) {
  const auto refused = [](const KeyFrameMapFile& file) {
    return test::ThrownMessage<std::invalid_argument>([&] { SerialiseKeyFrameMap(file); });
  };
  KeyFrameMapFile file = SampleMapFile(3, 2, false);
  file.contents.keyframes[1].frame_index = std::numeric_limits<int>::max();
  EXPECT_NE(refused(file).find("keyframe 7 has frame_index 2147483647, above 1073741823"),
            std::string::npos)
      << refused(file);
  file.contents.keyframes[1].frame_index = kKeyFrameMapMaxIndex;  // the largest allowed
  EXPECT_NO_THROW(SerialiseKeyFrameMap(file));
  file = SampleMapFile(3, 2, false);
  file.contents.keyframes[1].id = std::numeric_limits<int>::max();
  EXPECT_NE(refused(file).find("keyframe id 2147483647 is above 1073741823"), std::string::npos);
  file.contents.keyframes[1].id = kKeyFrameMapMaxIndex;
  EXPECT_NO_THROW(SerialiseKeyFrameMap(file));
  file = SampleMapFile(3, 2, false);
  file.contents.points[2].id = std::numeric_limits<PointId>::max();
  EXPECT_NE(refused(file).find("map point id 9223372036854775807 is above 4611686018427387903"),
            std::string::npos);
}

TEST(KeyFrameMapFile, Version1FilesLoadWithAWarning) {
  KeyFrameMapFile v1 = SampleMapFile(7, 4, true);
  v1.settings.reset();
  const std::string bytes = SerialiseKeyFrameMap(v1);
  const std::string v2 = SerialiseKeyFrameMap(SampleMapFile(7, 4, true));
  // Version 1's layout: its 128-byte header is version 2's without the settings.
  EXPECT_EQ(GetLittleEndian(bytes, 8, 4), 1u);
  ASSERT_EQ(bytes.size() + 52, v2.size());
  EXPECT_EQ(bytes.substr(28, 100), v2.substr(28, 100));
  EXPECT_EQ(bytes.substr(128), v2.substr(180));
  const std::string path = (TempDir("kfm_version_1") / "map.bin").string();
  WriteFileAtomically(path, bytes, "test");
  const KeyFrameMapFile loaded = LoadKeyFrameMap(path);
  EXPECT_FALSE(loaded.settings.has_value());
  test::ExpectSameMap(v1, loaded);
  EXPECT_EQ(loaded.images.size(), 2u);
  EXPECT_EQ(KeyFrameMapWarning(loaded),
            "format version 1: the ORB and depth noise settings the map was made with are not "
            "in the file and cannot be checked against this run's");
  EXPECT_EQ(KeyFrameMapWarning(SampleMapFile(1, 1, false)), "");
  // Any settings pass: they cannot be checked. Written again, it stays version 1.
  EXPECT_EQ(
      CheckCompatible(loaded, test::SampleCamera(), v1.vocabulary_identity, KeyFrameMapSettings{}),
      "");
  EXPECT_EQ(GetLittleEndian(SerialiseKeyFrameMap(loaded), 8, 4), 1u);
}

TEST(KeyFrameMapFile, LoadRefusesDamagedFilesAsTheParserDoes) {
  const std::filesystem::path dir = TempDir("kfm_damaged");
  const std::string bytes = SerialiseKeyFrameMap(SampleMapFile(7, 4, true));
  const std::string path = (dir / "map.bin").string();
  const auto why = [&](const std::string& content) {
    WriteFileAtomically(path, content, "test");
    return test::ThrownMessage<KeyFrameMapError>([&] { LoadKeyFrameMap(path); });
  };
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x01;
  EXPECT_EQ(why(flipped), path + ": checksum mismatch: the file is corrupt");
  EXPECT_EQ(why(bytes.substr(0, 1000)),
            path + ": truncated: expected " + std::to_string(bytes.size()) + " bytes, got 1000");
  EXPECT_EQ(why(""), path + ": empty file, not a dslam keyframe map");
  EXPECT_NE(why("hello").find("not a dslam keyframe map"), std::string::npos);
  EXPECT_NE(why(bytes + "x").find("corrupt: "), std::string::npos);
  WriteFileAtomically(path, bytes, "test");
  EXPECT_NO_THROW(LoadKeyFrameMap(path));
}

TEST(KeyFrameMapFile, ConcurrentSavesToOnePathAllSucceed) {
  const std::filesystem::path dir = TempDir("kfm_concurrent");
  const std::string path = (dir / "map.bin").string();
  const KeyFrameMapFile files[2] = {SampleMapFile(60, 6, true), SampleMapFile(61, 5, true)};
  const std::string bytes[2] = {SerialiseKeyFrameMap(files[0]), SerialiseKeyFrameMap(files[1])};
  std::atomic<int> failures{0};
  const auto save = [&](int which) {
    for (int i = 0; i < 20; ++i) {
      try {
        SaveKeyFrameMap(path, files[which]);
      } catch (const std::exception& e) {
        ++failures;
        ADD_FAILURE() << e.what();
      }
    }
  };
  std::thread first(save, 0), second(save, 1);
  first.join();
  second.join();
  EXPECT_EQ(failures.load(), 0);
  const std::string now = ReadWholeFile(path, "test");
  EXPECT_TRUE(now == bytes[0] || now == bytes[1]);
  EXPECT_NO_THROW(LoadKeyFrameMap(path));
  EXPECT_EQ(Names(dir), (std::vector<std::string>{"map.bin"}));  // no temporary file left
}

TEST(KeyFrameMapFile, KeepingThePreviousFileKeepsItAsPrev) {
  const std::filesystem::path dir = TempDir("kfm_previous");
  const std::string path = (dir / "map.bin").string();
  const std::string bytes[3] = {SerialiseKeyFrameMap(SampleMapFile(3, 2, true)),
                                SerialiseKeyFrameMap(SampleMapFile(4, 2, true)),
                                SerialiseKeyFrameMap(SampleMapFile(5, 2, true))};
  SaveKeyFrameMap(path, SampleMapFile(3, 2, true), PreviousFile::kKeep);  // nothing to keep
  EXPECT_EQ(Names(dir), (std::vector<std::string>{"map.bin"}));
  SaveKeyFrameMap(path, SampleMapFile(4, 2, true), PreviousFile::kKeep);
  EXPECT_EQ(ReadWholeFile(path, "test"), bytes[1]);
  EXPECT_EQ(ReadWholeFile(path + ".prev", "test"), bytes[0]);
  SaveKeyFrameMap(path, SampleMapFile(5, 2, true), PreviousFile::kKeep);
  EXPECT_EQ(ReadWholeFile(path, "test"), bytes[2]);
  EXPECT_EQ(ReadWholeFile(path + ".prev", "test"), bytes[1]);
  EXPECT_NO_THROW(LoadKeyFrameMap(path + ".prev"));
  SaveKeyFrameMap(path, SampleMapFile(3, 2, true));  // replacing: .prev stays as it was
  EXPECT_EQ(ReadWholeFile(path, "test"), bytes[0]);
  EXPECT_EQ(ReadWholeFile(path + ".prev", "test"), bytes[1]);
  EXPECT_EQ(Names(dir), (std::vector<std::string>{"map.bin", "map.bin.prev"}));
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
  // The temporary file cannot be written whole (a file size limit, as on a full disk): map.bin
  // stays as it was and the temporary file is removed.
  const std::string cannot_write = SaveWithFileSizeLimit(path, SampleMapFile(50, 3, true), 1000);
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid()) + "-";
  EXPECT_EQ(cannot_write.rfind("SaveKeyFrameMap: cannot write " + temporary, 0), 0u)
      << cannot_write;
  EXPECT_EQ(ReadWholeFile(path, "test"), old_bytes);
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
  EXPECT_EQ(Names(dir), (std::vector<std::string>{"folder", "map.bin"}));
  EXPECT_THROW(SaveKeyFrameMap((dir / "missing" / "m.bin").string(), SampleMapFile(1, 1, false)),
               std::runtime_error);
}

TEST(KeyFrameMapFile, CheckCompatibleNamesForeignCameraAndVocabulary) {
  const KeyFrameMapFile file = SampleMapFile(1, 1, false);
  const KeyFrameMapSettings kSettings = test::SampleSettings();
  EXPECT_EQ(CheckCompatible(file, test::SampleCamera(), file.vocabulary_identity, kSettings), "");
  const PinholeCamera other(16, 12, 20.5, 21.25, 7.75, 5.6, test::SampleCamera().distortion());
  const std::string camera = CheckCompatible(file, other, file.vocabulary_identity, kSettings);
  EXPECT_EQ(camera.rfind("recorded with another camera (16x12 fx 20.5 fy 21.25 cx 7.75 cy 5.5 ", 0),
            0u)
      << camera;
  EXPECT_NE(camera.find(") than this run's (16x12 fx 20.5 fy 21.25 cx 7.75 cy 5.6 "),
            std::string::npos)
      << camera;
  const PinholeCamera undistorted(16, 12, 20.5, 21.25, 7.75, 5.5);
  EXPECT_NE(CheckCompatible(file, undistorted, file.vocabulary_identity, kSettings), "");
  EXPECT_EQ(CheckCompatible(file, test::SampleCamera(), 0x0123456789abcdefull, kSettings),
            "recorded with vocabulary 723a8e39b1688a18 but this run uses 0123456789abcdef");
}

TEST(KeyFrameMapFile, CheckCompatibleNamesOtherOrbAndDepthNoiseSettings) {
  const KeyFrameMapFile file = SampleMapFile(1, 1, false);
  const auto why = [&](const KeyFrameMapSettings& settings) {
    return CheckCompatible(file, test::SampleCamera(), file.vocabulary_identity, settings);
  };
  EXPECT_EQ(why(test::SampleSettings()), "");
  KeyFrameMapSettings s = test::SampleSettings();
  s.orb_scale_factor *= 1.0 + 1e-12;  // within 1e-9: the same
  EXPECT_EQ(why(s), "");
  s.orb_scale_factor = 1.2;
  EXPECT_EQ(why(s), "recorded with features.scale_factor 1.25 but this run uses 1.2");
  s = test::SampleSettings();
  s.orb_levels = 8;
  EXPECT_EQ(why(s), "recorded with features.num_levels 6 but this run uses 8");
  s = test::SampleSettings();
  s.depth_noise.sigma_d_quadratic = 1.4e-3;
  EXPECT_EQ(why(s), "recorded with depth_noise.sigma_d_quadratic 0.002 but this run uses 0.0014");
  s = test::SampleSettings();
  s.depth_noise.pixel_sigma_px = 1.0;
  EXPECT_EQ(why(s), "recorded with depth_noise.pixel_sigma_px 1.5 but this run uses 1");
  s = test::SampleSettings();
  s.depth_noise.max_depth_m = 6.0;
  EXPECT_EQ(why(s), "recorded with depth_noise.max_depth_m 7.5 but this run uses 6");
  // A run's settings come from its config.
  Config config;
  config.features.num_levels = 6;
  config.features.scale_factor = 1.25;
  config.depth_noise = test::SampleSettings().depth_noise;
  EXPECT_EQ(why(KeyFrameMapSettingsOf(config)), "");
  EXPECT_NE(why(KeyFrameMapSettingsOf(Config())), "");
}

}  // namespace
}  // namespace dslam

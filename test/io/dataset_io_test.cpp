#include <sys/stat.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "dslam/io/dataset_io.h"

namespace dslam {
namespace {

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

TEST(FileList, SkipsCommentsAndRejectsMalformedLines) {
  const std::string path = testing::TempDir() + "/dslam_list.txt";
  WriteText(path, "# colour\n# timestamp filename\n1.0 rgb/1.png\n\n2.5 rgb/2.png\n");
  const auto files = ReadFileList(path);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_DOUBLE_EQ(files[1].stamp_s, 2.5);
  EXPECT_EQ(files[1].path, "rgb/2.png");
  WriteText(path, "1.0\n");
  EXPECT_THROW(ReadFileList(path), std::runtime_error);
}

TEST(Association, NearestWithinToleranceEachDepthOnce) {
  const std::vector<StampedFile> colour = {{1.00, "c1"}, {1.033, "c2"}, {1.060, "c3"}, {2.0, "c4"}};
  const std::vector<StampedFile> depth = {{0.995, "d1"}, {1.040, "d2"}, {1.045, "d3"}};
  const auto pairs = AssociateByStamp(colour, depth, 0.02);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].depth.path, "d1");
  EXPECT_EQ(pairs[1].depth.path, "d2");  // 1.033 <-> 1.040 (dt 0.007) wins over d3
  EXPECT_EQ(pairs[2].depth.path, "d3");  // 1.060 <-> 1.045 (dt 0.015); 2.0 has no partner
}

TEST(CameraYaml, ReadsIntrinsicsDistortionAndCorrection) {
  const std::string path = testing::TempDir() + "/dslam_camera.yaml";
  WriteText(path,
            "width: 640\nheight: 480\nfx: 542.8\nfy: 542.5\ncx: 315.5\ncy: 237.7\n"
            "k1: 0.04\nk2: -0.1\np1: -0.0007\np2: -0.0001\nk3: 0\n"
            "depth_scale: 5000.0\ngroundtruth_correction: bonn\n");
  const CameraYaml cam = LoadCameraYaml(path);
  EXPECT_DOUBLE_EQ(cam.camera->fx(), 542.8);
  EXPECT_DOUBLE_EQ(cam.camera->distortion().k2, -0.1);
  EXPECT_EQ(cam.groundtruth_correction, GroundTruthCorrection::kBonn);
  WriteText(path, "width: 640\nheight: 480\nfx: 1\nfy: 1\ncx: 0\n");
  EXPECT_THROW(LoadCameraYaml(path), std::runtime_error);  // cy missing
  WriteText(path,
            "width: 640\nheight: 480\nfx: 1\nfy: 1\ncx: 0\ncy: 0\n"
            "groundtruth_correction: vicon\n");
  EXPECT_THROW(LoadCameraYaml(path), std::runtime_error);
}

TEST(TumDataset, LoadsAssociatedFrames) {
  const std::string dir = testing::TempDir() + "/dslam_tum_dataset";
  mkdir(dir.c_str(), 0755);
  mkdir((dir + "/rgb").c_str(), 0755);
  mkdir((dir + "/depth").c_str(), 0755);
  WriteText(dir + "/camera.yaml", "width: 8\nheight: 6\nfx: 5\nfy: 5\ncx: 4\ncy: 3\n");
  WriteText(dir + "/rgb.txt", "# rgb\n10.00 rgb/a.png\n10.10 rgb/b.png\n");
  WriteText(dir + "/depth.txt", "10.01 depth/a.png\n10.50 depth/b.png\n");
  cv::imwrite(dir + "/rgb/a.png", cv::Mat(6, 8, CV_8UC3, cv::Scalar(10, 20, 30)));
  cv::imwrite(dir + "/depth/a.png", cv::Mat(6, 8, CV_16UC1, cv::Scalar(7500)));
  const TumDataset dataset(dir, "", 0.02);
  ASSERT_EQ(dataset.size(), 1u);  // b has no depth partner within 0.02 s
  const RgbdFrame frame = dataset.LoadFrame(0);
  EXPECT_DOUBLE_EQ(frame.stamp_s, 10.0);
  EXPECT_FLOAT_EQ(frame.depth_m.at<float>(5, 7), 1.5f);
  EXPECT_EQ(frame.colour.at<cv::Vec3b>(0, 0)[2], 30);
  EXPECT_EQ(frame.Check(), "");
}

}  // namespace
}  // namespace dslam

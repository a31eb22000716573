// camera.yaml inputs that fuzzing (test/fuzz/) found to crash or pass unchecked: each is now
// rejected with a std::runtime_error that names the file and the key.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dslam/io/dataset_io.h"

namespace dslam {
namespace {

const char kIntrinsics[] = "fx: 500\nfy: 500\ncx: 320\ncy: 240\n";

/// The message of the std::runtime_error ParseCameraYaml throws for `text` ("" for none).
std::string ErrorOf(const std::string& text) {
  try {
    ParseCameraYaml(text, "cam.yaml");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CameraYaml, ParsesText) {
  const CameraYaml parsed = ParseCameraYaml(
      std::string("width: 640\nheight: 480\n") + kIntrinsics + "depth_scale: 1000\n", "cam.yaml");
  EXPECT_EQ(parsed.camera->width(), 640);
  EXPECT_DOUBLE_EQ(parsed.depth_scale, 1000.0);
}

/// A camera's own depth noise: both keys or neither, each in [0, 0.1]; UseCameraDepthNoise sets
/// depth_noise from it and leaves depth_noise alone when the file states none.
TEST(CameraYaml, DepthNoiseIsTheCamerasWhenStated) {
  const std::string base = std::string("width: 640\nheight: 480\n") + kIntrinsics;
  DepthNoiseConfig noise;
  noise.sigma_d_quadratic = 0.5e-3;
  noise.sigma_d_constant_m = 0.5e-3;
  const DepthNoiseConfig before = noise;
  EXPECT_FALSE(UseCameraDepthNoise(ParseCameraYaml(base, "cam.yaml"), &noise));
  EXPECT_EQ(noise.sigma_d_quadratic, before.sigma_d_quadratic);
  EXPECT_EQ(noise.sigma_d_constant_m, before.sigma_d_constant_m);
  const CameraYaml stated = ParseCameraYaml(
      base + "depth_sigma_d_quadratic: 0.0014\ndepth_sigma_d_constant_m: 0.001\n", "cam.yaml");
  EXPECT_TRUE(UseCameraDepthNoise(stated, &noise));
  EXPECT_EQ(noise.sigma_d_quadratic, 0.0014);
  EXPECT_EQ(noise.sigma_d_constant_m, 0.001);
  EXPECT_EQ(noise.pixel_sigma_px, before.pixel_sigma_px);
  EXPECT_NE(ErrorOf(base + "depth_sigma_d_quadratic: 0.0014\n").find("cam.yaml: give both"),
            std::string::npos);
  EXPECT_NE(ErrorOf(base + "depth_sigma_d_quadratic: 0.2\ndepth_sigma_d_constant_m: 0.001\n")
                .find("depth_sigma_d_quadratic must be in [0, 0.1]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(base + "depth_sigma_d_quadratic: 0.001\ndepth_sigma_d_constant_m: .nan\n")
                .find("depth_sigma_d_constant_m"),
            std::string::npos);
  EXPECT_EQ(CameraYamlPath("/data/seq", ""), "/data/seq/camera.yaml");
  EXPECT_EQ(CameraYamlPath("/data/seq", "/calib/cam.yaml"), "/calib/cam.yaml");
}

TEST(CameraYaml, RejectsTopLevelThatIsNotAMap) {
  // yaml-cpp's "operator[] call on a scalar" escaped before, naming neither file nor key.
  EXPECT_NE(ErrorOf("2 bon-BRnlmu# r").find("cam.yaml: expected a map"), std::string::npos);
  EXPECT_NE(ErrorOf("[1, 2]").find("cam.yaml: expected a map"), std::string::npos);
}

TEST(CameraYaml, RejectsSidesThatAreNotWholePixelCountsInRange) {
  // 1e10 cast to int was undefined behaviour before the check.
  EXPECT_NE(ErrorOf(std::string("width: 1e10\nheight: 480\n") + kIntrinsics).find("'width'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(std::string("width: 640\nheight: 479.5\n") + kIntrinsics).find("'height'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(std::string("width: .nan\nheight: 480\n") + kIntrinsics).find("'width'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(std::string("width: 16384\nheight: 16384\n") + kIntrinsics).find("pixels"),
            std::string::npos);
}

TEST(CameraYaml, RejectsNonFiniteIntrinsicsBadScalesAndNonStringCorrection) {
  const std::string size = "width: 640\nheight: 480\n";
  EXPECT_NE(ErrorOf(size + "fx: .inf\nfy: 500\ncx: 320\ncy: 240\n").find("cam.yaml"),
            std::string::npos);
  EXPECT_NE(ErrorOf(size + kIntrinsics + "depth_scale: 1e300\n").find("depth_scale"),
            std::string::npos);
  EXPECT_NE(ErrorOf(size + kIntrinsics + "groundtruth_correction: {a: 1}\n")
                .find("'groundtruth_correction' is not a string"),
            std::string::npos);
}

}  // namespace
}  // namespace dslam

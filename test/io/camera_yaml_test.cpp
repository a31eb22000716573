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

// Bounds on sizes and values read from files and messages (found by fuzzing, test/fuzz/): image
// sizes, camera intrinsics, depth scales, PNG headers.
#include "dslam/core/image_limits.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dslam/core/camera.h"
#include "dslam/core/depth_conversion.h"

namespace dslam {
namespace {

/// The message of the std::exception `f` throws ("" when it throws none).
template <typename F>
std::string ErrorOf(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(ImageLimits, CheckImageSizeNamesTheProblem) {
  EXPECT_NO_THROW(CheckImageSize(7680, 4320, "x"));
  EXPECT_NO_THROW(CheckImageSize(kMaxImageSidePx, 1, "x"));
  EXPECT_NE(ErrorOf([] { CheckImageSize(0, 480, "img"); }).find("img: image size 0x480 is empty"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { CheckImageSize(16385, 2, "img"); }).find("side above 16384"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { CheckImageSize(16384, 16384, "img"); }).find("more than 33554432"),
            std::string::npos);
  EXPECT_THROW(CheckImageSize(int64_t{1} << 32, 1, "img"), std::invalid_argument);
}

TEST(ImageLimits, CameraRejectsAbsurdSizesAndNonFiniteIntrinsics) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(PinholeCamera(100000, 480, 500, 500, 320, 240), std::invalid_argument);
  EXPECT_THROW(PinholeCamera(640, 480, inf, 500, 320, 240), std::invalid_argument);
  EXPECT_THROW(PinholeCamera(640, 480, 500, 500, nan, 240), std::invalid_argument);
  Distortion d;
  d.k2 = inf;
  EXPECT_THROW(PinholeCamera(640, 480, 500, 500, 320, 240, d), std::invalid_argument);
}

TEST(ImageLimits, DepthConversionRejectsEmptyImagesAndScalesOutsideItsRange) {
  EXPECT_THROW(DepthFromScaledUint16(cv::Mat(3, 0, CV_16UC1), 5000.0), std::invalid_argument);
  EXPECT_THROW(DepthFromMetres(cv::Mat(0, 2, CV_32FC1)), std::invalid_argument);
  const cv::Mat raw(1, 1, CV_16UC1, cv::Scalar(5000));
  // 1e215 units per metre turned every measurement into 0 (no measurement) before the bound.
  EXPECT_NE(ErrorOf([&] { DepthFromScaledUint16(raw, 1e215); }).find("units per metre"),
            std::string::npos);
  EXPECT_THROW(DepthFromScaledUint16(raw, 0.5), std::invalid_argument);
  EXPECT_THROW(DepthFromScaledUint16(raw, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  EXPECT_FLOAT_EQ(DepthFromScaledUint16(raw, kMaxDepthUnitsPerMetre).at<float>(0, 0), 0.005f);
}

TEST(ImageLimits, PngHeaderBeyondLimitsIsRejectedBeforeDecoding) {
  // Signature, IHDR of 32768 x 32767 16-bit grey (CRC not checked before the size), no data:
  // OpenCV would allocate 2 GB and decode for seconds.
  const unsigned char header[] = {0x89, 'P', 'N',  'G',  '\r', '\n', 0x1a, '\n', 0,    0,
                                  0,    13,  'I',  'H',  'D',  'R',  0,    0,    0x80, 0,
                                  0,    0,   0x7f, 0xff, 16,   0,    0,    0,    0};
  const std::string path = testing::TempDir() + "/dslam_huge_header.png";
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(header), sizeof(header));
  const std::string error = ErrorOf([&] { ReadDepthPng(path, 5000.0); });
  EXPECT_NE(error.find("PNG header: image size 32768x32767"), std::string::npos) << error;
  EXPECT_NO_THROW(CheckImageFile(path + ".missing", false));  // the reader reports it
}

TEST(ImageLimits, DepthFilesOtherThanPngAreNotDecoded) {
  // 128 bytes and "DICM": OpenCV hands the file to GDCM, whose reader asserts (abort) on it
  // (found by fuzz_depth_conversion; test/fuzz/regressions/depth_conversion/dicom_gdcm_abort).
  const std::string path = testing::TempDir() + "/dslam_dicom_like.png";
  std::ofstream(path, std::ios::binary) << std::string(128, '\xc8') << "DICM\x02";
  const std::string error = ErrorOf([&] { ReadDepthPng(path, 5000.0); });
  EXPECT_NE(error.find("not a PNG file"), std::string::npos) << error;
  std::ofstream(path, std::ios::binary) << "\xff\xd8\xff" << std::string(40, '\0');
  EXPECT_NO_THROW(CheckImageFile(path, /*allow_jpeg=*/true));
  EXPECT_THROW(CheckImageFile(path, /*allow_jpeg=*/false), std::runtime_error);
}

}  // namespace
}  // namespace dslam

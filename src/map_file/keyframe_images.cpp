// A keyframe's images in the keyframe map file: colour as a lossless PNG, depth as a 16-bit PNG
// of millimetres (rounding in dslam/map_file/keyframe_map_file.h), and their checked decoding.
#include <cmath>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "dslam/core/depth_conversion.h"
#include "dslam/core/image_limits.h"
#include "keyframe_map_internal.h"

namespace dslam {
namespace map_file {
namespace {

constexpr int kPngCompression = 3;  // zlib level: smaller than OpenCV's default 1, still fast

std::string EncodePng(const cv::Mat& image) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, kPngCompression})) {
    throw std::runtime_error("SerialiseKeyFrameMap: PNG encoding failed");
  }
  return std::string(bytes.begin(), bytes.end());
}

// Decodes `png` after checking that it is a PNG (so that no other decoder of OpenCV sees it) of
// the camera's size (so that nothing larger is allocated); the image, or an empty one when that
// fails or the image has another size.
cv::Mat DecodePng(const std::string& png, const PinholeCamera& camera) {
  const auto* data = reinterpret_cast<const unsigned char*>(png.data());
  const auto size = PngHeaderSize(data, png.size());
  if (!size || (*size)[0] != camera.width() || (*size)[1] != camera.height()) return cv::Mat();
  cv::Mat image;
  try {
    image =
        cv::imdecode(cv::Mat(1, static_cast<int>(png.size()), CV_8U, const_cast<char*>(png.data())),
                     cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    return cv::Mat();
  }
  if (image.cols != camera.width() || image.rows != camera.height()) return cv::Mat();
  return image;
}

}  // namespace

std::string EncodeColour(const cv::Mat& colour) { return EncodePng(colour); }

std::string EncodeDepth(const cv::Mat& depth_m) {
  cv::Mat millimetres(depth_m.size(), CV_16UC1);
  for (int r = 0; r < depth_m.rows; ++r) {
    const float* in = depth_m.ptr<float>(r);
    auto* out = millimetres.ptr<std::uint16_t>(r);
    for (int c = 0; c < depth_m.cols; ++c) {
      const double mm = std::round(1000.0 * static_cast<double>(in[c]));
      out[c] = mm >= 1.0 && mm <= 65535.0 ? static_cast<std::uint16_t>(mm) : 0;
    }
  }
  return EncodePng(millimetres);
}

KeyFrameImages DecodeImages(const std::string& colour_png, const std::string& depth_png,
                            const PinholeCamera& camera, int id, const std::string& name) {
  const std::string prefix = name + ": invalid content: keyframe " + std::to_string(id) + "'s ";
  KeyFrameImages images;
  images.colour = DecodePng(colour_png, camera);
  const int type = images.colour.type();
  if (images.colour.empty() || (type != CV_8UC3 && type != CV_8UC1)) {
    throw KeyFrameMapError(prefix + "colour image is not an 8-bit PNG of the camera's size");
  }
  const cv::Mat millimetres = DecodePng(depth_png, camera);
  if (millimetres.empty() || millimetres.type() != CV_16UC1) {
    throw KeyFrameMapError(prefix + "depth image is not a 16-bit PNG of the camera's size");
  }
  images.depth_m = DepthFromMillimetres(millimetres);
  return images;
}

}  // namespace map_file
}  // namespace dslam

// CameraFromInfo (conversions.h): sensor_msgs/CameraInfo -> PinholeCamera with every field it
// reads checked, each failure naming the field.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dslam/ros/conversions.h"

namespace dslam {
namespace ros_layer {
namespace {

std::string Number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string SizeText(uint32_t width, uint32_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

[[noreturn]] void Fail(const std::string& problem) {
  throw std::invalid_argument("camera_info " + problem);
}

void CheckFinite(double value, const std::string& field) {
  if (std::isnan(value)) Fail(field + " is NaN");
  if (std::isinf(value)) Fail(field + " is infinite");
}

void CheckFocal(double value, const std::string& field) {
  CheckFinite(value, field);
  if (value <= 0.0) Fail(field + " is " + Number(value) + " (not calibrated; must be positive)");
}

void CheckCentre(double value, uint32_t extent, const std::string& field, const char* axis) {
  CheckFinite(value, field);
  if (value < 0.0 || value > extent) {
    Fail(field + " is " + Number(value) + ", outside the image " + axis + " [0, " +
         std::to_string(extent) + "]");
  }
}

void CheckZero(double value, const std::string& field, const std::string& meaning) {
  CheckFinite(value, field);
  if (value != 0.0) Fail(field + " is " + Number(value) + ": " + meaning);
}

void CheckSize(const sensor_msgs::CameraInfo& info, const sensor_msgs::Image& colour) {
  if (info.width == 0 || info.height == 0) {
    Fail("size is " + SizeText(info.width, info.height) + " (not calibrated)");
  }
  if (info.width != colour.width || info.height != colour.height) {
    Fail("size " + SizeText(info.width, info.height) + " differs from the colour image's " +
         SizeText(colour.width, colour.height));
  }
  if (info.binning_x > 1 || info.binning_y > 1) {
    Fail("binning_x, binning_y are " + std::to_string(info.binning_x) + ", " +
         std::to_string(info.binning_y) + ": binned images are not supported");
  }
  const sensor_msgs::RegionOfInterest& roi = info.roi;
  const bool unset = roi.x_offset == 0 && roi.y_offset == 0 && roi.width == 0 && roi.height == 0;
  const bool full = roi.x_offset == 0 && roi.y_offset == 0 && roi.width == info.width &&
                    roi.height == info.height;
  if (!unset && !full) {
    Fail("roi (" + std::to_string(roi.x_offset) + ", " + std::to_string(roi.y_offset) + ") " +
         SizeText(roi.width, roi.height) + ": a region of interest is not supported");
  }
}

/// Plumb-bob coefficients from D: no distortion for an empty or all-zero D.
Distortion DistortionFromInfo(const sensor_msgs::CameraInfo& info) {
  const std::vector<double>& D = info.D;
  bool any = false;
  for (size_t i = 0; i < D.size(); ++i) {
    CheckFinite(D[i], "D[" + std::to_string(i) + "]");
    any = any || D[i] != 0.0;
  }
  const std::string& model = info.distortion_model;
  const size_t expected = model == "plumb_bob" ? 5 : model == "rational_polynomial" ? 8 : 0;
  if (expected == 0) {
    if (any) {
      Fail("distortion_model '" + model +
           "' is not supported with a non-zero D (supported: plumb_bob, rational_polynomial "
           "with k4..k6 = 0)");
    }
    return Distortion();
  }
  if (!D.empty() && D.size() != expected) {
    Fail("D has " + std::to_string(D.size()) + " coefficients, " + model + " needs " +
         std::to_string(expected));
  }
  if (!any) return Distortion();
  static const char* const kHigherRadial[] = {"k4", "k5", "k6"};
  for (size_t i = 5; i < D.size(); ++i) {
    CheckZero(D[i], "D[" + std::to_string(i) + "] (" + kHigherRadial[i - 5] + ")",
              "rational_polynomial k4..k6 are not supported");
  }
  Distortion d;
  d.k1 = D[0], d.k2 = D[1], d.p1 = D[2], d.p2 = D[3], d.k3 = D[4];
  return d;
}

}  // namespace

std::shared_ptr<const PinholeCamera> CameraFromInfo(const sensor_msgs::CameraInfo& info,
                                                    const sensor_msgs::Image& colour,
                                                    ImageGeometry geometry) {
  CheckSize(info, colour);
  const int width = static_cast<int>(info.width), height = static_cast<int>(info.height);
  if (geometry == ImageGeometry::kRaw) {
    const auto& K = info.K;
    CheckFocal(K[0], "K[0] (fx)");
    CheckFocal(K[4], "K[4] (fy)");
    CheckCentre(K[2], info.width, "K[2] (cx)", "width");
    CheckCentre(K[5], info.height, "K[5] (cy)", "height");
    CheckZero(K[1], "K[1] (skew)", "skewed pixel axes are not supported");
    return std::make_shared<const PinholeCamera>(width, height, K[0], K[4], K[2], K[5],
                                                 DistortionFromInfo(info));
  }
  const auto& P = info.P;
  CheckFocal(P[0], "P[0] (fx')");
  CheckFocal(P[5], "P[5] (fy')");
  CheckCentre(P[2], info.width, "P[2] (cx')", "width");
  CheckCentre(P[6], info.height, "P[6] (cy')", "height");
  CheckZero(P[1], "P[1] (skew)", "skewed pixel axes are not supported");
  CheckZero(P[3], "P[3] (Tx)",
            "the projection of a second stereo camera; use the reference (left) camera's");
  CheckZero(P[7], "P[7] (Ty)",
            "the projection of a second stereo camera; use the reference (upper) camera's");
  return std::make_shared<const PinholeCamera>(width, height, P[0], P[5], P[2], P[6]);
}

}  // namespace ros_layer
}  // namespace dslam

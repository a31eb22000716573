#include "dslam/io/dataset_io.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "dslam/core/depth_conversion.h"
#include "dslam/core/image_limits.h"
#include "dslam/io/stamp_association.h"

namespace dslam {
namespace {

double RequiredNumber(const YAML::Node& root, const std::string& key, const std::string& path) {
  const YAML::Node node = root[key];
  if (!node) throw std::runtime_error(path + ": missing key '" + key + "'");
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw std::runtime_error(path + ": key '" + key + "' is not a number");
  }
}

double OptionalNumber(const YAML::Node& root, const std::string& key, double fallback,
                      const std::string& path) {
  return root[key] ? RequiredNumber(root, key, path) : fallback;
}

/// An image side [px]: a whole number in [1, kMaxImageSidePx] (checked before the cast to int).
int RequiredSide(const YAML::Node& root, const std::string& key, const std::string& path) {
  const double value = RequiredNumber(root, key, path);
  if (!(value >= 1.0 && value <= kMaxImageSidePx) || value != std::floor(value)) {
    throw std::runtime_error(path + ": key '" + key + "' must be a whole number of pixels in [1, " +
                             std::to_string(kMaxImageSidePx) + "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

std::string OptionalString(const YAML::Node& root, const std::string& key,
                           const std::string& fallback, const std::string& path) {
  const YAML::Node node = root[key];
  if (!node) return fallback;
  try {
    return node.as<std::string>();
  } catch (const YAML::Exception&) {
    throw std::runtime_error(path + ": key '" + key + "' is not a string");
  }
}

/// depth_sigma_d_quadratic and depth_sigma_d_constant_m: both or neither, each in [0, 0.1].
void ReadDepthNoise(const YAML::Node& root, const std::string& path, CameraYaml* out) {
  const char* kQuadratic = "depth_sigma_d_quadratic";
  const char* kConstant = "depth_sigma_d_constant_m";
  if (!root[kQuadratic] && !root[kConstant]) return;
  if (!root[kQuadratic] || !root[kConstant]) {
    throw std::runtime_error(path + ": give both " + kQuadratic + " and " + kConstant +
                             " (the depth noise a d^2 + b) or neither");
  }
  const auto in_range = [&](const char* key) {
    const double value = RequiredNumber(root, key, path);
    if (!(value >= 0.0 && value <= 0.1)) {
      throw std::runtime_error(path + ": " + key + " must be in [0, 0.1], got " +
                               std::to_string(value));
    }
    return value;
  };
  out->depth_sigma_d_quadratic = in_range(kQuadratic);
  out->depth_sigma_d_constant_m = in_range(kConstant);
}

CameraYaml CameraYamlFromNode(const YAML::Node& root, const std::string& path) {
  if (!root.IsMap()) {
    throw std::runtime_error(path +
                             ": expected a map of keys (width, height, fx, fy, cx, cy, ...)");
  }
  Distortion d;
  d.k1 = OptionalNumber(root, "k1", 0.0, path);
  d.k2 = OptionalNumber(root, "k2", 0.0, path);
  d.p1 = OptionalNumber(root, "p1", 0.0, path);
  d.p2 = OptionalNumber(root, "p2", 0.0, path);
  d.k3 = OptionalNumber(root, "k3", 0.0, path);
  CameraYaml out;
  try {
    const int width = RequiredSide(root, "width", path),
              height = RequiredSide(root, "height", path);
    CheckImageSize(width, height, path);
    out.camera = std::make_shared<PinholeCamera>(
        width, height, RequiredNumber(root, "fx", path), RequiredNumber(root, "fy", path),
        RequiredNumber(root, "cx", path), RequiredNumber(root, "cy", path), d);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  out.depth_scale = OptionalNumber(root, "depth_scale", 5000.0, path);
  if (!(out.depth_scale >= kMinDepthUnitsPerMetre && out.depth_scale <= kMaxDepthUnitsPerMetre)) {
    throw std::runtime_error(path + ": depth_scale must be in [1, 1e6] units per metre, got " +
                             std::to_string(out.depth_scale));
  }
  ReadDepthNoise(root, path, &out);
  const std::string correction = OptionalString(root, "groundtruth_correction", "none", path);
  if (correction == "bonn") {
    out.groundtruth_correction = GroundTruthCorrection::kBonn;
  } else if (correction != "none") {
    throw std::runtime_error(path + ": groundtruth_correction must be none or bonn, got '" +
                             correction + "'");
  }
  return out;
}

}  // namespace

CameraYaml LoadCameraYaml(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error("cannot read camera file " + path + ": " + e.what());
  }
  return CameraYamlFromNode(root, path);
}

CameraYaml ParseCameraYaml(const std::string& yaml_text, const std::string& name) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error("cannot read camera file " + name + ": " + e.what());
  }
  return CameraYamlFromNode(root, name);
}

std::vector<StampedFile> ReadFileList(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open file list " + path);
  return ParseFileList(in, path);
}

std::vector<StampedFile> ParseFileList(std::istream& in, const std::string& path) {
  std::vector<StampedFile> files;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    StampedFile f;
    if (!(fields >> f.stamp_s >> f.path)) {
      throw std::runtime_error(path + ":" + std::to_string(line_number) +
                               ": expected 'stamp file'");
    }
    files.push_back(f);
  }
  return files;
}

std::vector<AssociatedPair> AssociateByStamp(const std::vector<StampedFile>& colour,
                                             const std::vector<StampedFile>& depth,
                                             double max_dt_s) {
  std::vector<double> colour_stamps, depth_stamps;
  for (const StampedFile& f : colour) colour_stamps.push_back(f.stamp_s);
  for (const StampedFile& f : depth) depth_stamps.push_back(f.stamp_s);
  std::vector<AssociatedPair> pairs;
  for (const auto& [c, d] : AssociateStamps(colour_stamps, depth_stamps, max_dt_s)) {
    pairs.push_back({colour[c], depth[d]});
  }
  return pairs;
}

std::string CameraYamlPath(const std::string& folder, const std::string& camera_yaml_path) {
  return camera_yaml_path.empty() ? folder + "/camera.yaml" : camera_yaml_path;
}

bool UseCameraDepthNoise(const CameraYaml& camera, DepthNoiseConfig* depth_noise) {
  if (!camera.depth_sigma_d_quadratic || !camera.depth_sigma_d_constant_m) return false;
  depth_noise->sigma_d_quadratic = *camera.depth_sigma_d_quadratic;
  depth_noise->sigma_d_constant_m = *camera.depth_sigma_d_constant_m;
  return true;
}

TumDataset::TumDataset(const std::string& folder, const std::string& camera_yaml_path,
                       double association_max_dt_s)
    : folder_(folder) {
  camera_yaml_ = LoadCameraYaml(CameraYamlPath(folder, camera_yaml_path));
  pairs_ = AssociateByStamp(ReadFileList(folder + "/rgb.txt"), ReadFileList(folder + "/depth.txt"),
                            association_max_dt_s);
}

RgbdFrame TumDataset::LoadFrame(size_t index) const {
  const AssociatedPair& pair = pairs_.at(index);
  RgbdFrame frame;
  frame.stamp_s = pair.colour.stamp_s;
  frame.camera = camera_yaml_.camera;
  CheckImageFile(folder_ + "/" + pair.colour.path, /*allow_jpeg=*/true);
  frame.colour = cv::imread(folder_ + "/" + pair.colour.path, cv::IMREAD_COLOR);
  if (frame.colour.empty()) {
    throw std::runtime_error("cannot read colour image " + folder_ + "/" + pair.colour.path);
  }
  frame.depth_m = ReadDepthPng(folder_ + "/" + pair.depth.path, camera_yaml_.depth_scale);
  return frame;
}

}  // namespace dslam

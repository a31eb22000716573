#include "dslam/synth/writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dslam/core/stopwatch.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/synth/object_truth.h"
#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

void WritePng(const std::string& path, const cv::Mat& image) {
  if (!cv::imwrite(path, image)) throw std::runtime_error("cannot write image " + path);
}

std::ofstream OpenText(const std::string& path, const std::string& header) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << header;
  return out;
}

}  // namespace

cv::Mat NoiseFreeDepthUnits(const cv::Mat& depth_true_m, double depth_scale) {
  cv::Mat units(depth_true_m.size(), CV_16UC1, cv::Scalar(0));
  for (int v = 0; v < depth_true_m.rows; ++v) {
    for (int u = 0; u < depth_true_m.cols; ++u) {
      const double value = std::round(depth_true_m.at<float>(v, u) * depth_scale);
      if (value >= 1.0 && value <= 65535.0) units.at<uint16_t>(v, u) = static_cast<uint16_t>(value);
    }
  }
  return units;
}

std::string FormatStamp(double stamp_s) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6f", stamp_s);
  return buffer;
}

void WriteCameraYaml(const std::string& path, const SensorParams& s) {
  const Distortion& d = s.distortion;
  std::ofstream out = OpenText(path, d.IsZero() ? "# dslam_synth camera: pinhole, no distortion\n"
                                                : "# dslam_synth camera: pinhole, plumb_bob\n");
  const auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.10g", value);
    return value == 0.0 ? std::string("0.0") : std::string(text);
  };
  out << "width: " << s.width << "\nheight: " << s.height << "\nfx: " << s.fx << "\nfy: " << s.fy
      << "\ncx: " << s.cx << "\ncy: " << s.cy << "\nk1: " << number(d.k1)
      << "\nk2: " << number(d.k2) << "\np1: " << number(d.p1) << "\np2: " << number(d.p2)
      << "\nk3: " << number(d.k3) << "\ndepth_scale: " << s.depth_scale
      << "\ngroundtruth_correction: none\n";
  if (!s.structured_light.enabled) {
    // The renderer's depth noise, independent per pixel: the tracker's depth model for this
    // camera (a structured-light render, like a real camera, states none).
    out << "depth_sigma_d_quadratic: " << number(s.depth_sigma_quadratic_per_m)
        << "\ndepth_sigma_d_constant_m: " << number(s.depth_sigma_constant_m) << "\n";
  }
  if (!out) throw std::runtime_error("error while writing " + path);
}

namespace {

/// The text files of a sequence folder that grow by one or more lines per frame.
struct FrameLists {
  std::ofstream rgb, depth, mask, depth_true, objects, coverage;

  FrameLists(const std::string& folder, const Scenario& sc) {
    const std::string note = "# dslam_synth " + sc.name + " seed " + std::to_string(sc.seed) + "\n";
    const std::string columns = "# timestamp filename\n";
    rgb = OpenText(folder + "/rgb.txt", "# color images\n" + note + columns);
    depth = OpenText(folder + "/depth.txt", "# depth maps\n" + note + columns);
    mask = OpenText(folder + "/mask.txt",
                    "# moving-object masks (16-bit id, 0 = static)\n" + note + columns);
    depth_true = OpenText(folder + "/depth_true.txt",
                          "# noise-free depth maps (16-bit, depth_scale units per metre, 0 = "
                          "nothing hit; no sensor range, dropouts or noise)\n" +
                              note + columns);
    objects = OpenText(folder + "/objects.txt", ObjectTruthHeader(sc));
    coverage = OpenText(folder + "/dynamic_coverage.txt",
                        "# timestamp fraction_of_pixels_on_moving_objects\n");
  }

  void Close(const std::string& folder) {
    for (std::ofstream* out : {&rgb, &depth, &mask, &depth_true, &objects, &coverage}) {
      out->flush();
      if (!*out) throw std::runtime_error("error while writing the file lists in " + folder);
    }
  }
};

/// Writes the images of frame `f` and its lines of the file lists.
void WriteFrame(const SyntheticSequence& sequence, const SyntheticFrame& f,
                const std::string& folder, FrameLists* lists) {
  const std::string stamp = FormatStamp(f.frame.stamp_s);
  WritePng(folder + "/rgb/" + stamp + ".png", f.frame.colour);
  WritePng(folder + "/depth/" + stamp + ".png", f.depth_units);
  WritePng(folder + "/mask/" + stamp + ".png", f.mask);
  WritePng(folder + "/depth_true/" + stamp + ".png",
           NoiseFreeDepthUnits(f.depth_true_m, sequence.scenario().sensor.depth_scale));
  lists->rgb << stamp << " rgb/" << stamp << ".png\n";
  lists->depth << stamp << " depth/" << stamp << ".png\n";
  lists->mask << stamp << " mask/" << stamp << ".png\n";
  lists->depth_true << stamp << " depth_true/" << stamp << ".png\n";
  for (const ObjectTruth& object : VisibleObjects(sequence, f)) {
    lists->objects << FormatObjectTruth(f.frame.stamp_s, object) << "\n";
  }
  char line[64];
  std::snprintf(line, sizeof(line), "%s %.6f\n", stamp.c_str(), f.dynamic_fraction);
  lists->coverage << line;
}

}  // namespace

WriteSummary WriteSequence(const SyntheticSequence& sequence, const std::string& folder, int frames,
                           const std::function<void(int, int)>& progress) {
  const Stopwatch watch;
  namespace fs = std::filesystem;
  for (const char* sub : {"rgb", "depth", "mask", "depth_true"}) {
    fs::create_directories(fs::path(folder) / sub);
  }
  const Scenario& sc = sequence.scenario();
  WriteCameraYaml(folder + "/camera.yaml", sc.sensor);
  std::ofstream info = OpenText(folder + "/synth_info.txt", "# dslam_synth sequence\n");
  info << "scenario: " << sc.name << "\nseed: " << sc.seed << "\nframes: " << frames << "\n";
  if (sc.camera.exposure.exposure_s > 0.0) {  // motion blur (motion_blur.h); absent when sharp
    info << "exposure_s: " << sc.camera.exposure.exposure_s << "\n";
  }
  FrameLists lists(folder, sc);
  Trajectory groundtruth;
  WriteSummary summary;
  summary.coverage_min = 1.0;
  for (int i = 0; i < frames; ++i) {
    const SyntheticFrame f = sequence.RenderFrame(i);
    WriteFrame(sequence, f, folder, &lists);
    groundtruth.push_back({f.frame.stamp_s, f.T_world_camera});
    summary.coverage_mean += f.dynamic_fraction / std::max(1, frames);
    summary.coverage_min = std::min(summary.coverage_min, f.dynamic_fraction);
    summary.coverage_max = std::max(summary.coverage_max, f.dynamic_fraction);
    if (progress) progress(i + 1, frames);
  }
  WriteTumTrajectory(folder + "/groundtruth.txt", groundtruth);
  lists.Close(folder);
  summary.frames = frames;
  summary.seconds = watch.ElapsedMs() / 1000.0;
  return summary;
}

cv::Mat MakePreviewPanel(const SyntheticFrame& f, double max_depth_m) {
  cv::Mat depth8, depth_colour, mask_colour(f.mask.size(), CV_8UC3, cv::Scalar::all(0));
  f.frame.depth_m.convertTo(depth8, CV_8UC1, 255.0 / max_depth_m);
  cv::applyColorMap(depth8, depth_colour, cv::COLORMAP_JET);
  depth_colour.setTo(cv::Scalar::all(0), f.frame.depth_m == 0.0f);
  for (int v = 0; v < f.mask.rows; ++v) {
    for (int u = 0; u < f.mask.cols; ++u) {
      const uint16_t id = f.mask.at<uint16_t>(v, u);
      if (id == 0) continue;
      const Eigen::Vector3f c = HashColour(Hash3(12345u, id, 0)) * 1.1f;
      mask_colour.at<cv::Vec3b>(v, u) =
          cv::Vec3b(cv::saturate_cast<uint8_t>(c[0]), cv::saturate_cast<uint8_t>(c[1]),
                    cv::saturate_cast<uint8_t>(c[2]));
    }
  }
  cv::Mat panel;
  cv::hconcat(std::vector<cv::Mat>{f.frame.colour, depth_colour, mask_colour}, panel);
  cv::resize(panel, panel, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  const char* labels[3] = {"colour", "depth", "mask"};
  for (int k = 0; k < 3; ++k) {
    cv::putText(panel, labels[k], cv::Point(8 + k * f.mask.cols / 2, 20), cv::FONT_HERSHEY_SIMPLEX,
                0.6, cv::Scalar(255, 255, 255), 2);
  }
  return panel;
}

}  // namespace synth
}  // namespace dslam

#include "dslam/synth/render.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kNear = 1e-3;  ///< [m] smallest accepted ray parameter (depth)

/// Pixel rectangle [u0, u1) x [v0, v1) that may contain a primitive.
struct Rect {
  int u0, v0, u1, v1;
};

/// Screen rectangle covering camera-frame points; the whole image if one is near or behind.
Rect ScreenRect(const std::vector<Eigen::Vector3d>& points, const PinholeCamera& camera) {
  Rect full{0, 0, camera.width(), camera.height()};
  double u_min = 1e18, u_max = -1e18, v_min = 1e18, v_max = -1e18;
  for (const Eigen::Vector3d& p : points) {
    if (p.z() < 0.02) return full;
    const Eigen::Vector2d uv = camera.Project(p);
    u_min = std::min(u_min, uv.x());
    u_max = std::max(u_max, uv.x());
    v_min = std::min(v_min, uv.y());
    v_max = std::max(v_max, uv.y());
  }
  auto clamp = [](double x, int hi) {
    return static_cast<int>(std::max(0.0, std::min(static_cast<double>(hi), x)));
  };
  return {
      clamp(std::floor(u_min) - 1, camera.width()), clamp(std::floor(v_min) - 1, camera.height()),
      clamp(std::ceil(u_max) + 2, camera.width()), clamp(std::ceil(v_max) + 2, camera.height())};
}

/// Per-view state: primitives moved into the camera frame, their rectangles, and the G-buffer.
struct Frame {
  const SceneGeometry& scene;
  const PinholeCamera& camera;
  Eigen::Isometry3d T_world_camera;
  std::vector<BoxInCamera> boxes;
  std::vector<Rect> box_rects;
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;  // camera frame
  std::vector<Rect> triangle_rects;
  std::vector<double> xn, yn;  // normalised coordinates of columns and rows
  std::vector<float> depth;
  std::vector<int32_t> primitive;  // box index, or boxes.size() + triangle index; -1 none
  std::vector<uint8_t> face;
  std::vector<Eigen::Vector2f> bary;
};

void Prepare(Frame* f) {
  const PinholeCamera& cam = f->camera;
  const Eigen::Isometry3d T_camera_world = f->T_world_camera.inverse();
  for (const Box& box : f->scene.boxes) {
    f->boxes.push_back(PrepareBox(box, f->T_world_camera));
    std::vector<Eigen::Vector3d> corners;
    for (int i = 0; i < 8 && !box.inward; ++i) {
      const Eigen::Vector3d c((i & 1 ? 1 : -1) * box.half_extent.x(),
                              (i & 2 ? 1 : -1) * box.half_extent.y(),
                              (i & 4 ? 1 : -1) * box.half_extent.z());
      corners.push_back(T_camera_world * (box.T_world_box * c));
    }
    f->box_rects.push_back(box.inward ? Rect{0, 0, cam.width(), cam.height()}
                                      : ScreenRect(corners, cam));
  }
  for (const Triangle& tri : f->scene.triangles) {
    std::array<Eigen::Vector3d, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = T_camera_world * tri.vertex[k];
    f->triangles.push_back(v);
    f->triangle_rects.push_back(ScreenRect({v[0], v[1], v[2]}, cam));
  }
  for (int u = 0; u < cam.width(); ++u) f->xn.push_back((u - cam.cx()) / cam.fx());
  for (int v = 0; v < cam.height(); ++v) f->yn.push_back((v - cam.cy()) / cam.fy());
  const size_t n = static_cast<size_t>(cam.width()) * cam.height();
  f->depth.assign(n, std::numeric_limits<float>::infinity());
  f->primitive.assign(n, -1);
  f->face.assign(n, 0);
  f->bary.assign(n, Eigen::Vector2f::Zero());
}

void CastRows(Frame* f, int row_begin, int row_end) {
  const int w = f->camera.width();
  for (size_t b = 0; b < f->boxes.size(); ++b) {
    const Rect& r = f->box_rects[b];
    const BoxInCamera& prepared = f->boxes[b];
    const Eigen::Matrix3d& R = prepared.R_box_camera;
    for (int v = std::max(row_begin, r.v0); v < std::min(row_end, r.v1); ++v) {
      const Eigen::Vector3d row_dir = R.col(1) * f->yn[v] + R.col(2);
      for (int u = r.u0; u < r.u1; ++u) {
        int face = 0;
        const double t =
            IntersectBox(f->scene.boxes[b], prepared, R.col(0) * f->xn[u] + row_dir, kNear, &face);
        const size_t i = static_cast<size_t>(v) * w + u;
        if (t > 0.0 && t < f->depth[i]) {
          f->depth[i] = static_cast<float>(t);
          f->primitive[i] = static_cast<int32_t>(b);
          f->face[i] = static_cast<uint8_t>(face);
        }
      }
    }
  }
  for (size_t k = 0; k < f->triangles.size(); ++k) {
    const Rect& r = f->triangle_rects[k];
    const auto& tri = f->triangles[k];
    for (int v = std::max(row_begin, r.v0); v < std::min(row_end, r.v1); ++v) {
      for (int u = r.u0; u < r.u1; ++u) {
        Eigen::Vector2d bary;
        const double t = IntersectTriangle(tri[0], tri[1], tri[2],
                                           Eigen::Vector3d(f->xn[u], f->yn[v], 1.0), kNear, &bary);
        const size_t i = static_cast<size_t>(v) * w + u;
        if (t > 0.0 && t < f->depth[i]) {
          f->depth[i] = static_cast<float>(t);
          f->primitive[i] = static_cast<int32_t>(f->boxes.size() + k);
          f->bary[i] = bary.cast<float>();
        }
      }
    }
  }
}

/// Fixed light: ambient plus a directional term on |n . l| (both sides of sheets are lit).
float Lighting(const Eigen::Vector3d& normal_world) {
  static const Eigen::Vector3d kLight = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  return static_cast<float>(0.55 + 0.45 * std::abs(normal_world.dot(kLight)));
}

void ShadeRows(const Frame& f, int row_begin, int row_end, RenderedImages* out) {
  const int w = f.camera.width();
  const size_t num_boxes = f.boxes.size();
  for (int v = row_begin; v < row_end; ++v) {
    for (int u = 0; u < w; ++u) {
      const size_t i = static_cast<size_t>(v) * w + u;
      const int32_t p = f.primitive[i];
      if (p < 0) continue;
      Eigen::Vector3f bgr;
      uint16_t id;
      if (static_cast<size_t>(p) < num_boxes) {
        const Box& box = f.scene.boxes[p];
        const BoxInCamera& prep = f.boxes[p];
        const Eigen::Vector3d dir = prep.R_box_camera * Eigen::Vector3d(f.xn[u], f.yn[v], 1.0);
        const Eigen::Vector3d p_box = prep.origin + static_cast<double>(f.depth[i]) * dir;
        bgr = TextureColour(box.material, f.face[i], BoxFaceUv(box, f.face[i], p_box)) *
              Lighting(BoxFaceNormalWorld(box, f.face[i]));
        id = box.object_id;
      } else {
        const Triangle& tri = f.scene.triangles[p - num_boxes];
        const Eigen::Vector2f& b = f.bary[i];
        const Eigen::Vector2d uv =
            (1.0 - b.x() - b.y()) * tri.uv[0] + b.x() * tri.uv[1] + b.y() * tri.uv[2];
        const Eigen::Vector3d n =
            (tri.vertex[1] - tri.vertex[0]).cross(tri.vertex[2] - tri.vertex[0]).normalized();
        bgr = TextureColour(tri.material, 0, uv) * Lighting(n);
        id = tri.object_id;
      }
      bgr = bgr.cwiseMin(255.f).cwiseMax(0.f);
      out->colour.at<cv::Vec3b>(v, u) =
          cv::Vec3b(static_cast<uint8_t>(bgr[0] + 0.5f), static_cast<uint8_t>(bgr[1] + 0.5f),
                    static_cast<uint8_t>(bgr[2] + 0.5f));
      out->depth_m.at<float>(v, u) = f.depth[i];
      out->mask.at<uint16_t>(v, u) = id;
    }
  }
}

}  // namespace

RenderedImages RenderScene(const SceneGeometry& scene, const PinholeCamera& camera,
                           const Eigen::Isometry3d& T_world_camera) {
  Frame f{scene, camera, T_world_camera, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  Prepare(&f);
  RenderedImages out;
  out.colour = cv::Mat(camera.height(), camera.width(), CV_8UC3, cv::Scalar::all(0));
  out.depth_m = cv::Mat(camera.height(), camera.width(), CV_32FC1, cv::Scalar(0.0f));
  out.mask = cv::Mat(camera.height(), camera.width(), CV_16UC1, cv::Scalar(0));
  cv::parallel_for_(
      cv::Range(0, camera.height()),
      [&](const cv::Range& rows) {
        CastRows(&f, rows.start, rows.end);
        ShadeRows(f, rows.start, rows.end, &out);
      },
      8);
  return out;
}

PixelHit CastPixelRay(const SceneGeometry& scene, const PinholeCamera& camera,
                      const Eigen::Isometry3d& T_world_camera, double u, double v) {
  const Eigen::Vector3d dir_camera((u - camera.cx()) / camera.fx(), (v - camera.cy()) / camera.fy(),
                                   1.0);
  PixelHit best;
  best.depth_m = std::numeric_limits<double>::infinity();
  for (const Box& box : scene.boxes) {
    const BoxInCamera prep = PrepareBox(box, T_world_camera);
    int face = 0;
    const double t = IntersectBox(box, prep, prep.R_box_camera * dir_camera, kNear, &face);
    if (t > 0.0 && t < best.depth_m) best = {true, t, box.object_id};
  }
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  for (const Triangle& tri : scene.triangles) {
    Eigen::Vector2d bary;
    const double t =
        IntersectTriangle(T_camera_world * tri.vertex[0], T_camera_world * tri.vertex[1],
                          T_camera_world * tri.vertex[2], dir_camera, kNear, &bary);
    if (t > 0.0 && t < best.depth_m) best = {true, t, tri.object_id};
  }
  if (!best.hit) best.depth_m = 0.0;
  return best;
}

}  // namespace synth
}  // namespace dslam

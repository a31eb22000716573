// PCD files of the static map through PCL's reader and writer (pcl::PointXYZRGB).
#include <fstream>
#include <stdexcept>

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "dslam/mapping/coloured_cloud.h"

namespace dslam {

void WritePcd(const std::string& path, const ColouredCloud& cloud) {
  pcl::PointCloud<pcl::PointXYZRGB> out;
  out.reserve(cloud.size());
  for (const ColouredPoint& point : cloud) {
    pcl::PointXYZRGB q(point.r, point.g, point.b);
    q.x = point.p.x();
    q.y = point.p.y();
    q.z = point.p.z();
    out.push_back(q);
  }
  out.width = static_cast<uint32_t>(out.size());
  out.height = 1;
  // An empty cloud is a valid map (nothing fused yet); PCL's writer refuses it, so its header is
  // written here.
  if (out.empty()) {  // PCL's binary writer throws on an empty cloud, a valid (empty) map
    std::ofstream file(path);
    file << pcl::PCDWriter().generateHeader(out, 0) << "DATA ascii\n";
    if (!file.flush()) throw std::runtime_error("cannot write " + path);
    return;
  }
  int status = -1;
  try {  // PCL's writer reports some failures by status, others by pcl::IOException
    status = pcl::io::savePCDFileBinary(path, out);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  if (status != 0) throw std::runtime_error("cannot write " + path);
}

ColouredCloud ReadPcd(const std::string& path) {
  pcl::PCLPointCloud2 blob;
  int status = -1;
  try {
    status = pcl::io::loadPCDFile(path, blob);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read " + path + ": " + e.what());
  }
  if (status != 0) throw std::runtime_error("cannot read " + path);
  // PCL 1.13's fromPCLPointCloud2 takes &cloud[0] of an empty cloud (undefined behaviour,
  // UBSan in scripts/sanitize.sh address): a file without points is read as an empty cloud here.
  if (blob.width * blob.height == 0) return {};
  pcl::PointCloud<pcl::PointXYZRGB> in;
  pcl::fromPCLPointCloud2(blob, in);
  ColouredCloud cloud;
  cloud.reserve(in.size());
  for (const pcl::PointXYZRGB& q : in) {
    cloud.push_back({Eigen::Vector3f(q.x, q.y, q.z), q.r, q.g, q.b});
  }
  return cloud;
}

}  // namespace dslam

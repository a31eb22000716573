#include "dslam/io/loop_io.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dslam/io/trajectory_io.h"

namespace dslam {
namespace {

constexpr char kHeader[] =
    "# stamp_query stamp_match tx ty tz qx qy qz qw (T_match_query, camera optical frames)\n";

}  // namespace

std::vector<LoopRecord> ReadLoopFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open loop file " + path);
  return ParseLoopFile(in, path);
}

std::vector<LoopRecord> ParseLoopFile(std::istream& in, const std::string& name) {
  std::vector<LoopRecord> loops;
  std::string line;
  int line_number = 0;
  while (ReadDataLine(in, &line, &line_number)) {
    const std::string where = name + ":" + std::to_string(line_number) + ": ";
    std::istringstream fields(line);
    LoopRecord loop;
    double f[7];
    if (!(fields >> loop.stamp_query_s >> loop.stamp_match_s >> f[0] >> f[1] >> f[2] >> f[3] >>
          f[4] >> f[5] >> f[6])) {
      throw std::runtime_error(where + "expected 'stamp_query stamp_match tx ty tz qx qy qz qw'");
    }
    loop.T_match_query = PoseFromTumFields(f, where);
    loops.push_back(loop);
  }
  return loops;
}

void WriteLoopFile(const std::string& path, const std::vector<LoopRecord>& loops) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write loop file " + path);
  out << kHeader;
  for (const LoopRecord& loop : loops) {
    const Eigen::Vector3d& p = loop.T_match_query.translation();
    const Eigen::Quaterniond q(loop.T_match_query.rotation());
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), "%.6f %.6f %.6f %.6f %.6f %.7f %.7f %.7f %.7f\n",
                  loop.stamp_query_s, loop.stamp_match_s, p.x(), p.y(), p.z(), q.x(), q.y(), q.z(),
                  q.w());
    out << buffer;
  }
  if (!out) throw std::runtime_error("error while writing loop file " + path);
}

}  // namespace dslam

#pragma once
// Makes the file size and checksum fields of a keyframe map file's header
// (dslam/map_file/keyframe_map_file.h) agree with its bytes, so that a changed or cut body
// reaches the body parser instead of the size or checksum check (fuzz harness and tests).

#include <string>

#include "dslam/core/binary_io.h"

namespace dslam {
namespace fuzz {

/// `bytes` with the size (offset 12) and checksum (offset 20) fields set from its length and
/// its bytes from offset 28; unchanged when shorter than 28 bytes.
inline std::string Resealed(std::string bytes) {
  if (bytes.size() < 28) return bytes;
  std::string fields;
  PutU64(bytes.size(), &fields);
  PutU64(Fnv1a64(bytes.data() + 28, bytes.size() - 28), &fields);
  bytes.replace(12, 16, fields);
  return bytes;
}

}  // namespace fuzz
}  // namespace dslam

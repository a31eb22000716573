// ParseKeyFrameMap / LoadKeyFrameMap refuse every damaged file with a KeyFrameMapError that says
// why: empty, another magic, a newer version, every truncation, a flipped byte, huge counts,
// and bodies with a right checksum (resealed, fuzz/keyframe_map_seal.h) but invalid contents.
#include <gtest/gtest.h>

#include "dslam/core/binary_io.h"
#include "dslam/map_file/keyframe_map_file.h"
#include "fuzz/keyframe_map_seal.h"
#include "map_file/sample_map.h"
#include "support/thrown_message.h"

namespace dslam {
namespace {

using fuzz::Resealed;

// Offsets in a file of SampleMapFile (format in keyframe_map_file.h).
constexpr size_t kPointsCount = 116, kImagesCount = 124, kSettings = 128, kFirstPoint = 180;
constexpr size_t kPointWithDescriptor = 150 + 32;
constexpr size_t kFlags = kFirstPoint + 8 + 24 + 72 + 1 + 32 + 4 + 4 + 8;  // of point 0
constexpr size_t kDescriptorLength = kFirstPoint + 8 + 24 + 72;            // of point 0

std::string Why(const std::string& bytes) {
  return test::ThrownMessage<KeyFrameMapError>([&] { ParseKeyFrameMap(bytes, "kfm.bin"); });
}

// `bytes` with `value` written little-endian over `size` bytes at `offset`.
std::string Patched(std::string bytes, size_t offset, std::uint64_t value, int size) {
  for (int i = 0; i < size; ++i) bytes[offset + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
  return bytes;
}

class KeyFrameMapCorrupt : public testing::Test {
 protected:
  const std::string bytes_ = SerialiseKeyFrameMap(test::SampleMapFile(3, 2, true));
};

TEST_F(KeyFrameMapCorrupt, HeaderProblemsAreNamed) {
  EXPECT_EQ(Why(""), "kfm.bin: empty file, not a dslam keyframe map");
  EXPECT_NE(Why("DSLAMVOC" + bytes_.substr(8)).find("kfm.bin: not a dslam keyframe map"),
            std::string::npos);
  EXPECT_NE(Why("hello").find("not a dslam keyframe map"), std::string::npos);
  EXPECT_EQ(Why(Patched(bytes_, 8, 3, 4)),
            "kfm.bin: unsupported format version 3 (this build reads 1 and 2)");
  EXPECT_EQ(Why(Patched(bytes_, 8, 0, 4)),
            "kfm.bin: unsupported format version 0 (this build reads 1 and 2)");
  EXPECT_EQ(Why(bytes_.substr(0, 170)),
            "kfm.bin: truncated: expected at least 180 bytes (the header), got 170");
  EXPECT_EQ(Why(Patched(bytes_, 8, 1, 4).substr(0, 100)),
            "kfm.bin: truncated: expected at least 128 bytes (the header), got 100");
  EXPECT_EQ(Why(bytes_.substr(0, 1000)),
            "kfm.bin: truncated: expected " + std::to_string(bytes_.size()) + " bytes, got 1000");
  EXPECT_NE(Why(bytes_ + "xy").find("corrupt: " + std::to_string(bytes_.size() + 2) + " bytes"),
            std::string::npos);
  const std::string message = test::ThrownMessage<KeyFrameMapError>(
      [] { LoadKeyFrameMap(testing::TempDir() + "/kfm_missing.bin"); });
  EXPECT_NE(message.find("kfm_missing.bin: cannot open the file"), std::string::npos) << message;
}

TEST_F(KeyFrameMapCorrupt, EveryPrefixIsRefused) {
  ASSERT_NO_THROW(ParseKeyFrameMap(bytes_));
  for (size_t n = 0; n < bytes_.size(); ++n) {
    const std::string prefix = bytes_.substr(0, n);
    EXPECT_NE(Why(prefix), "") << n;
    // With size and checksum made right, the body parser finds the cut.
    if (n >= 28) {
      EXPECT_NE(Why(Resealed(prefix)), "") << n;
    }
  }
}

TEST_F(KeyFrameMapCorrupt, EveryFlippedByteIsRefused) {
  for (size_t i = 0; i < bytes_.size(); ++i) {
    std::string flipped = bytes_;
    flipped[i] ^= 0x10;
    const std::string why = Why(flipped);
    if (i >= 28) {
      EXPECT_EQ(why, "kfm.bin: checksum mismatch: the file is corrupt") << i;
    }
    EXPECT_NE(why, "") << i;
  }
}

TEST_F(KeyFrameMapCorrupt, HugeCountsAreRefusedBeforeAllocating) {
  EXPECT_NE(Why(Resealed(Patched(bytes_, kPointsCount, 0xFFFFFFFFu, 4)))
                .find("truncated body: 4294967295 map points of at least 150 bytes"),
            std::string::npos);
  EXPECT_NE(Why(Resealed(Patched(bytes_, kImagesCount, 0x7FFFFFFFu, 4))).find("image pairs"),
            std::string::npos);
  // One keyframe without points: its point-id count and its measurement count.
  const std::string one = SerialiseKeyFrameMap(test::SampleMapFile(0, 1, false));
  const size_t point_ids = kFirstPoint + 4 + 4 + 8 + 96 + 288 + 1;
  EXPECT_NE(Why(Resealed(Patched(one, point_ids, 0xFFFFFFF0u, 4))).find("point ids"),
            std::string::npos);
  EXPECT_NE(Why(Resealed(Patched(one, one.size() - 4, 0xFFFFFFF0u, 4))).find("measurements"),
            std::string::npos);
}

TEST_F(KeyFrameMapCorrupt, InvalidContentsWithARightChecksumAreNamed) {
  const auto why = [](const std::string& bytes) { return Why(Resealed(bytes)); };
  // Point 1 (id 4) takes point 0's id 1.
  EXPECT_NE(why(Patched(bytes_, kFirstPoint + kPointWithDescriptor, 1, 8))
                .find("invalid content: map point id 1 is negative or not above the one before"),
            std::string::npos);
  EXPECT_NE(why(Patched(bytes_, kFirstPoint + 8, 0x7FF8000000000000ull, 8))
                .find("map point 1 has a non-finite position"),
            std::string::npos);
  EXPECT_NE(why(Patched(bytes_, kFlags, 4, 1)).find("map point 1 has flags 4"), std::string::npos);
  EXPECT_NE(why(Patched(bytes_, kDescriptorLength, 5, 1))
                .find("map point 1 has a descriptor of 5 bytes (0 or 32)"),
            std::string::npos);
  const std::string one = SerialiseKeyFrameMap(test::SampleMapFile(0, 1, false));
  EXPECT_NE(why(Patched(one, kFirstPoint + 4 + 4 + 8 + 96 + 288, 2, 1))
                .find("keyframe 5 has weak_since_previous 2"),
            std::string::npos);
  EXPECT_NE(why(Patched(one, kFirstPoint + 16, 0x7FF0000000000000ull, 8))
                .find("keyframe 5 has a non-finite pose"),
            std::string::npos);
  EXPECT_NE(why(Patched(one, kFirstPoint, 0xFFFFFFFFu, 4)).find("keyframe id -1 is negative"),
            std::string::npos);
  EXPECT_NE(why(bytes_ + "tail").find("4 bytes after the last record"), std::string::npos);
}

TEST_F(KeyFrameMapCorrupt, OutOfRangeNumbersWithARightChecksumAreNamed) {
  const auto why = [](const std::string& bytes) { return Why(Resealed(bytes)); };
  const std::string one = SerialiseKeyFrameMap(test::SampleMapFile(0, 1, false));
  EXPECT_NE(why(Patched(one, kFirstPoint + 4, 0x7FFFFFFFu, 4))
                .find("invalid content: keyframe 5 has frame_index 2147483647, above 1073741823"),
            std::string::npos);
  EXPECT_NE(why(Patched(one, kFirstPoint, 0x7FFFFFFFu, 4))
                .find("invalid content: keyframe id 2147483647 is above 1073741823"),
            std::string::npos);
  // The information's first element -1: not positive definite.
  EXPECT_NE(why(Patched(one, kFirstPoint + 4 + 4 + 8 + 96, 0xBFF0000000000000ull, 8))
                .find("keyframe 5 has an information matrix that is neither zero (unknown) nor "
                      "symmetric positive definite"),
            std::string::npos);
  // Point 0's cov_world(0, 1) 1: not symmetric.
  EXPECT_NE(why(Patched(bytes_, kFirstPoint + 8 + 24 + 8, 0x3FF0000000000000ull, 8))
                .find("map point 1 has a covariance (cov_world) that is not symmetric positive "
                      "definite"),
            std::string::npos);
  EXPECT_NE(why(Patched(bytes_, kFirstPoint + 2 * kPointWithDescriptor, 0x7FFFFFFFFFFFFFFFull, 8))
                .find("map point id 9223372036854775807 is above 4611686018427387903"),
            std::string::npos);
  EXPECT_NE(why(Patched(bytes_, kSettings, 0, 4)).find("settings: features.num_levels 0, not >= 1"),
            std::string::npos);
  EXPECT_NE(why(Patched(bytes_, kSettings + 4, 0x3FF0000000000000ull, 8))
                .find("settings: features.scale_factor 1, not finite and > 1"),
            std::string::npos);
}

TEST(KeyFrameMapImages, BadImagesAreNamed) {
  const std::string good = SerialiseKeyFrameMap(test::SampleMapFile(0, 1, true));
  const size_t colour = good.find("\x89PNG");             // keyframe 5's colour PNG
  const size_t depth = good.find("\x89PNG", colour + 1);  // and its depth PNG
  ASSERT_NE(depth, std::string::npos);
  const auto why = [](const std::string& bytes) { return Why(Resealed(bytes)); };
  EXPECT_NE(why(Patched(good, colour - 8, 6, 4)).find("images of keyframe 6, not in the map"),
            std::string::npos);
  const std::string colour_problem = "keyframe 5's colour image is not an 8-bit PNG";
  EXPECT_NE(why(Patched(good, colour, 'X', 1)).find(colour_problem), std::string::npos);
  EXPECT_NE(why(Patched(good, colour + 40, good[colour + 40] ^ 0x55, 1)).find(colour_problem),
            std::string::npos);
  // Width 17 in the IHDR (big-endian at offset 16): refused before decoding.
  EXPECT_NE(why(Patched(good, colour + 19, 17, 1)).find(colour_problem), std::string::npos);
  EXPECT_NE(why(Patched(good, depth, 'X', 1)).find("keyframe 5's depth image is not a 16-bit PNG"),
            std::string::npos);
  // Depth PNG as colour and colour PNG as depth.
  std::string swapped = good.substr(0, colour - 4);
  const std::string colour_png = good.substr(colour, depth - 4 - colour);
  const std::string depth_png = good.substr(depth);
  PutU32(static_cast<std::uint32_t>(depth_png.size()), &swapped);
  swapped += depth_png;
  PutU32(static_cast<std::uint32_t>(colour_png.size()), &swapped);
  swapped += colour_png;
  EXPECT_NE(why(swapped).find(colour_problem), std::string::npos);
}

}  // namespace
}  // namespace dslam

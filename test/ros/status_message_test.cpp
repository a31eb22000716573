// FillBackEndStatus sets each back-end field of FrameStatus from the BackEndStatus::Fields()
// entry of the same name, and FillLoopStatus each loop field from the LoopStatus member of its
// name: the message is serialized as on the wire and read back field by field with the layout of
// msg/FrameStatus.msg, so the check goes through the names of the .msg file and of the table,
// never through the generated struct's members.
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <ros/serialization.h>

#include "dslam/ros/frame_publisher.h"
#include "support/message_fields.h"

namespace dslam {
namespace ros_layer {
namespace {

template <typename T>
T Read(const std::vector<uint8_t>& bytes, size_t* at) {
  if (*at + sizeof(T) > bytes.size()) throw std::runtime_error("message too short");
  T value;
  std::memcpy(&value, &bytes[*at], sizeof(T));  // ROS serializes little-endian, as x86 / ARM
  *at += sizeof(T);
  return value;
}

// The numeric fields of a serialized FrameStatus by name, read with the .msg file's layout.
std::map<std::string, double> Decode(const dslam::FrameStatus& message) {
  std::vector<uint8_t> bytes(ros::serialization::serializationLength(message));
  ros::serialization::OStream out(bytes.data(), static_cast<uint32_t>(bytes.size()));
  ros::serialization::serialize(out, message);
  std::map<std::string, double> values;
  size_t at = 0;
  for (const auto& [type, name] : test::MessageFields("msg/FrameStatus.msg")) {
    if (type == "Header") {
      at += 3 * sizeof(uint32_t);  // seq, stamp
      const uint32_t frame_id_length = Read<uint32_t>(bytes, &at);
      at += frame_id_length;
    } else if (type == "string") {
      const uint32_t length = Read<uint32_t>(bytes, &at);
      at += length;
    } else if (type == "bool") {
      values[name] = Read<uint8_t>(bytes, &at);
    } else if (type == "int32") {
      values[name] = Read<int32_t>(bytes, &at);
    } else if (type == "uint64") {
      values[name] = static_cast<double>(Read<uint64_t>(bytes, &at));
    } else if (type == "float64") {
      values[name] = Read<double>(bytes, &at);
    } else {
      throw std::runtime_error("type " + type + " of " + name + " not read by this test");
    }
  }
  EXPECT_EQ(at, bytes.size()) << "the .msg file and the generated message differ";
  return values;
}

// Names of the table's message fields.
std::vector<std::string> MessageFieldNames() {
  std::vector<std::string> names;
  const BackEndStatus status;
  BackEndStatus::Fields(status, [&](const StatusFieldInfo& info, const auto&) {
    if (info.outputs & kStatusMessage) names.push_back(info.name);
  });
  return names;
}

// One table field at a time is set (true, 7 or 7.5): exactly the message field of its name, and
// no other back-end field, takes that value.
TEST(StatusMessage, EachBackEndFieldComesFromTheTableFieldOfItsName) {
  const std::vector<std::string> names = MessageFieldNames();
  ASSERT_FALSE(names.empty());
  for (const std::string& set : names) {
    BackEndStatus backend;
    double expected = 0.0;
    BackEndStatus::Fields(backend, [&](const StatusFieldInfo& info, auto& value) {
      if (set != info.name) return;
      value = static_cast<std::decay_t<decltype(value)>>(7.5);
      expected = static_cast<double>(value);
    });
    dslam::FrameStatus message;
    FillBackEndStatus(backend, &message);
    const std::map<std::string, double> values = Decode(message);
    for (const std::string& name : names) {
      ASSERT_EQ(values.count(name), 1u) << name << " is not a field of FrameStatus.msg";
      EXPECT_EQ(values.at(name), name == set ? expected : 0.0) << name << " with " << set << " set";
    }
  }
}

// Each loop closing field goes to the message field of its name.
TEST(StatusMessage, LoopFieldsComeFromLoopStatus) {
  LoopStatus loops;
  loops.loop_closures = 3;
  loops.loop_keyframes = 41;
  loops.loop_ms = 7.5;
  dslam::FrameStatus message;
  FillLoopStatus(loops, &message);
  const std::map<std::string, double> values = Decode(message);
  EXPECT_EQ(values.at("loop_closures"), 3.0);
  EXPECT_EQ(values.at("loop_keyframes"), 41.0);
  EXPECT_EQ(values.at("loop_ms"), 7.5);
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam

#pragma once
// Checks on the synchronized inputs before they reach the odometry (ROS-free, unit-tested): the
// image stamps (zero, repeated, backwards, gaps) and the watchdog that says which input is missing
// when no synchronized set is formed.

#include <array>
#include <cstdint>
#include <string>

namespace dslam {
namespace ros_layer {

/// What to do with one input set, judged by its stamp against the last accepted one.
struct StampVerdict {
  bool accept = true;      ///< false: skip the set (counted as rejected)
  std::string problem;     ///< why it was skipped, or what is unusual about it; empty when normal
  bool backwards = false;  ///< older than the last accepted set: the odometry starts a new world
};

/// Judges image stamps in arrival order. A zero stamp (a driver that sets none) and a stamp
/// equal to the last accepted one (a duplicated message) are skipped; an older stamp (a bag
/// played in a loop) and a gap longer than `gap_warning_s` [s] are accepted with a note.
class StampCheck {
 public:
  explicit StampCheck(double gap_warning_s) : gap_warning_s_(gap_warning_s) {}

  /// Judges `stamp_s` [s] and, when accepted, remembers it.
  StampVerdict Check(double stamp_s);

 private:
  double gap_warning_s_;
  bool have_last_ = false;
  double last_s_ = 0.0;
};

/// Counts arrivals on each input topic and synchronized sets, and says what is wrong when
/// inputs arrive but no set is formed (a missing topic, or stamps that never match).
class InputWatchdog {
 public:
  enum Input { kColour = 0, kDepth = 1, kInfo = 2 };

  /// `names`: the three resolved topic names, for the messages.
  explicit InputWatchdog(std::array<std::string, 3> names) : names_(std::move(names)) {}

  /// One message arrived on `input` with stamp `stamp_s` [s].
  void Arrived(Input input, double stamp_s);
  /// A synchronized set was formed.
  void Synchronized() { ++sets_; }

  /// Called every period: empty when a set was formed since the last call or nothing arrived at
  /// all; otherwise a warning naming the inputs that did not arrive, or, when all did, their last
  /// stamps (which never matched). Resets the counts of the period.
  std::string Check();

 private:
  std::array<std::string, 3> names_;
  std::array<uint64_t, 3> arrived_{};
  std::array<double, 3> last_stamp_s_{};
  uint64_t sets_ = 0;
};

}  // namespace ros_layer
}  // namespace dslam

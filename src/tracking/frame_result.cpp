#include "dslam/tracking/frame_result.h"

namespace dslam {

const char* ToString(TrackingState state) {
  switch (state) {
    case TrackingState::kInitialised:
      return "initialised";
    case TrackingState::kTracking:
      return "tracking";
    case TrackingState::kRecovered:
      return "recovered";
    case TrackingState::kLost:
      return "lost";
    case TrackingState::kLocalising:
      return "localising";
  }
  return "unknown";
}

}  // namespace dslam

#pragma once
// Tests' access to Slam's back-end holds (private in dslam/backend/slam.h: no caller outside the
// tests needs them).

#include "dslam/backend/slam.h"

namespace dslam {

/// Slam::HoldBackEnd and Slam::HoldBackEndResults for tests (slam.h documents both).
class SlamTestAccess {
 public:
  static void HoldBackEnd(Slam* slam, bool hold) { slam->HoldBackEnd(hold); }
  static void HoldBackEndResults(Slam* slam, bool hold) { slam->HoldBackEndResults(hold); }
};

}  // namespace dslam

#pragma once
// The message of the exception a call throws, for tests that check what an error names.

#include <string>

namespace dslam {
namespace test {

/// The what() of the `Exception` that `f()` throws, or "" when it throws none (an exception of
/// another type propagates).
template <typename Exception, typename F>
std::string ThrownMessage(F&& f) {
  try {
    f();
  } catch (const Exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace test
}  // namespace dslam

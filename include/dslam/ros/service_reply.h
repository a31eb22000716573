#pragma once
// The answer of a service that writes a file: `success` and `message` of its response filled the
// same way by every such service of the node.

#include <exception>
#include <string>

namespace dslam {
namespace ros_layer {

/// Runs `write`, which fills `res`'s own fields and returns the success message ("wrote ...");
/// on an exception `success` is false and `message` its text. Returns true: the call itself
/// succeeded, the response says whether the file was written.
template <typename Response, typename Write>
bool AnswerWrite(Response& res, Write&& write) {
  try {
    res.message = write();
    res.success = true;
  } catch (const std::exception& e) {
    res.success = false;
    res.message = e.what();
  }
  return true;
}

}  // namespace ros_layer
}  // namespace dslam

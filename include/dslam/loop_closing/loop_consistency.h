#pragma once
// The consistency test of loop detection (ORB-SLAM2's LoopClosing::DetectLoop, simplified): a
// place is trusted only when the candidates of several consecutive query keyframes agree. Each
// candidate comes with its group (the candidate and the keyframes around it); a group continues
// a chain when it shares a keyframe with a group of the previous query keyframe.

#include <cstddef>
#include <vector>

namespace dslam {

/// A loop candidate of one query keyframe and the keyframes around it.
struct CandidateGroup {
  int candidate = -1;          ///< keyframe id of the candidate
  std::vector<int> keyframes;  ///< keyframe ids of the group, ascending, the candidate included
};

/// Chains of overlapping candidate groups over consecutive query keyframes.
class ConsistentGroups {
 public:
  /// Takes the candidate groups of the next query keyframe. A group's chain length is 1 plus the
  /// longest chain among the previous query keyframe's groups it shares a keyframe id with (1
  /// when it shares none); these groups and lengths replace the previous ones (no groups: the
  /// chains end). Returns the candidates whose chain length reached `required`, in the order of
  /// `groups`.
  std::vector<int> Update(const std::vector<CandidateGroup>& groups, int required);

  void Clear() { chains_.clear(); }                    ///< ends every chain
  std::size_t size() const { return chains_.size(); }  ///< groups kept from the last Update

 private:
  struct Chain {
    std::vector<int> keyframes;  // ascending
    int length = 0;              // consecutive query keyframes
  };
  std::vector<Chain> chains_;
};

}  // namespace dslam

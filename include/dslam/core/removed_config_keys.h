#pragma once
// Parameters that dslam no longer has. A YAML file or rosparam namespace written for an older
// version may still set them: the loaders (config_io.h, param_loader.h) ignore such a key with a
// warning that names it and says why it went, instead of failing as on an unknown key.

#include <cstddef>
#include <string>
#include <string_view>

namespace dslam {

/// One removed parameter: `section`.`name`, and what happened to it (the BENCHMARKS.md section
/// that measured the losing option, the key it was merged into, or the constant that replaced it).
struct RemovedConfigKey {
  std::string_view section;  ///< config section, e.g. "tracking"
  std::string_view name;     ///< key inside the section, e.g. "descriptor_observations"
  std::string_view reason;   ///< one line, e.g. "merged into depth_noise.max_depth_m"
};

/// The constant table of removed parameters (a view: begin, end, size).
class RemovedConfigKeyList {
 public:
  constexpr RemovedConfigKeyList(const RemovedConfigKey* first, std::size_t size)
      : first_(first), size_(size) {}
  constexpr const RemovedConfigKey* begin() const { return first_; }
  constexpr const RemovedConfigKey* end() const { return first_ + size_; }
  constexpr std::size_t size() const { return size_; }

 private:
  const RemovedConfigKey* first_;
  std::size_t size_;
};

/// Every removed parameter, by section.
RemovedConfigKeyList RemovedConfigKeys();

/// The removed parameter `section`.`name`, or nullptr when there never was one (or it exists).
const RemovedConfigKey* FindRemovedConfigKey(std::string_view section, std::string_view name);

/// The warning for a setting of `key`, whose name in the user's input is `shown` (e.g.
/// "tracking.descriptor_observations" or "/dslam/tracking/descriptor_observations"):
/// "<shown> was removed (<reason>); its value is ignored".
std::string RemovedConfigKeyWarning(const std::string& shown, const RemovedConfigKey& key);

}  // namespace dslam

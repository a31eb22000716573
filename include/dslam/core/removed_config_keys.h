#pragma once
// Parameters that dslam no longer has. A YAML file or rosparam namespace written for an older
// version may still set them: the loaders (config_io.h, param_loader.h) ignore such a key with a
// warning that names it and says why it went, instead of failing as on an unknown key.

#include <string>
#include <vector>

namespace dslam {

/// One removed parameter: `section`.`name`, and what happened to it (the BENCHMARKS.md section
/// that measured the losing option, the key it was merged into, or the constant that replaced it).
struct RemovedConfigKey {
  std::string section;  ///< config section, e.g. "tracking"
  std::string name;     ///< key inside the section, e.g. "descriptor_observations"
  std::string reason;   ///< one line, e.g. "merged into depth_noise.max_depth_m"
};

/// Every removed parameter, by section.
const std::vector<RemovedConfigKey>& RemovedConfigKeys();

/// The removed parameter `section`.`name`, or nullptr when there never was one (or it exists).
const RemovedConfigKey* FindRemovedConfigKey(const std::string& section, const std::string& name);

/// The warning for a setting of `key`, whose name in the user's input is `shown` (e.g.
/// "tracking.descriptor_observations" or "/dslam/tracking/descriptor_observations"):
/// "<shown> was removed (<reason>); its value is ignored".
std::string RemovedConfigKeyWarning(const std::string& shown, const RemovedConfigKey& key);

}  // namespace dslam

// Fuzz harness: config YAML text (dslam/io/config_io.h, LoadConfigYamlString).
#include <yaml-cpp/exceptions.h>

#include "dslam/io/config_io.h"
#include "fuzz_input.h"
#include "harnesses.h"

namespace dslam {
namespace fuzz {

void ConfigYamlHarness(const std::string& data) {
  ParsedOrRejected<ConfigError>("", [&] {
    Config config;
    std::vector<std::string> warnings;  // removed keys: collected, not printed
    try {
      LoadConfigYamlString(data, &config, &warnings);
    } catch (const YAML::Exception& e) {
      throw ContractViolation(std::string("yaml-cpp exception escaped: ") + e.what());
    }
    try {
      config.Validate();  // what the loader accepted must be valid
    } catch (const ConfigError& e) {
      throw ContractViolation(std::string("loaded config does not validate: ") + e.what());
    }
  });
}

}  // namespace fuzz
}  // namespace dslam

DSLAM_FUZZ_TARGET(dslam::fuzz::ConfigYamlHarness)

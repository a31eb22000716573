// dslam_config_doc: prints the Markdown table of every parameter (defaults, units, ranges), the
// default YAML file (--yaml), or validates a YAML file (--check config.yaml).
#include <iostream>
#include <string>

#include "dslam/io/config_io.h"

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--check") {
    dslam::Config config;
    try {
      dslam::LoadConfigYaml(argv[2], &config);
    } catch (const dslam::ConfigError& e) {
      std::cerr << "invalid: " << e.what() << "\n";
      return 1;
    }
    std::cout << argv[2] << ": ok\n";
    return 0;
  }
  if (argc == 2 && std::string(argv[1]) == "--yaml") {
    std::cout << dslam::DescribeConfigYaml();
    return 0;
  }
  if (argc != 1) {
    std::cerr << "usage: dslam_config_doc [--yaml | --check config.yaml]\n";
    return 2;
  }
  std::cout << dslam::DescribeConfigMarkdown();
  return 0;
}

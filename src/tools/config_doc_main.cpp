// dslam_config_doc: prints the Markdown table of every parameter (defaults, units, ranges), the
// default YAML file (--yaml), or validates a YAML file (--check config.yaml); --status-columns and
// --summary-keys print the tables of dslam_run_dataset's back-end status CSV columns and summary
// keys (eval/status_table.h).
#include <iostream>
#include <string>

#include "dslam/eval/status_table.h"
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
  if (argc == 2 && std::string(argv[1]) == "--status-columns") {
    std::cout << dslam::BackEndCsvMarkdown();
    return 0;
  }
  if (argc == 2 && std::string(argv[1]) == "--summary-keys") {
    std::cout << dslam::BackEndSummaryMarkdown();
    return 0;
  }
  if (argc != 1) {
    std::cerr << "usage: dslam_config_doc [--yaml | --check config.yaml | --status-columns | "
                 "--summary-keys]\n";
    return 2;
  }
  std::cout << dslam::DescribeConfigMarkdown();
  return 0;
}

#pragma once
// Loading the Config tree from YAML (files shipped in config/, or a user's), and describing it.

#include <string>
#include <vector>

#include "dslam/core/config.h"

namespace dslam {

/// Overrides fields of `config` with the values in a YAML file whose top-level keys are section
/// names ("dataset: {association_max_dt_s: 0.02}"). Unknown sections or keys and values of the
/// wrong type throw ConfigError naming the parameter; the result is validated. A key dslam no
/// longer has (removed_config_keys.h) is ignored with a warning that names it and says it was
/// removed: appended to `warnings`, or printed to stderr when `warnings` is null.
void LoadConfigYaml(const std::string& path, Config* config,
                    std::vector<std::string>* warnings = nullptr);

/// Same as LoadConfigYaml, from YAML text.
void LoadConfigYamlString(const std::string& yaml_text, Config* config,
                          std::vector<std::string>* warnings = nullptr);

/// YAML text with every section and key at the values of `config`, each with its unit and
/// description as a comment (config/default.yaml is this for the defaults).
std::string DescribeConfigYaml(const Config& config = Config());

/// A Markdown table of every parameter: name, default, unit, bounds, description.
std::string DescribeConfigMarkdown(const Config& defaults = Config());

}  // namespace dslam

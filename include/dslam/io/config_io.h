#pragma once
// Loading the Config tree from YAML (files shipped in config/, or a user's), and describing it.

#include <string>

#include "dslam/core/config.h"

namespace dslam {

/// Overrides fields of `config` with the values in a YAML file whose top-level keys are section
/// names ("dataset: {association_max_dt_s: 0.02}"). Unknown sections or keys and values of the
/// wrong type throw ConfigError naming the parameter; the result is validated.
void LoadConfigYaml(const std::string& path, Config* config);

/// Same as LoadConfigYaml, from YAML text.
void LoadConfigYamlString(const std::string& yaml_text, Config* config);

/// YAML text with every section and key at the values of `config`, each with its unit and
/// description as a comment (config/default.yaml is this for the defaults).
std::string DescribeConfigYaml(const Config& config = Config());

/// A Markdown table of every parameter: name, default, unit, bounds, description.
std::string DescribeConfigMarkdown(const Config& defaults = Config());

}  // namespace dslam

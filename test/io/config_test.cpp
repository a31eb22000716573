#include <dirent.h>

#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/core/removed_config_keys.h"
#include "dslam/io/config_io.h"
#include "support/generated_block.h"

namespace dslam {
namespace {

TEST(Config, DefaultsAreValid) { EXPECT_NO_THROW(Config().Validate()); }

TEST(Config, ValidateNamesTheParameter) {
  Config config;
  config.dataset.association_max_dt_s = -1.0;
  try {
    config.Validate();
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("dataset.association_max_dt_s"), std::string::npos)
        << e.what();
  }
}

TEST(Config, ValidateNamesBothParametersOfABrokenPair) {
  Config config;
  config.tracking.reanchor_weak_inliers = 100;
  config.tracking.reanchor_strong_inliers = 80;
  try {
    config.Validate();
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("tracking.reanchor_strong_inliers"), std::string::npos) << what;
    EXPECT_NE(what.find("tracking.reanchor_weak_inliers"), std::string::npos) << what;
  }
}

TEST(Config, YamlOverridesDefaults) {
  Config config;
  LoadConfigYamlString("dataset: {association_max_dt_s: 0.05}", &config);
  EXPECT_DOUBLE_EQ(config.dataset.association_max_dt_s, 0.05);
}

TEST(Config, YamlRejectsUnknownKeysAndBadTypes) {
  Config config;
  EXPECT_THROW(LoadConfigYamlString("dataset: {association_max_dt: 0.05}", &config), ConfigError);
  EXPECT_THROW(LoadConfigYamlString("datasett: {}", &config), ConfigError);
  EXPECT_THROW(LoadConfigYamlString("dataset: {association_max_dt_s: fast}", &config), ConfigError);
  EXPECT_THROW(LoadConfigYamlString("dataset: {association_max_dt_s: 5.0}", &config), ConfigError);
}

// A removed parameter is ignored with a warning naming it; loading goes on.
TEST(Config, YamlWarnsAboutRemovedKeys) {
  Config config;
  std::vector<std::string> warnings;
  LoadConfigYamlString(
      "tracking: {descriptor_observations: 8, window_keyframes: 7}\nmap: {max_depth_m: 4.0}\n",
      &config, &warnings);
  EXPECT_EQ(config.tracking.window_keyframes, 7);
  EXPECT_DOUBLE_EQ(config.depth_noise.max_depth_m, 6.0);  // the merged key's value is ignored
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].rfind("tracking.descriptor_observations was removed (tried, off: ", 0), 0u)
      << warnings[0];
  EXPECT_EQ(warnings[1],
            "map.max_depth_m was removed (merged into depth_noise.max_depth_m); its value is "
            "ignored");
  // Unknown keys stay errors, in the sections of removed keys too.
  EXPECT_THROW(LoadConfigYamlString("tracking: {descriptor_observation: 8}", &config, &warnings),
               ConfigError);
  EXPECT_EQ(warnings.size(), 2u);
}

// Every removed key names a section that exists and a key that it no longer has.
TEST(Config, RemovedKeysAreNotParameters) {
  std::set<std::string> sections, parameters;
  Config config;
  Config::Sections(config, [&](const char* section, auto& s) {
    sections.insert(section);
    using Section = std::decay_t<decltype(s)>;
    Section::Fields(s, [&](const FieldInfo& info, auto&) {
      parameters.insert(std::string(section) + "." + info.name);
    });
  });
  EXPECT_GE(RemovedConfigKeys().size(), 40u);
  for (const RemovedConfigKey& key : RemovedConfigKeys()) {
    const std::string name = std::string(key.section) + "." + std::string(key.name);
    EXPECT_TRUE(sections.count(std::string(key.section))) << name;
    EXPECT_FALSE(parameters.count(name)) << name;
    EXPECT_EQ(FindRemovedConfigKey(key.section, key.name), &key);
  }
  EXPECT_EQ(FindRemovedConfigKey("tracking", "window_keyframes"), nullptr);
  const RemovedConfigKey* descriptors =
      FindRemovedConfigKey("tracking", "descriptor_observations");
  ASSERT_NE(descriptors, nullptr);
  EXPECT_EQ(descriptors->reason,
            "tried, off: docs/benchmarks/tracking.md, \"Map point descriptors refined from their "
            "observations\"");
}

TEST(Config, YamlRejectsKeysThatAreNotNames) {
  // A map or sequence as a key made yaml-cpp's "bad conversion" escape (found by fuzzing).
  const auto error = [](const std::string& yaml) {
    Config config;
    try {
      LoadConfigYamlString(yaml, &config);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("pose:\n  ? {huber_delta_pixel: 2.4}\n  : 1\n"),
            "pose: keys must be plain names, got a map as a key");
  // A NUL in a key ended the message at what() (an empty message).
  EXPECT_EQ(error("\"\\0pose\": {}\n"), "\\x00pose: unknown config section");  // YAML "\0": NUL
  EXPECT_EQ(error("? [dataset]\n: {}\n"),
            "config: keys must be plain names, got a sequence as a key");
}

TEST(Config, MarkdownListsEveryParameter) {
  const std::string table = DescribeConfigMarkdown();
  EXPECT_NE(table.find("`dataset.association_max_dt_s`"), std::string::npos);
}

// Every YAML file shipped in config/ loads and validates.
TEST(Config, ShippedYamlFilesLoad) {
  const std::string dir = std::string(DSLAM_SOURCE_DIR) + "/config";
  DIR* handle = opendir(dir.c_str());
  ASSERT_NE(handle, nullptr) << dir;
  std::vector<std::string> files;
  while (const dirent* entry = readdir(handle)) {
    const std::string name = entry->d_name;
    if (name.size() > 5 && name.substr(name.size() - 5) == ".yaml") files.push_back(name);
  }
  closedir(handle);
  ASSERT_FALSE(files.empty());
  for (const std::string& name : files) {
    Config config;
    std::vector<std::string> warnings;
    EXPECT_NO_THROW(LoadConfigYaml(dir + "/" + name, &config, &warnings)) << name;
    EXPECT_TRUE(warnings.empty()) << name << ": " << (warnings.empty() ? "" : warnings[0]);
  }
}

}  // namespace
}  // namespace dslam

namespace dslam {
namespace {

// config/default.yaml is the generated default file (every key, with its default).
TEST(Config, DefaultYamlIsGeneratedFromCode) {
  std::ifstream in(std::string(DSLAM_SOURCE_DIR) + "/config/default.yaml");
  ASSERT_TRUE(in.good());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, DescribeConfigYaml()) << "run scripts/update_readme.sh";
  Config loaded;
  LoadConfigYamlString(text, &loaded);
  EXPECT_EQ(DescribeConfigYaml(loaded), text);
}

// The parameter table of docs/parameters.md is generated from the code
// (scripts/update_readme.sh); it must match what the code says now.
TEST(Config, ParameterPageTableMatchesCode) {
  EXPECT_EQ(test::GeneratedBlock("docs/parameters.md",
                                 "<!-- BEGIN PARAMETERS (generated by dslam_config_doc) -->",
                                 "<!-- END PARAMETERS -->"),
            DescribeConfigMarkdown())
      << "run scripts/update_readme.sh";
}

}  // namespace
}  // namespace dslam

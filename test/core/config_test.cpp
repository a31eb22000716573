#include <dirent.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/core/config_io.h"

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

TEST(Config, YamlOverridesDefaults) {
  Config config;
  LoadConfigYamlString("dataset: {association_max_dt_s: 0.05}", &config);
  EXPECT_DOUBLE_EQ(config.dataset.association_max_dt_s, 0.05);
}

TEST(Config, YamlRejectsUnknownKeysAndBadTypes) {
  Config config;
  EXPECT_THROW(LoadConfigYamlString("dataset: {association_max_dt: 0.05}", &config), ConfigError);
  EXPECT_THROW(LoadConfigYamlString("datasett: {}", &config), ConfigError);
  EXPECT_THROW(LoadConfigYamlString("dataset: {association_max_dt_s: fast}", &config),
               ConfigError);
  EXPECT_THROW(LoadConfigYamlString("dataset: {association_max_dt_s: 5.0}", &config), ConfigError);
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
    EXPECT_NO_THROW(LoadConfigYaml(dir + "/" + name, &config)) << name;
  }
}

}  // namespace
}  // namespace dslam

// The test binaries' shared scene file (test/support/scene_cache.h, rendered_sequence.h): frames
// read from it are bit for bit the frames rendered in-process, and a request for more frames than
// the file holds renders them and replaces the file.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "support/rendered_sequence.h"

namespace dslam {
namespace {

bool Identical(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() &&
         (a.empty() || cv::countNonZero(a.reshape(1) != b.reshape(1)) == 0);
}

void ExpectSameSequence(const test::RenderedSequence& a, const test::RenderedSequence& b) {
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (size_t i = 0; i < a.frames.size(); ++i) {
    EXPECT_TRUE(Identical(a.frames[i].colour, b.frames[i].colour)) << "frame " << i;
    EXPECT_TRUE(Identical(a.frames[i].depth_m, b.frames[i].depth_m)) << "frame " << i;
    EXPECT_TRUE(Identical(a.masks[i], b.masks[i])) << "frame " << i;
    EXPECT_EQ(a.frames[i].stamp_s, b.frames[i].stamp_s);
    EXPECT_EQ(a.frames[i].camera->fx(), b.frames[i].camera->fx());
    EXPECT_EQ(a.frames[i].camera->width(), b.frames[i].camera->width());
    EXPECT_TRUE(a.groundtruth[i].T_world_camera.isApprox(b.groundtruth[i].T_world_camera, 0.0));
  }
}

TEST(SceneCache, CachedFramesAreTheRenderedOnes) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("dslam_scene_cache_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const char* before = std::getenv("DSLAM_TEST_SCENES");
  const std::string saved = before ? before : "";
  unsetenv("DSLAM_TEST_SCENES");
  const test::RenderedSequence rendered = test::RenderSequence("walking", 4);
  setenv("DSLAM_TEST_SCENES", folder.c_str(), 1);
  const test::RenderedSequence first = test::RenderSequence("walking", 3);  // renders, writes 3
  EXPECT_EQ(test::ReadSceneCache((folder / "walking_s1.bin").string()).size(), 3u);
  const test::RenderedSequence more = test::RenderSequence("walking", 4);  // renders 4, replaces
  EXPECT_EQ(test::ReadSceneCache((folder / "walking_s1.bin").string()).size(), 4u);
  const test::RenderedSequence read = test::RenderSequence("walking", 4);  // read back
  if (saved.empty())
    unsetenv("DSLAM_TEST_SCENES");
  else
    setenv("DSLAM_TEST_SCENES", saved.c_str(), 1);
  std::filesystem::remove_all(folder);
  ExpectSameSequence(rendered, more);
  ExpectSameSequence(rendered, read);
  ASSERT_EQ(first.frames.size(), 3u);
  EXPECT_TRUE(Identical(first.frames[2].colour, rendered.frames[2].colour));
}

}  // namespace
}  // namespace dslam

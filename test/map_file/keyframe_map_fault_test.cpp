// The fault harness of the keyframe map file's save: a child process saving a keyframe map over a
// complete one is killed (SIGKILL) at a random moment of the save, 50 times; after each kill the
// file at the path is the complete old file or the complete new one, byte for byte, and loads;
// the next save removes the temporary files the killed saves left. Own binary: the children are
// forked from a process without other threads.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/core/binary_io.h"
#include "dslam/map_file/keyframe_map_file.h"
#include "map_file/sample_map.h"

namespace dslam {
namespace {

constexpr int kKills = 50;
// A map whose save takes a few ms: each keyframe measures most of the points.
constexpr int kPoints = 1500, kKeyFrames = 24;

// Forks a child that saves `file` to `path` and leaves with _exit (0: saved, 1: failed); returns
// its pid once the child is about to save.
pid_t StartSaving(const std::string& path, const KeyFrameMapFile& file) {
  int ready[2];
  if (::pipe(ready) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(ready[0]);
    const char byte = 1;
    const bool told = ::write(ready[1], &byte, 1) == 1;
    int code = told ? 0 : 2;
    try {
      SaveKeyFrameMap(path, file);
    } catch (...) {
      code = 1;
    }
    ::_exit(code);
  }
  ::close(ready[1]);
  char byte = 0;
  if (pid > 0 && ::read(ready[0], &byte, 1) != 1) ADD_FAILURE() << "the child did not start";
  ::close(ready[0]);
  return pid;
}

// [s] the longest of three saves of `file` to `path` by a child of StartSaving, from the moment
// it is about to save to its exit (what the kills are spread over).
double ChildSaveSeconds(const std::string& path, const KeyFrameMapFile& file) {
  double longest = 0.0;
  for (int i = 0; i < 3; ++i) {
    const pid_t pid = StartSaving(path, file);
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    ::waitpid(pid, &status, 0);
    longest = std::max(
        longest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  std::filesystem::remove(path);
  return longest;
}

// The files in `dir` whose names start with `prefix`.
int CountTemporaries(const std::filesystem::path& dir, const std::string& prefix = "map.bin.tmp-") {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    count += entry.path().filename().string().rfind(prefix, 0) == 0 ? 1 : 0;
  }
  return count;
}

TEST(KeyFrameMapFault, KilledSavesLeaveTheOldOrTheNewCompleteFile) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "kfm_fault";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "map.bin").string();
  const KeyFrameMapFile files[2] = {test::SampleMapFile(kPoints, kKeyFrames, true),
                                    test::SampleMapFile(kPoints + 1, kKeyFrames, true)};
  const std::string bytes[2] = {SerialiseKeyFrameMap(files[0]), SerialiseKeyFrameMap(files[1])};
  const double save_s = ChildSaveSeconds((dir / "timing.bin").string(), files[0]);
  std::mt19937 rng(45);
  std::uniform_real_distribution<double> delay_s(0.0, 1.25 * save_s);  // some after the end
  SaveKeyFrameMap(path, files[0]);
  int current = 0, kept_old = 0, wrote_new = 0, killed_during = 0, left = 0;
  for (int i = 0; i < kKills; ++i) {
    const int next = 1 - current;
    const pid_t pid = StartSaving(path, files[next]);
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay_s(rng)));
    ::kill(pid, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    killed_during += WIFSIGNALED(status) ? 1 : 0;
    if (WIFEXITED(status)) {
      EXPECT_EQ(WEXITSTATUS(status), 0) << i;
    }
    left += CountTemporaries(dir, "map.bin.tmp-" + std::to_string(pid) + "-");
    const std::string now = ReadWholeFile(path, "test");
    ASSERT_TRUE(now == bytes[current] || now == bytes[next])
        << "kill " << i << ": " << now.size() << " bytes";
    EXPECT_NO_THROW(LoadKeyFrameMap(path)) << i;
    if (now == bytes[next]) {
      ++wrote_new;
      current = next;
    } else {
      ++kept_old;
    }
  }
  std::printf(
      "save %.1f ms (%zu bytes); %d kills: %d during the save, %d after it; the file: %d times "
      "the old one, %d times the new one; %d temporary files left by killed saves\n",
      1e3 * save_s, bytes[0].size(), kKills, killed_during, kKills - killed_during, kept_old,
      wrote_new, left);
  EXPECT_GT(kept_old, 0);  // kills did fall inside saves (how many new files: timing-dependent)
  EXPECT_GT(killed_during, kKills / 3);
  EXPECT_GT(left, 0);
  SaveKeyFrameMap(path, files[0]);  // the next save removes what killed ones left
  EXPECT_EQ(CountTemporaries(dir), 0);
}

// The pid of a process that has ended (a child that exited and was waited for).
pid_t EndedPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

TEST(KeyFrameMapFault, ASaveRemovesOnlyTheTemporariesOfEndedProcesses) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "kfm_leftovers";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string ended = std::to_string(EndedPid());
  const std::string alive = std::to_string(::getpid());
  // Left: a running process's (it may be saving now), names of another form, another file's.
  const std::vector<std::string> stay = {"map.bin.tmp-" + alive + "-77", "map.bin.tmp-" + ended,
                                         "map.bin.tmp-x-1", "other.bin.tmp-" + ended + "-0"};
  std::vector<std::string> names = {"map.bin.tmp-" + ended + "-0",
                                    "map.bin.prev.tmp-" + ended + "-3"};
  names.insert(names.end(), stay.begin(), stay.end());
  for (const std::string& name : names) std::ofstream(dir / name) << "partial";
  SaveKeyFrameMap((dir / "map.bin").string(), test::SampleMapFile(2, 1, false));
  std::vector<std::string> now;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    now.push_back(entry.path().filename().string());
  }
  std::vector<std::string> expected = stay;
  expected.push_back("map.bin");
  std::sort(now.begin(), now.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(now, expected);
}

}  // namespace
}  // namespace dslam

// Replays the fuzzer's seed corpus and every input it crashed on
// (fuzz/regressions/) through the same pipeline as the libFuzzer target, so
// that a fixed crash stays fixed without clang in CI.

#include "fuzz/fuzz_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

std::vector<std::filesystem::path> files_in(const std::string& folder)
{
  std::vector<std::filesystem::path> files;
  for(const auto& entry : std::filesystem::directory_iterator(folder))
    if(entry.is_regular_file() && entry.path().filename() != "README.md")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Ends the process, naming the input, when one replay runs past a limit:
// a hang found by the fuzzer fails the suite instead of blocking it. The
// limit is generous (the slowest input takes about a second under the
// sanitizers); DISK_SEGMENTATION_REPLAY_TIME_LIMIT overrides it in seconds.
class Hang_watchdog
{
public:
  explicit Hang_watchdog(const std::string& input)
    : thread_([this, input] {
        std::unique_lock<std::mutex> lock(mutex_);
        if(!finished_changed_.wait_for(lock, limit(), [this] { return finished_; }))
        {
          std::fprintf(stderr, "replay of '%s' still runs after %lld s: a hang\n", input.c_str(),
                       static_cast<long long>(limit().count()));
          std::abort();
        }
      })
  {}
  ~Hang_watchdog()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      finished_ = true;
    }
    finished_changed_.notify_all();
    thread_.join();
  }

private:
  static std::chrono::seconds limit()
  {
    const char* text = std::getenv("DISK_SEGMENTATION_REPLAY_TIME_LIMIT");
    const long long seconds = text != nullptr ? std::atoll(text) : 0;
    return std::chrono::seconds(seconds > 0 ? seconds : 300);
  }

  std::mutex mutex_;
  std::condition_variable finished_changed_;
  bool finished_ = false;
  std::thread thread_;
};

fuzz_pipeline::Outcome replay(const std::filesystem::path& file,
                              fuzz_pipeline::Soup_options options = fuzz_pipeline::Soup_options::FROM_HASH)
{
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Hang_watchdog watchdog(file.string());
  return fuzz_pipeline::run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), options);
}

} // namespace

TEST(FuzzCorpus, SeedInputsGiveAtlasesOrClearRejections)
{
  std::map<std::string, fuzz_pipeline::Outcome> outcome;
  for(const auto& file : files_in(DISK_SEGMENTATION_FUZZ_DIR "/corpus"))
  {
    SCOPED_TRACE(file.string());
    outcome[file.filename().string()] = replay(file);
  }
  ASSERT_GE(outcome.size(), 10u);
  // Valid triangle meshes in each format must give an atlas, whatever
  // parameters their bytes select; a NaN coordinate never can.
  for(const char* valid : { "tetrahedron.off", "tetrahedron.ply", "torus.off", "two_triangles.stl", "degenerate.off" })
    EXPECT_EQ(outcome.at(valid), fuzz_pipeline::Outcome::ATLAS) << valid;
  EXPECT_EQ(outcome.at("nan.off"), fuzz_pipeline::Outcome::REJECTED_FILE);
}

TEST(FuzzCorpus, InputsTheFuzzerCrashedOnNoLongerCrash)
{
  // A crash here aborts the test program (that is the failure); otherwise
  // every file must be either rejected or turned into a valid atlas.
  std::size_t replayed = 0;
  for(const auto& file : files_in(DISK_SEGMENTATION_FUZZ_DIR "/regressions"))
  {
    SCOPED_TRACE(file.string());
    replay(file);
    replay(file, fuzz_pipeline::Soup_options::TRIANGULATE_ONLY);
    ++replayed;
  }
  RecordProperty("replayed", static_cast<int>(replayed));
}

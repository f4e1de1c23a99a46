// Replays the fuzzer's seed corpus and every input it crashed on
// (fuzz/regressions/) through the same pipeline as the libFuzzer target, so
// that a fixed crash stays fixed without clang in CI.

#include "fuzz/fuzz_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
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

fuzz_pipeline::Outcome replay(const std::filesystem::path& file)
{
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fuzz_pipeline::run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
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
    ++replayed;
  }
  RecordProperty("replayed", static_cast<int>(replayed));
}

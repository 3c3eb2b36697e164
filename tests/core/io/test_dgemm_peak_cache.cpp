// The DGEMM peak measured once per machine: a second call finds it in the cache (nothing probed: 0 s), a missing
// folder is made, a corrupt or foreign file is measured around and replaced, and a folder that cannot be written
// costs the cache only, never the measure.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/DgemmPeakCache.h"

namespace test_dgemm_peak_cache {

using namespace rollsim;
namespace fs = std::filesystem;

namespace {
/// A fresh folder under the system's temporary folder, removed at the end of the test.
struct TempDir {
  fs::path path = fs::temp_directory_path() / ("rollsim-peak-cache-" + std::to_string(::getpid()));
  TempDir() { fs::remove_all(path); }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};
}  // namespace

TEST(DgemmPeakCache, MeasuresOnceThenReadsTheCacheInAFolderItMakes) {
  TempDir t;
  const fs::path dir = t.path / "missing" / "rollsim";
  const DgemmPeak first = cached_dgemm_peak(1, 64, dir);
  EXPECT_GT(first.gflops, 0);
  EXPECT_GT(first.seconds, 0);  // probed
  ASSERT_TRUE(fs::exists(dgemm_peak_cache_file(dir)));
  const DgemmPeak again = cached_dgemm_peak(1, 64, dir);
  EXPECT_EQ(again.gflops, first.gflops);
  EXPECT_EQ(again.n, 64);
  EXPECT_EQ(again.seconds, 0.0);                        // nothing probed
  EXPECT_GT(cached_dgemm_peak(1, 32, dir).seconds, 0);  // another key: probed, and kept beside the first
  EXPECT_EQ(cached_dgemm_peak(1, 64, dir).gflops, first.gflops);
}

TEST(DgemmPeakCache, ACorruptCacheIsMeasuredAroundAndReplaced) {
  TempDir t;
  fs::create_directories(t.path);
  for (const std::string bad : {"{\"trunc", "[1, 2]", "{\"x\": {\"gflops\": \"fast\"}}", ""}) {
    std::ofstream(dgemm_peak_cache_file(t.path)) << bad;
    const DgemmPeak p = cached_dgemm_peak(1, 64, t.path);
    EXPECT_GT(p.gflops, 0) << bad;
    EXPECT_GT(p.seconds, 0) << bad;
    std::ifstream in(dgemm_peak_cache_file(t.path));
    EXPECT_TRUE(nlohmann::json::parse(in, nullptr, false).is_object()) << bad;
    EXPECT_EQ(cached_dgemm_peak(1, 64, t.path).seconds, 0.0) << bad;
  }
}

TEST(DgemmPeakCache, AFolderThatCannotBeWrittenStillMeasures) {
  TempDir t;
  fs::create_directories(t.path);
  std::ofstream(t.path / "file") << "x";
  const DgemmPeak p = cached_dgemm_peak(1, 64, t.path / "file" / "rollsim");  // a file where a folder should be
  EXPECT_GT(p.gflops, 0);
  EXPECT_FALSE(fs::exists(t.path / "file" / "rollsim"));
  EXPECT_GT(cached_dgemm_peak(1, 64, "").gflops, 0);  // no cache folder at all
}

}  // namespace test_dgemm_peak_cache

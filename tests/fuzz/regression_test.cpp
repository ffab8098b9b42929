// Every input the fuzz targets have been given to keep, replayed through the same fuzzOne as
// libFuzzer calls: the seed corpus (tests/fuzz/corpus/TARGET) and each finding's reproducer
// (tests/fuzz/regressions/TARGET) must return normally. Reproducers of findings still open
// (tests/fuzz/known/TARGET) are listed as disabled tests, to be run by hand with
// --gtest_also_run_disabled_tests and moved to regressions/ once fixed.
#include "tests/fuzz/fuzz_targets.h"

#include "engine/io/input_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

// Under the asan preset (ASan and UBSan) an undefined-behaviour report fails the replay, as it
// does under libFuzzer; a build without sanitizers never calls this.
extern "C" const char* __ubsan_default_options() { return "halt_on_error=1:print_stacktrace=1"; }

namespace fuzz {
namespace {

const std::filesystem::path kFuzzFolder = std::filesystem::path(WALKRAD_SOURCE) / "tests" / "fuzz";

struct Input {
  const Target* target;
  std::filesystem::path file;
};

// The files of `folder`/TARGET for every target, in name order.
std::vector<Input> inputsIn(const char* folder) {
  std::vector<Input> inputs;
  for (const Target& target : kTargets) {
    const std::filesystem::path dir = kFuzzFolder / folder / target.name;
    if (!std::filesystem::is_directory(dir)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) inputs.push_back({&target, file});
  }
  return inputs;
}

void PrintTo(const Input& in, std::ostream* out) { *out << in.target->name << " " << in.file.filename(); }

std::string testName(const testing::TestParamInfo<Input>& info) {
  std::string name = std::string(info.param.target->name) + "_" + info.param.file.filename().string();
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

class Replay : public testing::TestWithParam<Input> {};

TEST_P(Replay, ReturnsNormally) {
  const std::string bytes = engine::readInputFile(GetParam().file.string());
  GetParam().target->fuzzOne(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

INSTANTIATE_TEST_SUITE_P(Corpus, Replay, testing::ValuesIn(inputsIn("corpus")), testName);
INSTANTIATE_TEST_SUITE_P(Regressions, Replay, testing::ValuesIn(inputsIn("regressions")), testName);
INSTANTIATE_TEST_SUITE_P(DISABLED_Known, Replay, testing::ValuesIn(inputsIn("known")), testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Replay);

TEST(FuzzCorpus, EveryTargetHasSeeds) {
  const std::vector<Input> corpus = inputsIn("corpus");
  for (const Target& target : kTargets) {
    const auto seeds = std::count_if(corpus.begin(), corpus.end(), [&](const Input& in) { return in.target == &target; });
    EXPECT_GT(seeds, 0) << target.name;
  }
}

}  // namespace
}  // namespace fuzz

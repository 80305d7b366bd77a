// Seeds of the randomised GoogleTests (issue 20): every random stream starts from a fixed default
// written in its test, so the default suite is deterministic. The seed in use is printed once per
// test and stream; RPU_TEST_SEED=<k> adds k to every default, reseeding the whole suite at once
// (a failure prints the seeds that reproduce it).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string>
#include <utility>

namespace rpu::test {

inline std::uint64_t seed(std::uint64_t fixed) {
  static const std::uint64_t offset = [] {
    const char* s = std::getenv("RPU_TEST_SEED");
    return s ? std::strtoull(s, nullptr, 0) : 0;
  }();
  const std::uint64_t value = fixed + offset;
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "";
  static std::mutex mutex;
  static std::set<std::pair<std::string, std::uint64_t>> printed;
  const std::lock_guard<std::mutex> lock(mutex);
  if (printed.emplace(test, fixed).second)
    std::printf("[ seed     ] %s: %llu (default %llu + RPU_TEST_SEED %llu)\n", test.c_str(),
                static_cast<unsigned long long>(value), static_cast<unsigned long long>(fixed),
                static_cast<unsigned long long>(offset));
  return value;
}

}  // namespace rpu::test

// Test runner for the property tests: fixes RapidCheck's seed (and a moderate case count)
// unless RC_PARAMS is already set, so that every run, including the sanitizer build, checks
// the same cases. Override with e.g. RC_PARAMS="seed=42 max_success=1000".
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  // RapidCheck reads RC_PARAMS once, on the first property, i.e. after this point.
  setenv("RC_PARAMS", "seed=20240611 max_success=100", /*overwrite=*/0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

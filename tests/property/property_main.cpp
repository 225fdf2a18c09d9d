// main() of the property tests: a fixed RapidCheck seed and case count, so that ctest is
// deterministic, unless RC_PARAMS is set (RC_PARAMS="seed=N max_success=M" explores others; a
// failure prints the `reproduce` string that replays it).
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  setenv("RC_PARAMS", "seed=20261121 max_success=1000 verbose_progress=0", 0);  // 0: keep a given one
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

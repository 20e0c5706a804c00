// Compiled, not run, by the tests result_*_is_nodiscard (tests/CMakeLists.txt): with IGNORE_VOID
// or IGNORE_VALUE defined a call's Result is dropped, which -Werror must refuse; with neither the
// same calls are used, which must compile, so a failure above is the attribute's and nothing else.
#include "common/result.hpp"

namespace {

tumble::Result<void> remove_nothing(bool fail) {
  if (fail) return tumble::Error{"could not"};
  return tumble::Result<void>::success();
}

tumble::Result<int> count_nothing(bool fail) {
  if (fail) return tumble::Error{"could not"};
  return 0;
}

}  // namespace

int main(int argc, char**) {
#if defined(IGNORE_VOID)
  remove_nothing(argc > 1);
#elif defined(IGNORE_VALUE)
  count_nothing(argc > 1);
#else
  if (!remove_nothing(argc > 1)) return 1;
  if (const tumble::Result<int> counted = count_nothing(argc > 1); !counted) return 1;
#endif
  return 0;
}

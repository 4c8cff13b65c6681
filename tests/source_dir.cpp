#include "source_dir.hpp"

namespace dynpos_test_support {

const char* source_dir() noexcept { return DYNPOS_TEST_SOURCE_DIR_PATH; }

}  // namespace dynpos_test_support

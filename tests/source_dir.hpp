#pragma once
// The source tree, for the tests' data files. The path is compiled into one object of its own
// (source_dir.cpp), not into every test's flags: a flag holding the clone's path would make
// each test a compiler-cache miss in every new clone.

namespace dynpos_test_support {

/// The absolute path of the source tree the tests were built from.
const char* source_dir() noexcept;

}  // namespace dynpos_test_support

#define DYNPOS_SOURCE_DIR (::dynpos_test_support::source_dir())

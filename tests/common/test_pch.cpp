// The translation unit that builds the test suites' shared precompiled header
// (lfd_test_pch, tests/CMakeLists.txt); it has no code of its own.

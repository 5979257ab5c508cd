// Compiled only to build the precompiled header that every room's test executable reuses
// (tests/CMakeLists.txt: mb_test_pch).

// The source of the test_headers target, whose only product is the
// precompiled tests.h that every test program reuses (tests/CMakeLists.txt).

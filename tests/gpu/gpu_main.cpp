#include "tests/gpu/gl_test_context.hpp"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new ocean_test::GlEnvironment);  // gtest owns it
    return RUN_ALL_TESTS();
}

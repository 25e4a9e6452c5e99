// platform/private_network.h in the portable build (macOS): no network namespaces, so no
// private network, and create() says so (the run stops before it starts, never unisolated).
#include <gtest/gtest.h>

#include <string>

#include "platform/private_network.h"

using robottestingframework::platform::PrivateNetwork;

TEST(PrivateNetwork, ThePortableBuildSaysItHasNone) {
    std::string error;
    EXPECT_FALSE(PrivateNetwork::create(error));
    EXPECT_NE(error.find("no network namespaces"), std::string::npos) << error;
}

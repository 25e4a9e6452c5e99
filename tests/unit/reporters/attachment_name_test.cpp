// The name a stored attachment gets: one every report can link and Jenkins' line can hold.
#include <gtest/gtest.h>

#include "core/text_safety.h"

namespace robottestingframework {
namespace {

TEST(AttachmentName, ControlCharactersAndLineBreaksBecomeUnderscores) {
    EXPECT_EQ(reporters::safeFileName("bad\x01\nname.txt"), "bad__name.txt");
    EXPECT_EQ(reporters::safeFileName("tab\there\x7f.log"), "tab_here_.log");
}

TEST(AttachmentName, WhatEndsAJenkinsLineOrAWindowsNameBecomesAnUnderscore) {
    EXPECT_EQ(reporters::safeFileName("a]]b|c[d.png"), "a__b_c_d.png");
    EXPECT_EQ(reporters::safeFileName("x<y>z:\"q\\r?*.txt"), "x_y_z__q_r__.txt");
}

TEST(AttachmentName, Utf8StaysAndStrayBytesBecomeUnderscores) {
    EXPECT_EQ(reporters::safeFileName("pl\xC3\xB6t.svg"), "pl\xC3\xB6t.svg");
    EXPECT_EQ(reporters::safeFileName("pl\xFFt.svg"), "pl_t.svg");
}

}  // namespace
}  // namespace robottestingframework

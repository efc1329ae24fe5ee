#include <gtest/gtest.h>
#include "core/template_plan.h"
TEST(Placeholder, Compiles) { EXPECT_EQ(tquad::template_name(tquad::TemplateKind::T3), "T3"); }

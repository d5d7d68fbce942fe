// The script executor's dispatch table against the parser's command table: a command that parses
// always has a handler, and no handler waits for a command the parser would refuse.
#include "ScriptRunner.h"
#include "ViewerScript.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ptview {
namespace {

TEST(ScriptRunner, EveryCommandOfTheScriptTableHasAHandler) {
    std::vector<std::string> table = viewerScriptVerbs();
    std::vector<std::string> handled = ScriptRunner::handledVerbs();
    ASSERT_FALSE(table.empty());
    for (const std::string& verb : table)
        EXPECT_EQ(std::count(handled.begin(), handled.end(), verb), 1) << "\"" << verb << "\": handlers for it";
    for (const std::string& verb : handled)
        EXPECT_NE(std::find(table.begin(), table.end(), verb), table.end())
            << "a handler for \"" << verb << "\", which the script table does not have";
}

} // namespace
} // namespace ptview

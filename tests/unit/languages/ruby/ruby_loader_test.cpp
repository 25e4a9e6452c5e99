// The Ruby backend driven directly: loadTest("ruby", ...) and a collector.
#include <gtest/gtest.h>

#include "language_test_helpers.h"

#ifdef RTF_HAVE_RUBY

using namespace rtf_test;
using Kind = robottestingframework::ResultEvent::Kind;

TEST(RubyLoader, PassingTestReportsChecksWithScriptLine) {
    std::string path = writeScript(scriptFolder(), "passing.rb", R"(class TestCase
  def setup(param)
    RobotTestingFramework::setName("ruby passing")
    true
  end

  def run
    RobotTestingFramework::testReport("hello from ruby")
    RobotTestingFramework::testCheck(1 + 1 == 2, "arithmetic works")
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    ASSERT_TRUE(run.loaded) << run.loadError;
    EXPECT_EQ(run.status, TestStatus::Passed);
    EXPECT_EQ(run.name, "ruby passing");
    const ResultEvent* check = run.find(Kind::Check, "arithmetic works");
    ASSERT_NE(check, nullptr);
    EXPECT_EQ(check->message.getSourceLocation(), path + ":9");
}

TEST(RubyLoader, FailedCheckNamesFileAndLine) {
    std::string path = writeScript(scriptFolder(), "check.rb", R"(class TestCase
  def run
    RobotTestingFramework::testCheck(false, "wrong")
    RobotTestingFramework::testReport("still running")
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "wrong");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getSourceLocation(), path + ":3");
    EXPECT_NE(run.find(Kind::Report, "still running"), nullptr);
}

TEST(RubyLoader, AssertFailStopsTheScriptPastBareRescue) {
    std::string path = writeScript(scriptFolder(), "fail.rb", R"(class TestCase
  def run
    begin
      RobotTestingFramework::assertFail("stop here")
    rescue => e
      RobotTestingFramework::testReport("swallowed")
    end
    RobotTestingFramework::testReport("not reached")
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "stop here");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getSourceLineNumber(), 4u);
    EXPECT_EQ(run.find(Kind::Report, "swallowed"), nullptr);
    EXPECT_EQ(run.find(Kind::Report, "not reached"), nullptr);
}

TEST(RubyLoader, AssertFailRescuedByTheScriptStillFails) {
    std::string path = writeScript(scriptFolder(), "rescued.rb", R"(class TestCase
  def run
    begin
      RobotTestingFramework::assertFail("rescued")
    rescue Exception
    end
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_NE(run.find(Kind::Failure, "rescued"), nullptr);
}

TEST(RubyLoader, AssertErrorIsAnError) {
    std::string path = writeScript(scriptFolder(), "error.rb", R"(class TestCase
  def run
    RobotTestingFramework::assertError("no robot")
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_NE(run.find(Kind::Error, "no robot"), nullptr);
}

TEST(RubyLoader, ExceptionGivesClassMessageAndBacktrace) {
    std::string path = writeScript(scriptFolder(), "raises.rb", R"(def helper
  raise ArgumentError, "bad joint"
end

class TestCase
  def run
    helper
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    const ResultEvent* error = run.find(Kind::Error, "bad joint");
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->message.getMessage(), "bad joint (ArgumentError)");
    EXPECT_EQ(error->message.getSourceLocation(), path + ":2");
    EXPECT_NE(error->message.getDetail().find(path + ":7:in `run'"), std::string::npos)
        << error->message.getDetail();
}

TEST(RubyLoader, SyntaxErrorNamesFileAndLine) {
    std::string path =
        writeScript(scriptFolder(), "syntax.rb", "class TestCase\n  def run(\nend\n");
    ScriptRun run = runScript("ruby", path);
    ASSERT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find("SyntaxError"), std::string::npos) << run.loadError;
    EXPECT_NE(run.loadError.find(path + ":"), std::string::npos) << run.loadError;
}

TEST(RubyLoader, SetupReturningFalseIsAnError) {
    std::string path = writeScript(scriptFolder(), "setup.rb", R"(class TestCase
  def setup(param)
    false
  end
  def run
    RobotTestingFramework::testReport("ran")
  end
end
)");
    ScriptRun run = runScript("ruby", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_EQ(run.find(Kind::Report, "ran"), nullptr);
}

TEST(RubyLoader, ParamEnvironmentAndRepetition) {
    std::string path = writeScript(scriptFolder(), "param.rb", R"(class TestCase
  def setup(param)
    @count = 0
    RobotTestingFramework::testReport("setup got #{param}")
    true
  end
  def run
    @count += 1
    RobotTestingFramework::testReport("run #{@count} #{RobotTestingFramework::getParam} / #{RobotTestingFramework::getEnvironment}")
  end
end
)");
    ScriptRun run = runScript("ruby", path, "--speed 3", "--robot sim", 2);
    EXPECT_NE(run.find(Kind::Report, "setup got --speed 3"), nullptr);
    EXPECT_NE(run.find(Kind::Report, "run 2 --speed 3 / --robot sim"), nullptr);
}

TEST(RubyLoader, TwoScriptsDoNotShareClassesOrMethods) {
    auto folder = scriptFolder();
    std::string first = writeScript(folder, "a.rb", R"(def only_in_a
  1
end
class TestCase
  def run
    RobotTestingFramework::testCheck(!defined?(@@seen), "fresh class")
    @@seen = true
  end
end
)");
    std::string second = writeScript(folder, "b.rb", R"(class TestCase
  def run
    RobotTestingFramework::testCheck(!defined?(@@seen), "fresh class")
    RobotTestingFramework::testCheck(!respond_to?(:only_in_a, true), "no foreign method")
  end
end
)");
    EXPECT_EQ(runScript("ruby", first).status, TestStatus::Passed);
    ScriptRun run = runScript("ruby", second);
    EXPECT_EQ(run.status, TestStatus::Passed);
}

#endif  // RTF_HAVE_RUBY

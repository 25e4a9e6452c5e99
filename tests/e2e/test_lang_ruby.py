"""Ruby test cases through the real runner (SPEC 2 "Script test cases", 3.2)."""
from lang_cases import ScriptLanguageCases, run_isolated

SCRIPTS = {
    "passing": """class TestCase
  def run
    RobotTestingFramework::testReport("alive")
    RobotTestingFramework::testCheck(true, "holds")
  end
end
""",
    "failing_check": """class TestCase
  def run
    RobotTestingFramework::testCheck(1 == 2, "deliberate failure") # MARK
    RobotTestingFramework::testReport("after the check")
  end
end
""",
    "assert_error": """class TestCase
  def run
    RobotTestingFramework::assertError("no robot")
    RobotTestingFramework::testReport("not reached")
  end
end
""",
    "assert_fail": """class TestCase
  def run
    begin
      RobotTestingFramework::assertFail("gave up") # MARK
    rescue StandardError
    end
    RobotTestingFramework::testReport("not reached")
  end
end
""",
    "exception": """def helper
  1 / 0 # MARK
end

class TestCase
  def run
    helper
  end
end
""",
    "syntax_error": """class TestCase
  def run(
end
""",
    "setup_false": """class TestCase
  def setup(param)
    false
  end
  def run
    RobotTestingFramework::testReport("run was called")
  end
end
""",
    "param_env": """class TestCase
  def setup(param)
    RobotTestingFramework::testReport("setup param=" + param)
    true
  end
  def run
    RobotTestingFramework::testReport("param=" + RobotTestingFramework::getParam)
    RobotTestingFramework::testReport("env=" + RobotTestingFramework::getEnvironment)
  end
end
""",
    "repeat": """class TestCase
  def initialize
    @count = 0
  end
  def run
    @count += 1
    RobotTestingFramework::testReport("run #{@count}")
  end
end
""",
    "globals": """$seen_by = [] unless defined?(SEEN)
SEEN = true
class TestCase
  def run
    RobotTestingFramework::testCheck(!defined?(@@seen), "fresh class variables")
    @@seen = true
  end
end
""",
}


class TestRuby(ScriptLanguageCases):
    ext = "rb"
    scripts = SCRIPTS
    exception_text = "divided by 0 (ZeroDivisionError)"

    def syntax_error_location(self, path):
        return f"{path}:3: syntax error"

    def test_exception_shows_the_backtrace(self, tmp_path, isolation):
        path = self.write(tmp_path, "exception")
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert f"{path}:7:in `run'" in r.output, r

    def test_core_methods_written_in_ruby_and_installed_gems_work(self, tmp_path, isolation):
        # ruby_setup() alone leaves out what Ruby defines in Ruby (Kernel#class, Dir.glob,
        # GC.start...); rubygems is not loaded at start but by the first require that needs it.
        path = tmp_path / "core_test.rb"
        path.write_text("""class TestCase
  def run
    RobotTestingFramework::testCheck(!defined?(Gem), "rubygems waits for a require")
    RobotTestingFramework::testCheck(1.class == Integer, "Kernel#class")
    RobotTestingFramework::testCheck([1].tap { |a| a << 2 } == [1, 2], "Kernel#tap")
    RobotTestingFramework::testCheck(Dir.glob(__FILE__) == [__FILE__], "Dir.glob")
    GC.start
    require "json"   # in the standard library
    require "prime"  # a bundled gem: found through rubygems
    RobotTestingFramework::testCheck(Prime.first(3) == [2, 3, 5], "a gem")
    RobotTestingFramework::testReport("core methods and gems: #{JSON.generate([Gem::VERSION.class])}")
  end
end
""")
        for prestart in ("1", "0"):
            r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path,
                             env={"RTF_PRESTART": prestart})
            assert r.returncode == 0, (prestart, r)
            assert 'core methods and gems: ["String"]' in r.output, (prestart, r)

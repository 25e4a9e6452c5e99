"""Lua test cases through the real runner (SPEC 2 "Script test cases", 3.2)."""
import pytest

from lang_cases import ScriptLanguageCases, run_isolated, ISOLATIONS

SCRIPTS = {
    "passing": """TestCase = {}
function TestCase.run()
    robottestingframework.testReport("alive")
    robottestingframework.testCheck(true, "holds")
end
""",
    "failing_check": """TestCase = {}
function TestCase.run()
    robottestingframework.testCheck(1 == 2, "deliberate failure") -- MARK
    robottestingframework.testReport("after the check")
end
""",
    "assert_error": """TestCase = {}
function TestCase.run()
    robottestingframework.assertError("no robot")
    robottestingframework.testReport("not reached")
end
""",
    "assert_fail": """TestCase = {}
function TestCase.run()
    robottestingframework.assertFail("gave up") -- MARK
    robottestingframework.testReport("not reached")
end
""",
    "exception": """local function helper()
    return nil .. "text" -- MARK
end
TestCase = {}
function TestCase.run()
    helper()
end
""",
    "syntax_error": """TestCase = {}
function TestCase.run(
end
""",
    "setup_false": """TestCase = {}
function TestCase.setup(param)
    return false
end
function TestCase.run()
    robottestingframework.testReport("run was called")
end
""",
    "param_env": """TestCase = {}
function TestCase.setup(param)
    robottestingframework.testReport("setup param=" .. param)
    return true
end
function TestCase.run()
    robottestingframework.testReport("param=" .. robottestingframework.getParam())
    robottestingframework.testReport("env=" .. robottestingframework.getEnvironment())
end
""",
    "repeat": """TestCase = {}
local count = 0
function TestCase.run()
    count = count + 1
    robottestingframework.testReport("run " .. count)
end
""",
    "globals": """TestCase = {}
function TestCase.run()
    robottestingframework.testCheck(seen == nil, "fresh globals")
    seen = true
end
""",
}


class TestLua(ScriptLanguageCases):
    ext = "lua"
    scripts = SCRIPTS
    exception_text = "attempt to concatenate a nil value"

    def syntax_error_location(self, path):
        return "syntax_error.lua:3:"

    def test_runtime_error_shows_the_traceback(self, tmp_path, isolation):
        path = self.write(tmp_path, "exception")
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert "stack traceback:" in r.output, r
        assert "exception.lua:6: in " in r.output, r


@pytest.fixture(params=ISOLATIONS)
def isolation(request):
    return request.param


def test_requires_a_neighbour_module(tmp_path, isolation):
    (tmp_path / "robotutil.lua").write_text("return { gain = 7 }\n")
    (tmp_path / "uses.lua").write_text("""local robotutil = require("robotutil")
TestCase = {}
function TestCase.run()
    robottestingframework.testCheck(robotutil.gain == 7, "neighbour required")
end
""")
    r = run_isolated(isolation, "--test", "uses.lua", cwd=tmp_path)
    assert r.returncode == 0, r

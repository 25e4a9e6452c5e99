"""Ctrl-C on Windows, in the runner's own process (--isolation none): a console Ctrl-C
(console_ctrl_c.exe, as a user's key press reaches a console program) stops the running test,
the fixture is torn down, every report is written naming the interrupted test and what was not
run, and the exit status is 130, as on Linux."""
import xml.etree.ElementTree as ET

from conftest import copy_plugins, run_with_ctrl_c, validate_ctrf, validate_junit

# Says it is running (the file `started`), then runs until interrupted (at most 60 s).
HUNG = """TestCase.run = function()
    local started = io.open("started", "w")
    started:write("running")
    started:close()
    local deadline = os.clock() + 60
    while os.clock() < deadline do end
    robottestingframework.testReport("never interrupted")
end
"""
DONE = """TestCase.run = function()
    robottestingframework.testCheck(true, "done")
end
"""
SUITE = """<suite name="interrupted">
    <fixture param="--log fixture.log --name world">../plugins/order_fixture.dll</fixture>
    <test name="done">../tests/done.lua</test>
    <test name="hung">../tests/hung.lua</test>
    <test name="after">../tests/done.lua</test>
</suite>
"""
LATER = """<suite name="later"><test name="never">../tests/done.lua</test></suite>
"""


def junit_states(path):
    states = {}
    for case in ET.parse(path).getroot().iter("testcase"):
        error = case.find("error")
        states[case.get("name")] = (error.get("type") if error is not None else
                                    "failed" if case.find("failure") is not None else "passed")
    return states


def test_ctrl_c_stops_the_run_writes_the_reports_and_exits_130(tmp_path):
    copy_plugins(tmp_path / "plugins", "order_fixture.dll")
    tests = tmp_path / "tests"
    tests.mkdir()
    (tests / "hung.lua").write_text(HUNG)
    (tests / "done.lua").write_text(DONE)
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "suite.xml").write_text(SUITE)
    (suites / "later.xml").write_text(LATER)
    (suites / "out").mkdir()

    run = run_with_ctrl_c("started", "-s", "suite.xml", "-s", "later.xml", "--isolation", "none",
                          "-o", "junit:out/r.xml", "-o", "text:out/r.txt",
                          "-o", "json:out/r.json", cwd=suites)
    assert run.returncode == 130, run
    assert (suites / "started").exists(), run
    assert "interrupted; stopping the running test" in run.output, run
    # Torn down after the interrupted test; "after" was never checked for.
    assert (suites / "fixture.log").read_text().splitlines() == [
        "setup world", "check world", "check world", "teardown world"], run

    validate_junit(suites / "out" / "r.xml")
    assert junit_states(suites / "out" / "r.xml") == {
        "done": "passed", "hung": "interrupted", "after": "interrupted",
        "never": "interrupted"}, (suites / "out" / "r.xml").read_text()
    ctrf = validate_ctrf(suites / "out" / "r.json")
    states = {test["name"]: test["extra"]["robotology.rtf"]["state"]
              for test in ctrf["results"]["tests"]}
    assert states["done"] == "passed" and states["hung"] == "interrupted", states
    text = (suites / "out" / "r.txt").read_text()
    assert "INTERRUPTED" in text and "hung" in text, text

"""Crash context (issue 22, item 7): a Python test that crashes natively has its Python stack
in the report (faulthandler writes it into the worker's output), and a Lua error's message
is said once, not again at the top of its traceback."""
import json

import pytest

from conftest import run_runner


def test_a_python_test_that_segfaults_has_its_python_stack_in_the_report(tmp_path):
    (tmp_path / "native_crash.py").write_text("""import ctypes


def read_the_sensor():
    return ctypes.string_at(0)


class TestCase:
    def run(self):
        read_the_sensor()
""")
    run = run_runner("-t", "native_crash.py", "-o", "json:r.json", "-o", "text:r.txt",
                     cwd=tmp_path, timeout=60)
    assert run.returncode == 1, run
    (test,) = json.loads((tmp_path / "r.json").read_text())["results"]["tests"]
    assert test["extra"]["robotology.rtf"]["state"] == "crashed", test
    output = "\n".join(test["stdout"])
    assert "Segmentation fault" in output, output
    # The frames, innermost first: where it crashed and who called it.
    assert 'native_crash.py", line 5 in read_the_sensor' in output, output
    assert 'native_crash.py", line 10 in run' in output, output
    assert 'native_crash.py", line 5 in read_the_sensor' in (tmp_path / "r.txt").read_text()


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_a_lua_error_says_its_message_once(tmp_path, isolation):
    (tmp_path / "arm.lua").write_text("""TestCase = {}
function TestCase.run()
    local joint = nil
    error("joint 3 is not calibrated")
end
""")
    run = run_runner("-t", "arm.lua", "--isolation", isolation, "-o", "json:r.json",
                     "-o", "text:r.txt", cwd=tmp_path, timeout=60)
    assert run.returncode == 1, run
    (test,) = json.loads((tmp_path / "r.json").read_text())["results"]["tests"]
    assert test["message"].count("joint 3 is not calibrated") == 1, test["message"]
    assert "stack traceback" in test["message"], test["message"]
    assert "arm.lua:4" in test["message"], test["message"]
    text = (tmp_path / "r.txt").read_text()
    assert text.count("joint 3 is not calibrated") == 1, text
    assert run.output.count("joint 3 is not calibrated") == 1, run

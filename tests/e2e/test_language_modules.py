"""Script languages are modules loaded on first use (src/languages/script_module_interface.h): the
runner and its worker do not link any interpreter, the modules are found next to the program or
in $RTF_LANGUAGE_DIR, and a missing module is a clear error, not a crash."""
import subprocess

import pytest

from conftest import BUILD_DIR, RUNNER, run_runner

MODULE_DIR = BUILD_DIR / "lib" / "robottestingframework"
WORKER = BUILD_DIR / "bin" / "robottestingframework-worker"
INTERPRETERS = ("libpython", "libruby", "liblua")

SCRIPTS = {
    "python": ("check.py", """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testReport("module loaded")
"""),
    "lua": ("check.lua", """TestCase = {}
function TestCase.run()
    robottestingframework.testReport("module loaded")
end
"""),
    "ruby": ("check.rb", """class TestCase
  def run
    RobotTestingFramework::testReport("module loaded")
  end
end
"""),
}


def built(language):
    return (MODULE_DIR / f"robottestingframework-{language}.so").is_file()


@pytest.mark.parametrize("program", [RUNNER, str(WORKER)], ids=["runner", "worker"])
def test_programs_do_not_link_interpreters(program):
    ldd = subprocess.run(["ldd", program], capture_output=True, text=True, timeout=30)
    assert ldd.returncode == 0, ldd.stderr
    linked = [line.strip() for line in ldd.stdout.splitlines()
              if any(name in line for name in INTERPRETERS)]
    assert not linked, linked


@pytest.mark.parametrize("language", ["python", "lua", "ruby"])
def test_modules_do_not_carry_their_own_framework(language):
    """A module links the framework's shared library, so the process has one TestCase::current()."""
    if not built(language):
        pytest.skip(f"{language} test cases are not built")
    module = MODULE_DIR / f"robottestingframework-{language}.so"
    ldd = subprocess.run(["ldd", str(module)], capture_output=True, text=True, timeout=30)
    assert "libRobotTestingFramework.so" in ldd.stdout, ldd.stdout
    assert "not found" not in ldd.stdout, ldd.stdout
    symbols = subprocess.run(["nm", "-D", "--defined-only", str(module)], capture_output=True,
                             text=True, timeout=30)
    assert " rtf_language_module" in symbols.stdout
    assert "TestCase7current" not in symbols.stdout, "the module defines the core's symbols"


@pytest.mark.parametrize("isolation", ["none", "process"])
@pytest.mark.parametrize("language", ["python", "lua", "ruby"])
def test_language_dir_override(tmp_path, language, isolation):
    if not built(language):
        pytest.skip(f"{language} test cases are not built")
    name, text = SCRIPTS[language]
    script = tmp_path / name
    script.write_text(text)
    found = run_runner("--isolation", isolation, "--test", script.name, "--no-output", "-v",
                       cwd=tmp_path, env={"RTF_LANGUAGE_DIR": str(MODULE_DIR)}, timeout=60)
    assert found.returncode == 0, found
    assert "module loaded" in found.output, found

    empty = tmp_path / "no-modules"
    empty.mkdir()
    missing = run_runner("--isolation", isolation, "--test", script.name, "--no-output", "-v",
                         cwd=tmp_path, env={"RTF_LANGUAGE_DIR": str(empty)}, timeout=60)
    assert missing.returncode != 0, missing
    title = language.capitalize()
    assert f"{title} test cases are not available: " in missing.output, missing
    assert f"robottestingframework-{language}.so" in missing.output, missing
    assert "module loaded" not in missing.output, missing

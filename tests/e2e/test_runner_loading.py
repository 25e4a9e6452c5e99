"""Plug-ins that cannot be loaded are failed tests named after them, with the loader's reason;
bare names are looked for next to the suite file and on the library path."""
import re
import shutil

from conftest import plugin, run_runner


def test_missing_plugin_is_a_failed_test_with_the_places_searched(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <test>no_such_motor_test</test>
  <test>{plugin("passing_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 1, run
    assert re.search(r"^\s*FAILED\s+(?:.+/)?no_such_motor_test\b", run.stdout, re.M), run
    assert "cannot load no_such_motor_test" in run.stdout, run
    assert "libno_such_motor_test.so" in run.stdout, run   # the spellings tried
    # The suite's folder was searched, and is said as a path, not as "." (the suite was named
    # from its own folder).
    assert f" in the suite's folder {tmp_path.resolve()};" in run.stdout, run
    assert not re.search(r" in \.(, |$)", run.stdout, re.M), run
    assert "1 passed, 1 failed" in run.stdout, run


def test_missing_path_on_the_command_line(tmp_path):
    run = run_runner("-t", "gone/libx.so", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "cannot load" in run.stdout and "no such file" in run.stdout, run


def test_library_without_factory_is_not_a_plugin(tmp_path):
    run = run_runner("-t", plugin("not_a_plugin"), cwd=tmp_path)
    assert run.returncode == 1, run
    assert re.search(r"^\s*FAILED\s+\S*not_a_plugin", run.stdout, re.M), run
    assert "is not a Robot Testing Framework plug-in" in run.stdout, run
    assert "robottestingframework_plugin_abi" in run.stdout, run   # dlerror's words


def test_file_that_is_not_a_library_gives_dlerror(tmp_path):
    fake = tmp_path / "libfake.so"
    fake.write_text("this is not an ELF file\n")
    run = run_runner("-t", fake.name, cwd=tmp_path)
    assert run.returncode == 1, run
    assert str(fake) in run.stdout, run
    assert "invalid ELF header" in run.stdout or "file too short" in run.stdout, run


def test_bare_name_is_found_next_to_the_suite_with_prefix_and_suffix_omitted(tmp_path, suite_file):
    shutil.copy(plugin("passing_test"), tmp_path / "libmotor.so")
    suite = suite_file("<suite name='s'><test>motor</test><test>libmotor</test>"
                       "<test>motor.so</test></suite>")
    other = tmp_path / "elsewhere"
    other.mkdir()
    run = run_runner("-s", suite, cwd=other)
    assert run.returncode == 0, run
    assert "3 passed, 0 failed" in run.stdout, run


def test_relative_path_is_taken_from_the_suite_folder(tmp_path, suite_file):
    (tmp_path / "checks").mkdir()
    shutil.copy(plugin("passing_test"), tmp_path / "checks" / "enc.so")
    suite = suite_file("<suite name='s'><test>checks/enc.so</test></suite>")
    other = tmp_path / "elsewhere"
    other.mkdir()
    run = run_runner("-s", suite, cwd=other)
    assert run.returncode == 0, run


def test_bare_name_is_found_on_ld_library_path(tmp_path, suite_file):
    libs = tmp_path / "libs"
    libs.mkdir()
    shutil.copy(plugin("passing_test"), libs / "libonpath.so")
    suite = suite_file("<suite name='s'><test>onpath</test></suite>")
    run = run_runner("-s", suite.name, cwd=tmp_path, env={"LD_LIBRARY_PATH": str(libs)})
    assert run.returncode == 0, run


def test_test_given_a_fixture_plugin_says_so(tmp_path):
    run = run_runner("-t", plugin("order_fixture"), cwd=tmp_path)
    assert run.returncode == 1, run
    assert "it is a fixture plug-in" in run.stdout, run
